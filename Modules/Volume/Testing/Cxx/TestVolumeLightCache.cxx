// Smoke mode's cached lighting (LightCache): the transmittance towards each
// light kept per grid node and interpolated at the samples, instead of a
// shadow ray per sample.
//  - accuracy: within TestVolumeAccuracy's smoke bounds against the CPU
//    reference, and close to the shadow-ray image (which is always current);
//  - with empty-space skipping the nodes of transparent blocks are not
//    marched, and the image is the one with every node marched;
//  - the first frame after a change casts shadow rays (a light that moves
//    every frame never remakes the cache), the next one remakes it;
//  - no stale lighting: after a change of the light's direction, the opacity
//    transfer function, the data or the shadow step the cache is recomputed
//    once and the image again matches the shadow-ray image; a camera move
//    under a scene light recomputes nothing.
#include "plumeVolumeTestUtil.h"

#include "vtkDataArray.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"

int TestVolumeLightCache(int, char*[])
{
  using namespace plumevolumetest;
  int failures = 0;
  Scene s = SideLitSmoke();
  vtkLight* light = vtkLight::SafeDownCast(s.Renderer->GetLights()->GetItemAsObject(0));

  // the cached image against the reference, then against shadow rays
  plume::test::FloatImage cached;
  const Result r = CompareWithReference(s, vtkPlumeVolumeReference::SMOKE, 0.25, &cached);
  failures += Check("smoke, light cache vs reference", r, 0.008, 0.06);
  const int first = s.Mapper->GetLightVolumeUpdateCount();
  const bool used = s.Mapper->GetLastLightCache();
  // cached vs shadow rays, after `what` changed: `updates` recomputations expected
  const double tolerance = 0.004; // RMS over the image
  const double maxTolerance = 0.03;
  int expectedCount = first;
  const auto compare = [&](const char* what, int updates) {
    // the first frame after a change casts shadow rays (inputs that change
    // every frame would remake the cache every frame); the next one, with
    // the inputs held still, remakes it
    s.Window->Render();
    const bool raysFirst = !s.Mapper->GetLastLightCache();
    const int countFirst = s.Mapper->GetLightVolumeUpdateCount();
    expectedCount += updates;
    const plume::test::FloatImage withCache = plume::test::ReadBack(s.Window);
    const int count = s.Mapper->GetLightVolumeUpdateCount();
    const bool cachedAfter = s.Mapper->GetLastLightCache();
    s.Mapper->LightCacheOff();
    const plume::test::FloatImage rays = plume::test::ReadBack(s.Window);
    s.Mapper->LightCacheOn();
    const plume::test::ImageError e = plume::test::Compare(withCache, rays);
    const bool ok = count == expectedCount && countFirst == expectedCount - updates && raysFirst == (updates > 0) &&
      cachedAfter && e.RMS <= tolerance && e.Max <= maxTolerance &&
      plume::test::GLErrors(s.Window).empty();
    std::printf("%-40s first frame shadow rays %d (%d); light volume computed %d times (%d); cache vs shadow rays RMS %.5f (<= %.3f) max %.4f (<= %.2f)%s\n",
      what, raysFirst ? 1 : 0, updates > 0 ? 1 : 0, count, expectedCount, e.RMS, tolerance, e.Max, maxTolerance, ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
    return withCache;
  };
  const bool firstOk = used && first == 1;
  std::printf("%-40s used %d, computed %d times (1)%s\n", "first render", used ? 1 : 0, first, firstOk ? "" : "  FAIL");
  failures += firstOk ? 0 : 1;
  compare("same view", 0);
  {
    // with empty-space skipping only the nodes of non-transparent blocks are
    // marched: the same image as with every node marched (a fresh mapper with
    // skipping off)
    const double empty = s.Mapper->GetEmptyBlockFraction();
    const plume::test::FloatImage skipped = plume::test::ReadBack(s.Window);
    Scene u = SideLitSmoke();
    u.Mapper->EmptySpaceSkippingOff();
    const plume::test::FloatImage all = plume::test::ReadBack(u.Window);
    const plume::test::ImageError e = plume::test::Compare(skipped, all);
    const bool ok = empty > 0.1 && u.Mapper->GetLastLightCache() && e.Max <= 0.5 / 255;
    std::printf("%-40s empty blocks %.0f%% (> 10%%: skipping on); vs every node marched: max %.5f (<= 1/510)%s\n",
      "transparent blocks' nodes", 100 * empty, e.Max, ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
  }

  // a scene light stays put relative to the volume: nothing to recompute
  s.Renderer->GetActiveCamera()->Azimuth(35);
  s.Renderer->ResetCameraClippingRange();
  compare("camera moved", 0);
  light->SetPosition(-0.8, 1.4, 1.1);
  compare("light moved", 1);
  vtkPiecewiseFunction* opacity = s.Volume->GetProperty()->GetScalarOpacity();
  double range[2];
  s.Image->GetPointData()->GetScalars()->GetRange(range);
  opacity->AddPoint(range[0] + 0.5 * (range[1] - range[0]), 0.9);
  compare("opacity changed", 1);
  vtkDataArray* values = s.Image->GetPointData()->GetScalars();
  {
    // mirrored along x: same range, the shadows move
    int dims[3];
    s.Image->GetDimensions(dims);
    for (vtkIdType row = 0; row < vtkIdType(dims[1]) * dims[2]; ++row)
    {
      for (int i = 0; i < dims[0] / 2; ++i)
      {
        const vtkIdType a = row * dims[0] + i, b = row * dims[0] + dims[0] - 1 - i;
        const double va = values->GetTuple1(a);
        values->SetTuple1(a, values->GetTuple1(b));
        values->SetTuple1(b, va);
      }
    }
  }
  values->Modified();
  compare("data changed", 1);
  s.Mapper->SetShadowSampleDistance(1.0);
  compare("shadow step changed", 1);
  {
    // only the dense cores are visible (opacity from 40 % of the range up):
    // most blocks are transparent and the occupied ones border them inside
    // the smoke, where the skipped nodes' neighbours are in shadow
    Scene t = SideLitSmoke();
    double r[2];
    t.Image->GetPointData()->GetScalars()->GetRange(r);
    SetTransferFunctions(t.Volume->GetProperty(), r[0] + 0.4 * (r[1] - r[0]), r[1], 1.0, 0.01 * t.Image->GetLength());
    const plume::test::FloatImage skipped = plume::test::ReadBack(t.Window);
    const double empty = t.Mapper->GetEmptyBlockFraction();
    Scene u = SideLitSmoke();
    SetTransferFunctions(u.Volume->GetProperty(), r[0] + 0.4 * (r[1] - r[0]), r[1], 1.0, 0.01 * u.Image->GetLength());
    u.Mapper->EmptySpaceSkippingOff();
    const plume::test::FloatImage all = plume::test::ReadBack(u.Window);
    const plume::test::ImageError e = plume::test::Compare(skipped, all);
    const bool ok = empty > 0.5 && e.Max <= 0.5 / 255 && u.Mapper->GetLastLightCache();
    std::printf("%-40s empty blocks %.0f%% (> 50%%); vs every node marched: max %.5f (<= 1/510)%s\n",
      "dense cores only", 100 * empty, e.Max, ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
