// Numeric test (plus one byte-level baseline) of vtkPlumeAirlightPass with
// more positional lights than one shader takes (8): the lights beyond 8 are
// drawn in further passes of at most 8 lights each, added to the airlight
// term (the surface attenuation applied once, by the first pass).
// 1. eleven lights (two groups: 8 + 3), five of them shadowed (spot and
//    point lights, in both groups), the three lights of the second group
//    the strongest, against the independent vtkPlumeAirlightReference with
//    exact ray-cast shadows: the shadow tests' goal (RMS <= 0.5 %, max <= 2 %
//    of the airlight range away from shadow edges, edges bounded loosely);
//    nothing ignored, two groups, every occluded light shadowed. The same
//    eleven lights at Downsampling 2 against the same reference.
// 2. the first eight of those lights (one group): the image equals the one
//    the single-pass code rendered before groups existed
//    (Data/Baseline/TestAirlightManyLights8.png, looked at) within one 8-bit
//    level per channel. PLUME_AIRLIGHT_WRITE_BASELINE=1 rewrites it.
#include "plumeAirlightTestUtil.h"

namespace
{
// Eleven lights over the room with a plate: weak lights first (the first
// group), then three strong ones (the second group) whose airlight and
// shafts dominate: leaving them out, or attenuating the surfaces twice,
// errs by far more than the goal.
void AddLights(airtest::Scene& s, int count)
{
  struct L
  {
    bool Spot;
    double P[3], F[3];
    double Colour[3];
    double Intensity;
  };
  const L lights[11] = {
    { true, { -2.0, 3.6, 0.5 }, { -1.8, 0.0, -1.4 }, { 1.0, 0.9, 0.75 }, 0.2 },
    { false, { 2.8, 2.6, -2.5 }, { 0, 0, 0 }, { 0.7, 0.85, 1.0 }, 0.15 },
    { false, { 3.5, 0.8, 1.5 }, { 0, 0, 0 }, { 0.9, 1.0, 0.8 }, 0.12 },
    { true, { 1.8, 3.7, 0.6 }, { 1.6, 0.0, -1.2 }, { 1.0, 0.8, 0.7 }, 0.2 },
    { false, { -3.0, 2.8, -3.0 }, { 0, 0, 0 }, { 0.8, 0.8, 1.0 }, 0.15 },
    { false, { -3.8, 0.6, 1.0 }, { 0, 0, 0 }, { 1.0, 1.0, 0.9 }, 0.12 },
    { false, { 0.5, 4.5, 2.5 }, { 0, 0, 0 }, { 0.6, 0.9, 0.7 }, 0.12 },
    { false, { -1.0, 1.2, 2.0 }, { 0, 0, 0 }, { 0.9, 0.7, 0.9 }, 0.1 },
    // the second group
    { true, { 0.0, 4.2, -1.5 }, { 0.0, 0.0, -1.5 }, { 0.9, 1.0, 0.8 }, 0.8 },
    { false, { -0.1, 3.4, -1.5 }, { 0, 0, 0 }, { 1.0, 1.0, 0.9 }, 0.8 },
    { false, { 3.0, 1.0, -3.0 }, { 0, 0, 0 }, { 0.8, 0.9, 1.0 }, 0.3 },
  };
  for (int k = 0; k < count; ++k)
  {
    const L& l = lights[k];
    if (l.Spot)
    {
      s.AddSpotLight(l.P, l.F, 35.0, 1.0, l.Colour[0], l.Colour[1], l.Colour[2], l.Intensity);
    }
    else
    {
      s.AddPointLight(l.P[0], l.P[1], l.P[2], l.Colour[0], l.Colour[1], l.Colour[2], l.Intensity);
    }
  }
}

void Setup(airtest::Scene& s, int lights)
{
  airtest::PlateRoom(s);
  AddLights(s, lights);
}
}

int TestAirlightManyLights(int, char*[])
{
  int failures = 0;
  // Small: the reference casts exact shadow rays to eleven lights.
  const int W = 40, H = 30, stride = 4;

  // 1. Eleven lights against the reference (skipped while writing the baseline).
  if (!std::getenv("PLUME_AIRLIGHT_WRITE_BASELINE"))
  {
    airtest::Scene s(W, H);
    Setup(s, 11);
    // Shadow maps of 256 texels per side (default 1024): a cube face's 90
    // degrees in 0.35-degree texels, finer than this 40 x 30 frame's pixels
    // (1.7 degrees), and a sixteenth of the bakes' cost (most of this test's
    // CPU; the errors below stay under a tenth of the goal at 1024 and 256).
    s.Pass->SetShadowMapSize(256);
    const airtest::ShadowComparison r = airtest::CompareShadowed(s, stride, "eleven lights");
    failures += airtest::CheckShadowGoal(r);
    std::cout << "11 lights: " << s.Pass->GetNumberOfLightGroups() << " groups, "
              << s.Pass->GetNumberOfShadowedLights() << " shadowed, " << s.Pass->GetNumberOfIgnoredLights()
              << " ignored\n";
    PLUME_CHECK(s.Pass->GetNumberOfLightGroups() == 2);
    PLUME_CHECK(s.Pass->GetNumberOfIgnoredLights() == 0);
    PLUME_CHECK(s.Pass->GetNumberOfUnshadowedLights() == 0);
    PLUME_CHECK(r.ShadowedLightsOn == 11); // every light sees an occluder: all shadowed
    PLUME_CHECK(r.MaxRefDark >= 0.02 * r.All.Range);
    PLUME_CHECK(r.Brighter == 0);

    // The same at Downsampling 2 (each group its own low-resolution pass).
    s.Pass->SetDownsampling(2);
    const airtest::FloatImage low = s.RenderFloat(s.Pass);
    const airtest::EdgeSplit e = airtest::CompareAwayFromEdges(low, r.Ref, r.RefLit, r.Air, stride);
    airtest::Print("eleven lights, downsampling 2, away from shadow edges", e.Inner);
    PLUME_CHECK(e.Inner.RMS <= 0.005);
    PLUME_CHECK(e.Inner.Max <= 0.02);
    PLUME_CHECK(!plume::test::HasNonFinite(low));
    PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
  }

  // 2. Eight lights (one group): unchanged against the single-pass code's image.
  {
    airtest::Scene s(W, H);
    Setup(s, 8);
    s.Pass->ShadowsOn();
    const airtest::FloatImage image = s.RenderFloat(s.Pass);
    PLUME_CHECK(s.Pass->GetNumberOfLightGroups() == 1);
    PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
    const int worst = airtest::BaselineDifference(image, "TestAirlightManyLights8");
    PLUME_CHECK(worst >= 0); // the baseline's size
    std::cout << "8 lights against the single-pass baseline: largest difference " << worst << " levels\n";
    PLUME_CHECK(worst <= 1);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
