// Numeric test (plus one byte-level baseline) of vtkPlumeAirlightPass with
// more than 4 shadowed lights (the former limit, one sampler per light):
// 1. six shadowed lights in the test room, three spot lights and three point
//    lights (cube maps), against the independent vtkPlumeAirlightReference
//    with exact ray-cast shadows: the same goal as the single-light shadow
//    tests (RMS <= 0.5 %, max <= 2 % of the airlight range away from shadow
//    edges, edges bounded loosely); all six shadowed, none left unshadowed;
//    the shadows darken the reference by more than 2 % of the range
//    somewhere, and the pass's shafts darken the same pixels by as much.
// 2. the first four of those lights: the image equals the one rendered before
//    the limit was lifted (Data/Baseline/TestAirlightManyShadows4.png, looked
//    at, written by the 4-sampler code) within one 8-bit level per channel.
//    PLUME_AIRLIGHT_WRITE_BASELINE=1 rewrites it.
#include "plumeAirlightTestUtil.h"

namespace
{
// Three spot lights and three point lights over the room: each spot's cone holds
// an occluder, each point light sees all of them.
void AddShadowedLights(airtest::Scene& s, int count)
{
  // The last two (beyond the former limit) are the strong ones, straight over
  // the plate: their shafts are what the test sees.
  const double spots[3][6] = { { -2.0, 3.6, 0.5, -1.8, 0.0, -1.4 }, { 1.8, 3.7, 0.6, 1.6, 0.0, -1.2 },
    { 0.0, 4.2, -1.5, 0.0, 0.0, -1.5 } };
  const double points[3][3] = { { 2.8, 2.6, -2.5 }, { -3.0, 2.8, -3.0 }, { -0.1, 3.4, -1.5 } };
  const double colours[6][3] = { { 1.0, 0.9, 0.75 }, { 0.7, 0.85, 1.0 }, { 0.9, 1.0, 0.8 },
    { 1.0, 0.8, 0.7 }, { 0.8, 0.8, 1.0 }, { 1.0, 1.0, 0.9 } };
  const double intensities[6] = { 0.05, 0.05, 0.05, 0.05, 1.0, 1.0 };
  for (int k = 0; k < count; ++k)
  {
    // Alternate spot, point, spot, point, ... so that both kinds fall on either side of 4.
    if (k % 2 == 0)
    {
      const double* d = spots[k / 2];
      s.AddSpotLight(d, d + 3, 35.0, 1.0, colours[k][0], colours[k][1], colours[k][2], intensities[k]);
    }
    else
    {
      const double* p = points[k / 2];
      s.AddPointLight(p[0], p[1], p[2], colours[k][0], colours[k][1], colours[k][2], intensities[k]);
    }
  }
}

void SetupShadowed(airtest::Scene& s, int lights)
{
  airtest::PlateRoom(s);
  AddShadowedLights(s, lights);
}
}

int TestAirlightManyShadows(int, char*[])
{
  int failures = 0;
  // Small: the reference casts exact shadow rays to six lights (about a minute here).
  const int W = 48, H = 36, stride = 4;

  // 1. Six shadowed lights against the reference (skipped while writing the baseline).
  if (!std::getenv("PLUME_AIRLIGHT_WRITE_BASELINE"))
  {
    airtest::Scene s(W, H);
    SetupShadowed(s, 6);
    const airtest::ShadowComparison r = airtest::CompareShadowed(s, stride, "six shadowed lights");
    failures += airtest::CheckShadowGoal(r);
    std::cout << "6 lights: " << s.Pass->GetNumberOfShadowedLights() << " shadowed, "
              << s.Pass->GetNumberOfUnshadowedLights() << " unshadowed\n";
    PLUME_CHECK(r.ShadowedLightsOn == 6);
    PLUME_CHECK(s.Pass->GetNumberOfUnshadowedLights() == 0);
    // The shadows matter at the goal's level: leaving them out (lights 5 and 6
    // unshadowed, as under the former limit) errs by more than the 2 % max.
    PLUME_CHECK(r.MaxRefDark >= 0.02 * r.All.Range);
    PLUME_CHECK(r.Darker + 4 >= r.RefDarker && r.Darker <= r.RefDarker + 4);
    PLUME_CHECK(std::fabs(r.MaxDark - r.MaxRefDark) <= 0.05 * r.MaxRefDark);
    PLUME_CHECK(r.Brighter == 0);
  }

  // 2. Four shadowed lights: unchanged against the 4-sampler code's image.
  {
    airtest::Scene s(W, H);
    SetupShadowed(s, 4);
    s.Pass->ShadowsOn();
    const airtest::FloatImage image = s.RenderFloat(s.Pass);
    PLUME_CHECK(s.Pass->GetNumberOfShadowedLights() == 4);
    PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
    size_t off = 0;
    const int worst = airtest::BaselineDifference(image, "TestAirlightManyShadows4", &off);
    PLUME_CHECK(worst >= 0); // the baseline's size
    std::cout << "4 lights against the 4-sampler baseline: largest difference " << worst
              << " levels, " << off << " channels off by more than 1\n";
    PLUME_CHECK(worst <= 1);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
