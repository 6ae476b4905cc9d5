// Numeric test (no baseline) of vtkPlumeAirlightPass's shadows for point
// lights (a cube shadow map: six world-axis faces in a 3 x 2 atlas) against
// the independent vtkPlumeAirlightReference with exact ray-cast shadows:
// 1. a point light under the ceiling above a plate, in a room with a box and
//    a sphere: shadows on all sides of the light (several cube faces seen).
//    Goal: RMS <= 0.5 % and max <= 2 % of the airlight range away from
//    shadow-edge pixels; edge pixels reported separately, bounded loosely;
//    the shaft under the plate darkens the same pixels as in the reference.
// 2. the cube map is rebuilt only when the light or the geometry changes.
// 3. lit rays: a point light over a bare floor, shadows on equal shadows off.
// 4. six point lights needing shadows (more than the former limit of 4): all
//    are shadowed, none counted as unshadowed, no GL error.
#include "plumeAirlightTestUtil.h"

int TestAirlightPointShadow(int, char*[])
{
  int failures = 0;
  const int W = 80, H = 60, stride = 3;

  // 1. A point light above a plate: shafts of shadow under the plate, the box and the sphere.
  {
    airtest::Scene s(W, H);
    vtkActor* plate = airtest::PlateRoom(s);
    vtkLight* light = s.AddPointLight(-0.1, 3.4, -1.5, 1.0, 0.9, 0.75, 1.0);

    const airtest::ShadowComparison r = airtest::CompareShadowed(s, stride, "shadowed point light");
    failures += airtest::CheckShadowGoal(r);
    PLUME_CHECK(r.ShadowedLightsOn == 1);
    // The shafts: darker in the pass where the reference is darker.
    PLUME_CHECK(r.RefDarker >= 20);
    PLUME_CHECK(r.Darker + 4 >= r.RefDarker && r.Darker <= r.RefDarker + 4);
    PLUME_CHECK(std::fabs(r.MaxDark - r.MaxRefDark) <= 0.05 * r.MaxRefDark);
    PLUME_CHECK(r.Brighter == 0);
    failures += airtest::CheckMinMax(s, r, 0.4);

    // 2. Rebuilt only on change: not for a new frame, medium or eye; for a moved occluder or light.
    s.RenderAirlight();
    const int bakes = s.Pass->GetNumberOfShadowMapBakes();
    s.RenderAirlight();
    s.Pass->SetScattering(0.3, 0.3, 0.3);
    s.Camera(2.0, 1.5, 5.0, -0.3, 1.4, -1.5);
    s.RenderAirlight();
    std::cout << "bakes: " << bakes << " then " << s.Pass->GetNumberOfShadowMapBakes() << "\n";
    PLUME_CHECK(s.Pass->GetNumberOfShadowMapBakes() == bakes);
    plate->SetPosition(0.1, 0, 0);
    s.RenderAirlight();
    PLUME_CHECK(s.Pass->GetNumberOfShadowMapBakes() == bakes + 1);
    light->SetPosition(0.0, 3.3, -1.5);
    s.RenderAirlight();
    PLUME_CHECK(s.Pass->GetNumberOfShadowMapBakes() == bakes + 2);
    PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
  }

  // 3. Lit rays: a bare floor under a point light; every point above it is lit.
  {
    airtest::Scene s(W, H);
    s.AddBox(-5, 5, -0.1, 0, -4, 4, 0.6, 0.6, 0.55);
    s.AddPointLight(0.5, 2.5, -1.0, 1.0, 0.9, 0.8, 1.0);
    s.Pass->SetScattering(0.2, 0.2, 0.2);
    s.Pass->SetIntensityScale(20.0);
    // every pixel in both frames: without shadows the light would be on the
    // airlight lattice (TestAirlightLattice), with them at every pixel
    s.Pass->SetDownsampling(1);
    s.Camera(1.5, 1.5, 5.0, 0.0, 1.2, -2.0);
    int shadowed = 0;
    const airtest::Error e = airtest::ShadowsOnVersusOff(s, shadowed);
    PLUME_CHECK(shadowed == 1);
    airtest::Print("point light, fully lit, shadows on vs off", e);
    PLUME_CHECK(e.Range > 0.3);
    PLUME_CHECK(e.Max <= 1e-4);
  }

  // 4. Six lights needing shadows: all six are shadowed.
  {
    airtest::Scene s(48, 36);
    s.AddRoom();
    for (int k = 0; k < 6; ++k)
    {
      s.AddPointLight(-2.5 + k, 3.0, -1.0, 0.3, 0.3, 0.3, 1.0);
    }
    s.Pass->ShadowsOn();
    // cube maps of 256 texels per side (default 1024; part 1 checks that
    // size): the count of shadowed lights does not depend on it, and six
    // 3072 x 2048 bakes were a large share of this test's CPU
    s.Pass->SetShadowMapSize(256);
    s.Pass->SetScattering(0.2, 0.2, 0.2);
    s.Pass->SetIntensityScale(10.0);
    s.Camera(1.5, 1.5, 5.0, 0.0, 1.2, -2.0);
    const airtest::FloatImage image = s.RenderFloat(s.Pass);
    std::cout << "6 lights: " << s.Pass->GetNumberOfShadowedLights() << " shadowed, "
              << s.Pass->GetNumberOfUnshadowedLights() << " unshadowed\n";
    PLUME_CHECK(s.Pass->GetNumberOfShadowedLights() == 6);
    PLUME_CHECK(s.Pass->GetNumberOfUnshadowedLights() == 0);
    PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
    PLUME_CHECK(!plume::test::HasNonFinite(image));
  }

  // 5. Ten positional lights: none left out; the 2 beyond 8 take a second
  // light group (TestAirlightManyLights checks such frames against the reference).
  {
    airtest::Scene s(24, 18);
    s.AddRoom();
    for (int k = 0; k < 10; ++k)
    {
      s.AddPointLight(-2.5 + 0.5 * k, 3.0, -1.0, 0.3, 0.3, 0.3, 1.0);
    }
    s.Pass->SetScattering(0.2, 0.2, 0.2);
    s.Camera(1.5, 1.5, 5.0, 0.0, 1.2, -2.0);
    const airtest::FloatImage image = s.RenderFloat(s.Pass);
    std::cout << "10 lights: " << s.Pass->GetNumberOfIgnoredLights() << " left out, "
              << s.Pass->GetNumberOfLightGroups() << " groups\n";
    PLUME_CHECK(s.Pass->GetNumberOfIgnoredLights() == 0);
    PLUME_CHECK(s.Pass->GetNumberOfLightGroups() == 2);
    PLUME_CHECK(!plume::test::HasNonFinite(image));
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
