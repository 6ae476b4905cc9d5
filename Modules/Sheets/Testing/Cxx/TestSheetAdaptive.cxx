// Test (no baseline): adaptive sampling. On a fine mesh (triangles far below
// sigma_b) the 3-point rule must give the same image as the full quadrature
// (which the accuracy tests check against the reference), and it must really
// be a different path: a mesh of large triangles is unaffected by the switch.
#include "plumeSheetMeshes.h"
#include "plumeSheetTestUtil.h"

int TestSheetAdaptive(int, char*[])
{
  int failures = 0;
  auto fine = sheettest::Plane(48, 40, -1.0, 1.1, -0.9, 0.9, 0.0); // cells ~0.045
  sheettest::Scene s(fine, 96, 80);
  s.Mapper->SetDensityArrayName("density");
  s.Mapper->SetBlurRadius(0.2);
  s.Mapper->SetThickness(0.1);
  s.Camera(1.5, 1.0, 4.0, 0, 0, 0, 35);
  s.Renderer->ResetCameraClippingRange();
  s.Mapper->AdaptiveSamplingOn();
  const auto on = plume::test::ReadBack(s.Window);
  s.Mapper->AdaptiveSamplingOff();
  const auto off = plume::test::ReadBack(s.Window);
  const auto e = plume::test::Compare(on, off);
  std::printf("fine mesh, adaptive vs full quadrature: RMS %.5f max %.5f\n", e.RMS, e.Max);
  PLUME_CHECK(e.RMS < 0.003 && e.Max < 0.01);
  PLUME_CHECK(e.Max > 0.0); // the switch changed something: the cheap path ran
  PLUME_CHECK(!plume::test::HasNonFinite(on));
  const double white[3] = { 1, 1, 1 };
  PLUME_CHECK(plume::test::CountForeground(on, white, 0.05) > 1000);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
