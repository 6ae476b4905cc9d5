// The mapper's float image against vtkPlumeVolumeReference (independent CPU
// raycaster, double precision) on a 64³ analytic smoke field, per mode.
// RMS and max error (RGB, 0..1) are asserted; the read-back is 8-bit, so the
// floor is ~1/510 per channel.
#include "plumeVolumeTestUtil.h"


int TestVolumeAccuracy(int, char*[])
{
  using namespace plumevolumetest;
  int failures = 0;
  auto field = SmokeField(64);

  {
    Scene s = MakeScene(field, 200, 160);
    s.Mapper->JitterOff();
    failures += Check("composite, no jitter, step 0.5", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.005, 0.04);
    s.Mapper->JitterOn();
    failures += Check("composite, jitter, step 0.5", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.005, 0.04);
    s.Mapper->SetSampleDistance(0.25);
    failures += Check("composite, jitter, step 0.25", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.004, 0.03);
  }
  {
    // empty-space skipping must skip (the smoke field is mostly transparent)
    // and change nothing: same image with and without it
    Scene s = MakeScene(field, 200, 160);
    const plume::test::FloatImage with = plume::test::ReadBack(s.Window);
    const double emptyFraction = s.Mapper->GetEmptyBlockFraction();
    s.Mapper->EmptySpaceSkippingOff();
    const plume::test::FloatImage without = plume::test::ReadBack(s.Window);
    const plume::test::ImageError e = plume::test::Compare(with, without);
    const bool ok = emptyFraction > 0.3 && e.RMS < 1e-4 && e.Max <= 1.5 / 255;
    std::printf("%-40s empty blocks %.0f%%, skip vs no skip RMS %.6f max %.4f%s\n", "empty-space skipping",
      100 * emptyFraction, e.RMS, e.Max, ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
  }
  {
    // shaded composite: every sample Phong-lit with its central-difference normal
    Scene s = MakeScene(field, 200, 160);
    s.Volume->GetProperty()->ShadeOn();
    s.Volume->GetProperty()->SetAmbient(0.2);
    s.Volume->GetProperty()->SetDiffuse(0.7);
    s.Volume->GetProperty()->SetSpecular(0.3);
    s.Volume->GetProperty()->SetSpecularPower(15);
    failures += Check("composite, shaded", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.005, 0.05);
  }
  {
    // nearest-node sampling (the property's interpolation type), on a coarse grid where it shows
    Scene s = MakeScene(SmokeField(16), 200, 160);
    s.Volume->GetProperty()->SetInterpolationTypeToNearest();
    // blocky: a ray's sample can fall on either side of a node's cell face
    failures += Check("nearest interpolation", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.006, 0.15);
  }
  {
    Scene s = MakeScene(field, 200, 160);
    s.Mapper->SetBlendModeToMaximumIntensity();
    failures += Check("maximum intensity", CompareWithReference(s, vtkPlumeVolumeReference::MAXIMUM_INTENSITY), 0.005, 0.05);
  }
  {
    Scene s = MakeScene(field, 200, 160);
    s.Mapper->SetBlendModeToIsoSurface();
    s.Mapper->SetIsoValue(0.55);
    s.Volume->GetProperty()->SetAmbient(0.2);
    s.Volume->GetProperty()->SetDiffuse(0.7);
    s.Volume->GetProperty()->SetSpecular(0.3);
    s.Volume->GetProperty()->SetSpecularPower(20);
    // silhouettes may differ by a pixel where a thin crossing lies between two samples
    failures += Check("isosurface", CompareWithReference(s, vtkPlumeVolumeReference::ISOSURFACE), 0.02, 1.0);
  }
  {
    Scene s = SideLitSmoke();
    failures += Check("smoke, self-shadowed", CompareWithReference(s, vtkPlumeVolumeReference::SMOKE, 0.25), 0.008, 0.06);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
