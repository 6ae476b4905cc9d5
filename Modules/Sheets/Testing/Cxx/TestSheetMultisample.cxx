// Numeric test (no baseline): the bounded integral in a multisampled window.
// The sheet crossing an opaque sphere is drawn in an 8-sample window, whose
// depth reaches the sheet through vtkPlumeOpaqueDepthTexture's resolving
// blit; the result must match the reference given the window's (resolved)
// depth, and must differ from the unbounded integral behind the sphere.
#include "plumeSheetMeshes.h"
#include "plumeSheetTestUtil.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"

int TestSheetMultisample(int, char*[])
{
  sheettest::UseThreads();
  int failures = 0;
  auto sheet = sheettest::Plane(3, 2, -1.2, 1.1, -0.9, 1.0, 0.05);
  sheettest::Scene s(sheet, 48, 40);
  s.Window->SetMultiSamples(8);
  s.Mapper->SetDensityArrayName("density");
  s.Mapper->SetDensityScale(0.6);
  s.Mapper->SetBlurRadius(0.08);
  s.Mapper->SetThickness(0.12);
  s.AddOpaqueSphere(0.2, -0.1, 0.0, 0.45, 0.9, 0.6, 0.3);
  s.Camera(1.6, 1.2, 4.0, 0, 0, 0, 35);
  s.Window->Render();
  // VTK draws into its render framebuffer: that is what must be multisampled
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(s.Window);
  const int samples = gl && gl->GetRenderFramebuffer() ? gl->GetRenderFramebuffer()->GetMultiSamples() : 0;
  std::printf("render framebuffer samples: %d\n", samples);
  PLUME_CHECK(samples > 1);
  const sheettest::Result r = sheettest::CompareWithReference(s, sheet, "MSAA sheet across a sphere");
  failures += sheettest::CheckGoal(r, "MSAA opaque crossing");

  s.Mapper->BoundedByDepthOff();
  const auto unb = plume::test::ReadBack(s.Window);
  s.Mapper->BoundedByDepthOn();
  const auto bnd = plume::test::ReadBack(s.Window);
  const plume::test::ImageError diff = plume::test::Compare(unb, bnd);
  std::printf("bounded vs unbounded image: max difference %.3f\n", diff.Max);
  PLUME_CHECK(diff.Max > 0.05);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
