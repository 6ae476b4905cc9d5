// Image regression: a vortex-ring-like torus of smoke with per-point RGB
// absorption and a blue smoke colour, crossing an opaque sphere, seen
// obliquely (asymmetric). Baseline: Testing/Data/Baseline/TestSheetRing.png.
#include "plumeSheetMeshes.h"
#include "plumeSheetTestUtil.h"

#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkRegressionTestImage.h"

int TestSheetRing(int argc, char* argv[])
{
  const double centre[3] = { 0.1, 0, 0 };
  auto ring = sheettest::Ring(36, 12, 0.8, 0.25, centre);
  vtkNew<vtkDoubleArray> rgb;
  rgb->SetName("absorption");
  rgb->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < ring->GetNumberOfPoints(); ++i)
  {
    double p[3];
    ring->GetPoint(i, p);
    rgb->InsertNextTuple3(0.4 + 0.6 * (p[0] > 0), 0.7, 1.2 - 0.5 * (p[1] > 0));
  }
  ring->GetPointData()->AddArray(rgb);
  sheettest::Scene s(ring, 240, 180);
  s.Renderer->SetBackground(0.95, 0.92, 0.85);
  s.Mapper->SetDensityArrayName("density");
  s.Mapper->SetDensityScale(0.25);
  s.Mapper->SetAbsorptionArrayName("absorption");
  s.Mapper->SetBlurRadius(0.05);
  s.Mapper->SetThickness(0.03);
  s.Mapper->SetSmokeColor(0.1, 0.15, 0.35);
  s.AddOpaqueSphere(0.7, 0.3, 0.0, 0.3, 0.8, 0.3, 0.2);
  s.Camera(1.2, 2.6, 3.4, 0.1, 0, 0, 38);
  s.Renderer->ResetCameraClippingRange();
  s.Window->Render();
  int failures = 0;
  const auto img = plume::test::ReadBack(s.Window, false);
  PLUME_CHECK(!plume::test::HasNonFinite(img));
  PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
  const int result = vtkRegressionTestImage(s.Window);
  return failures == 0 && result != vtkRegressionTester::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
