// Empty-space skipping changes nothing but the time, in every mode: the image
// with skipping on equals the image with it off (within float noise: RMS
// < 1e-4, max one 8-bit step) for composite, smoke, maximum intensity (opt-in
// MIPSkipping: blocks whose max is not above the ray's running max are jumped
// over) and isosurface (blocks whose range misses the iso value on the side
// the ray is on), from outside, with the camera inside a puff (rays start
// above the iso value) and for a rotated, anisotropically spaced volume. The
// isosurface classification must mark most blocks of the sparse field (> 50 %).
#include "plumeVolumeTestUtil.h"

#include "vtkLight.h"

namespace
{
int SameWithAndWithout(const char* name, plumevolumetest::Scene& s, double minFraction = -1)
{
  s.Mapper->EmptySpaceSkippingOn();
  const plume::test::FloatImage with = plume::test::ReadBack(s.Window);
  const double fraction = s.Mapper->GetEmptyBlockFraction();
  s.Mapper->EmptySpaceSkippingOff();
  const plume::test::FloatImage without = plume::test::ReadBack(s.Window);
  const plume::test::ImageError e = plume::test::Compare(with, without);
  const double background[3] = { 0.12, 0.1, 0.18 };
  const size_t drawn = plume::test::CountForeground(with, background, 2.0 / 255);
  const std::string gl = plume::test::GLErrors(s.Window);
  const bool ok = e.RMS < 1e-4 && e.Max <= 1.5 / 255 && fraction >= minFraction && drawn > 200 && gl.empty() &&
    !plume::test::HasNonFinite(with);
  std::printf("%-44s skip vs no skip RMS %.6f max %.4f, skipped blocks %.0f%%, drew %zu px %s%s\n", name, e.RMS,
    e.Max, 100 * fraction, drawn, gl.c_str(), ok ? "" : "  FAIL");
  return ok ? 0 : 1;
}

void Lighting(vtkVolumeProperty* p)
{
  p->SetAmbient(0.2);
  p->SetDiffuse(0.7);
  p->SetSpecular(0.3);
  p->SetSpecularPower(20);
}
}

int TestVolumeSkipping(int, char*[])
{
  using namespace plumevolumetest;
  int failures = 0;
  auto field = SmokeField(64);
  {
    Scene s = MakeScene(field, 200, 160);
    failures += SameWithAndWithout("composite", s, 0.3);
    s.Mapper->SmokeOn();
    failures += SameWithAndWithout("smoke", s, 0.3);
  }
  {
    Scene s = MakeScene(field, 200, 160);
    s.Mapper->SetBlendModeToMaximumIntensity();
    s.Mapper->MIPSkippingOn(); // off by default (slower on llvmpipe)
    failures += SameWithAndWithout("maximum intensity", s);
    s.Mapper->JitterOff();
    s.Mapper->SetSampleDistance(1.7);
    failures += SameWithAndWithout("maximum intensity, no jitter, step 1.7", s);
  }
  {
    Scene s = MakeScene(field, 200, 160);
    s.Mapper->SetBlendModeToIsoSurface();
    s.Mapper->SetIsoValue(0.55);
    Lighting(s.Volume->GetProperty());
    failures += SameWithAndWithout("isosurface", s, 0.5);
    s.Mapper->SetIsoValue(0.2);
    s.Mapper->SetSampleDistance(1.3);
    failures += SameWithAndWithout("isosurface 0.2, step 1.3", s, 0.5);
  }
  {
    // coarse grid, fine steps: a skipped block spans many samples
    Scene s = MakeScene(SmokeField(12), 200, 160);
    s.Mapper->SetBlendModeToIsoSurface();
    s.Mapper->SetIsoValue(0.5);
    s.Mapper->SetSampleDistance(0.1);
    Lighting(s.Volume->GetProperty());
    failures += SameWithAndWithout("isosurface, 12^3 grid, step 0.1", s, 0.1);
  }
  {
    // camera inside the first puff: rays start above the iso value and must find its exit
    Scene s = MakeScene(field, 160, 160);
    s.Mapper->SetBlendModeToIsoSurface();
    s.Mapper->SetIsoValue(0.6);
    Lighting(s.Volume->GetProperty());
    vtkCamera* camera = s.Renderer->GetActiveCamera();
    camera->SetPosition(0.35, 0.4, 0.45);
    camera->SetFocalPoint(0.9, 0.7, 0.5);
    camera->SetViewAngle(70);
    camera->SetClippingRange(0.001, 5);
    failures += SameWithAndWithout("isosurface, camera inside a puff", s, 0.5);
    s.Mapper->SetBlendModeToMaximumIntensity();
    s.Mapper->MIPSkippingOn();
    failures += SameWithAndWithout("maximum intensity, camera inside", s);
  }
  {
    // rotated volume, anisotropic spacing, extent offset
    auto tilted = SmokeField(48);
    tilted->SetSpacing(1.0 / 47, 1.6 / 47, 0.7 / 47);
    tilted->SetExtent(5, 52, -3, 44, 0, 47);
    Scene s = MakeScene(tilted, 200, 160);
    s.Volume->RotateX(25);
    s.Volume->RotateY(-40);
    s.Renderer->ResetCamera();
    s.Mapper->SetBlendModeToIsoSurface();
    s.Mapper->SetIsoValue(0.5);
    Lighting(s.Volume->GetProperty());
    failures += SameWithAndWithout("isosurface, rotated anisotropic", s, 0.5);
    s.Mapper->SetBlendModeToMaximumIntensity();
    s.Mapper->MIPSkippingOn();
    failures += SameWithAndWithout("maximum intensity, rotated anisotropic", s);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
