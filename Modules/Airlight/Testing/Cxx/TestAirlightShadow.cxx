// Numeric test (no baseline) of vtkPlumeAirlightPass's shadowed path (spot
// lights with a shadow map and the jittered march) against the independent
// vtkPlumeAirlightReference with exact ray-cast shadows (its own triangle hierarchy):
// 1. a spot light above a plate over the floor of an asymmetric room: a
//    shadow shaft below the plate. Goal: RMS <= 0.5 % and max <= 2 % of the
//    airlight range away from shadow-edge pixels (edge pixels: where the
//    reference's shadow, unshadowed minus shadowed, changes by more than 2 %
//    of the range to a neighbour); the edge error is printed separately and
//    bounded loosely. The shadow darkens the airlight (a shaft).
// 2. the shadow map is rebuilt only when the light or the geometry changes.
// 3. a fully lit scene (nothing between the spot and the floor, exponent 0):
//    shadows on equal shadows off (the march telescopes to the closed form).
// 4. stress: camera inside the shadow shaft with the occluder out of view,
//    occluder touching the light (both vs the reference).
#include "plumeAirlightTestUtil.h"

#include "vtkTransform.h"

int TestAirlightShadow(int, char*[])
{
  int failures = 0;
  const int W = 96, H = 72, stride = 2;

  // 1. A spot light above a plate: a shaft of shadow under it.
  {
    airtest::Scene s(W, H);
    s.AddRoom();
    vtkActor* plate = s.AddBox(-0.6, 0.3, 2.2, 2.3, -1.9, -1.1, 0.9, 0.9, 0.8);
    const double sp[3] = { -0.3, 3.6, -1.2 }, sf[3] = { 0.2, 0.0, -1.8 };
    s.AddSpotLight(sp, sf, 40.0, 1.0, 1.0, 0.9, 0.75, 1.0);
    // (Point lights are shadowed too: TestAirlightPointShadow. One light here
    // keeps the reference's ray casts affordable.)
    s.Pass->SetScattering(0.22, 0.2, 0.18);
    s.Pass->SetAbsorption(0.02, 0.03, 0.05);
    s.Pass->SetIntensityScale(30.0);
    s.Camera(2.5, 1.4, 5.5, -0.3, 1.4, -1.5);

    const airtest::ShadowComparison r = airtest::CompareShadowed(s, stride, "shadowed spot");
    failures += airtest::CheckShadowGoal(r);
    PLUME_CHECK(r.ShadowedLightsOn == 1);
    // The shaft: the reference and the pass are darker behind the plate.
    PLUME_CHECK(r.MaxRefDark > 0.02 * r.All.Range);
    PLUME_CHECK(r.MaxDark > 0.02 * r.All.Range);
    PLUME_CHECK(r.RefDarker >= 8);
    PLUME_CHECK(r.Darker + 3 >= r.RefDarker && r.Darker <= r.RefDarker + 3);
    PLUME_CHECK(r.Brighter == 0);
    failures += airtest::CheckMinMax(s, r, 0.4);

    // Error against the march steps (published in Documentation/Airlight.md).
    for (int k : { 16, 256 })
    {
      s.Pass->SetShadowSteps(k);
      const airtest::EdgeSplit e =
        airtest::CompareAwayFromEdges(s.RenderFloat(s.Pass), r.Ref, r.RefLit, r.Air, stride);
      std::cout << "shadow steps " << k << ": ";
      airtest::Print("away from edges", e.Inner);
      std::cout << "  ";
      airtest::Print("edges", e.Edge);
    }
    s.Pass->SetShadowSteps(64);

    // 2. Rebuilt only on change: not for a new frame or a new medium; for a moved occluder.
    // (In the window: RenderFloat's framebuffer pass releases its delegate's resources.)
    s.RenderAirlight();
    const int bakes = s.Pass->GetNumberOfShadowMapBakes();
    s.RenderAirlight();
    s.Pass->SetScattering(0.3, 0.3, 0.3);
    s.RenderAirlight();
    std::cout << "bakes: " << bakes << " then " << s.Pass->GetNumberOfShadowMapBakes() << "\n";
    PLUME_CHECK(s.Pass->GetNumberOfShadowMapBakes() == bakes);
    plate->SetPosition(0.1, 0, 0);
    s.RenderAirlight();
    PLUME_CHECK(s.Pass->GetNumberOfShadowMapBakes() == bakes + 1);
    s.Pass->SetShadowMapSize(512);
    s.RenderAirlight();
    PLUME_CHECK(s.Pass->GetNumberOfShadowMapBakes() == bakes + 2);
  }

  // 3. Fully lit: a floor and a wall only, the spot (exponent 0) on the floor.
  {
    airtest::Scene s(W, H);
    s.AddBox(-5, 5, -0.1, 0, -4, 4, 0.6, 0.6, 0.55);
    s.AddBox(-5, 5, 0, 5, -4.1, -4, 0.5, 0.55, 0.6);
    const double sp[3] = { 0.5, 3.5, -1.0 }, sf[3] = { 0.0, 0.0, -1.5 };
    s.AddSpotLight(sp, sf, 30.0, 0.0, 1.0, 0.9, 0.8, 1.0);
    s.Pass->SetScattering(0.2, 0.2, 0.2);
    s.Pass->SetIntensityScale(20.0);
    s.Camera(1.5, 1.5, 5.0, 0.0, 1.2, -2.0);
    int shadowed = 0;
    const airtest::Error e = airtest::ShadowsOnVersusOff(s, shadowed);
    PLUME_CHECK(shadowed == 1); // the floor is in the cone
    airtest::Print("fully lit, shadows on vs off", e);
    PLUME_CHECK(e.Range > 0.3);
    PLUME_CHECK(e.Max <= 1e-4);
  }

  // 4. Stress: the camera inside the shadow shaft; an occluder touching the light.
  {
    airtest::Scene s(96, 72);
    s.AddRoom();
    s.AddBox(-0.6, 0.3, 2.2, 2.3, -1.9, -1.1, 0.9, 0.9, 0.8);
    const double sp[3] = { -0.15, 3.6, -1.5 }, sf[3] = { -0.15, 0.0, -1.5 };
    s.AddSpotLight(sp, sf, 40.0, 1.0, 1.0, 0.9, 0.75, 1.0);
    s.Pass->ShadowsOn();
    s.Pass->SetScattering(0.2, 0.2, 0.2);
    s.Pass->SetIntensityScale(30.0);
    s.Camera(-0.15, 1.2, -1.5, 3.0, 1.0, -1.5, 70); // under the plate, looking out of the shaft
    const airtest::FloatImage plain = s.RenderFloat(nullptr);
    airtest::FloatImage air;
    const airtest::FloatImage ref = s.Reference(plain, 3, &air, false);
    const airtest::FloatImage image = s.RenderFloat(s.Pass);
    PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
    PLUME_CHECK(!plume::test::HasNonFinite(image));
    const airtest::Error e = airtest::Compare(image, ref, air);
    airtest::Print("camera inside the shadow", e);
    // The plate is outside the view: its shadow must still be cast (before the
    // fix, props culled to the eye were missing from the map: 100 % RMS).
    // All pixels, shadow edges included, of a small airlight range (0.037).
    PLUME_CHECK(e.RMS <= 0.02);
    PLUME_CHECK(e.Max <= 0.05);

    // The light on the top face of a box right under it: everything below is shadowed.
    airtest::Scene t(96, 72);
    t.AddRoom();
    t.AddBox(-0.5, 0.5, 3.0, 3.6, -2.0, -1.0, 0.9, 0.9, 0.8);
    const double tp[3] = { 0.0, 3.6, -1.5 }, tf[3] = { 0.0, 0.0, -1.5 };
    t.AddSpotLight(tp, tf, 30.0, 0.0, 1.0, 1.0, 1.0, 1.0);
    t.Pass->ShadowsOn();
    t.Pass->SetScattering(0.2, 0.2, 0.2);
    t.Pass->SetIntensityScale(30.0);
    t.Camera(1.5, 1.5, 5.0, 0.0, 1.2, -2.0);
    const airtest::FloatImage plainT = t.RenderFloat(nullptr);
    airtest::FloatImage airT;
    const airtest::FloatImage refT = t.Reference(plainT, 3, &airT, false);
    const airtest::FloatImage imageT = t.RenderFloat(t.Pass);
    PLUME_CHECK(plume::test::GLErrors(t.Window).empty());
    PLUME_CHECK(!plume::test::HasNonFinite(imageT));
    const airtest::Error eT = airtest::Compare(imageT, refT, refT);
    airtest::Print("occluder touching the light (vs reference, range of the total)", eT);
    PLUME_CHECK(eT.Max <= 0.02);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
