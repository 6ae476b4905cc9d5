// Numeric test (no baseline): a sheet passing through an opaque sphere is
// integrated only up to the opaque depth (bounded integral), so it is right
// in front of, behind and across the sphere; compared with the reference
// given the same depth buffer. Also checks that the unbounded (paper) mode
// differs there, so the bound is really in effect. Run twice: in a plain
// window and in an 8-sample one, whose depth reaches the sheet through
// vtkPlumeOpaqueDepthTexture's resolving blit.
#include "plumeSheetMeshes.h"
#include "plumeSheetTestUtil.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"

#include <string>

int TestSheetOpaqueCrossing(int, char*[])
{
  sheettest::UseThreads();
  int failures = 0;
  auto sheet = sheettest::Plane(3, 2, -1.2, 1.1, -0.9, 1.0, 0.05);
  for (int samples : { 0, 8 })
  {
    sheettest::Scene s(sheet, 48, 40);
    s.Window->SetMultiSamples(samples);
    s.Mapper->SetDensityArrayName("density");
    s.Mapper->SetDensityScale(0.6);
    s.Mapper->SetBlurRadius(0.08);
    s.Mapper->SetThickness(0.12); // thick: the sphere cuts through the smoke
    s.AddOpaqueSphere(0.2, -0.1, 0.0, 0.45, 0.9, 0.6, 0.3);
    s.Camera(1.6, 1.2, 4.0, 0, 0, 0, 35);
    const std::string what = samples ? "MSAA opaque crossing" : "opaque crossing";
    if (samples)
    {
      // VTK draws into its render framebuffer: that is what must be multisampled
      s.Window->Render();
      auto* gl = vtkOpenGLRenderWindow::SafeDownCast(s.Window);
      const int got = gl && gl->GetRenderFramebuffer() ? gl->GetRenderFramebuffer()->GetMultiSamples() : 0;
      std::printf("render framebuffer samples: %d\n", got);
      PLUME_CHECK(got > 1);
    }
    const sheettest::Result r = sheettest::CompareWithReference(s, sheet, what + ": sheet across a sphere");
    failures += sheettest::CheckGoal(r, what);

    // the unbounded (paper) integral must differ visibly where the sheet is behind the sphere
    s.Mapper->BoundedByDepthOff();
    const auto unb = plume::test::ReadBack(s.Window);
    s.Mapper->BoundedByDepthOn();
    const auto bnd = plume::test::ReadBack(s.Window);
    const plume::test::ImageError diff = plume::test::Compare(unb, bnd);
    std::printf("%s: bounded vs unbounded image: max difference %.3f\n", what.c_str(), diff.Max);
    PLUME_CHECK(diff.Max > 0.05);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
