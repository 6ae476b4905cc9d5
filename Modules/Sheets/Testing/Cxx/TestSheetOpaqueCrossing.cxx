// Numeric test (no baseline): a sheet passing through an opaque sphere is
// integrated only up to the opaque depth (bounded integral), so it is right
// in front of, behind and across the sphere; compared with the reference
// given the same depth buffer. Also checks that the unbounded (paper) mode
// differs there, so the bound is really in effect.
#include "plumeSheetMeshes.h"
#include "plumeSheetTestUtil.h"


int TestSheetOpaqueCrossing(int, char*[])
{
  sheettest::UseThreads();
  int failures = 0;
  auto sheet = sheettest::Plane(3, 2, -1.2, 1.1, -0.9, 1.0, 0.05);
  sheettest::Scene s(sheet, 48, 40);
  s.Mapper->SetDensityArrayName("density");
  s.Mapper->SetDensityScale(0.6);
  s.Mapper->SetBlurRadius(0.08);
  s.Mapper->SetThickness(0.12); // thick: the sphere cuts through the smoke
  s.AddOpaqueSphere(0.2, -0.1, 0.0, 0.45, 0.9, 0.6, 0.3);
  s.Camera(1.6, 1.2, 4.0, 0, 0, 0, 35);
  const sheettest::Result r = sheettest::CompareWithReference(s, sheet, "sheet across a sphere");
  failures += sheettest::CheckGoal(r, "opaque crossing");

  // the unbounded (paper) integral must differ visibly where the sheet is behind the sphere
  s.Mapper->BoundedByDepthOff();
  const auto unb = plume::test::ReadBack(s.Window);
  s.Mapper->BoundedByDepthOn();
  const auto bnd = plume::test::ReadBack(s.Window);
  const plume::test::ImageError diff = plume::test::Compare(unb, bnd);
  std::printf("bounded vs unbounded image: max difference %.3f\n", diff.Max);
  PLUME_CHECK(diff.Max > 0.05);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
