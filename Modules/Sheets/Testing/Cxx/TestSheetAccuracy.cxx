// Numeric test (no baseline): the transmittance the mapper renders matches
// vtkPlumeSheetReference (double precision, adaptive quadrature along each
// exact ray) within the goal (RMS <= 1 %, max <= 5 % of the
// reference's dynamic range) on simple scenes: face-on, edge-on and grazing
// triangles, sigma_b much larger than the triangle, sigma below a pixel,
// thin-sheet mode, RGB absorption and a closed ring.
#include "plumeSheetMeshes.h"
#include "plumeSheetTestUtil.h"

int TestSheetAccuracy(int, char*[])
{
  sheettest::UseThreads();
  int failures = 0;
  const int W = 48, H = 40;
  const double a[3] = { -0.8, -0.6, 0.0 }, b[3] = { 0.9, -0.4, 0.1 }, c[3] = { -0.2, 0.8, -0.1 };

  {
    auto tri = sheettest::Triangle(a, b, c, { 0.4, 1.0, 0.7 });
    sheettest::Scene s(tri, W, H);
    s.Mapper->SetDensityArrayName("density");
    s.Mapper->SetDensityScale(1.5);
    s.Mapper->SetBlurRadius(0.15);
    s.Mapper->SetThickness(0.1);
    s.Camera(0.3, 0.2, 5.0, 0, 0, 0);
    failures += sheettest::CheckGoal(sheettest::CompareWithReference(s, tri, "face-on"), "face-on");
    s.Camera(5.0, 0.3, 0.45, 0, 0, 0); // the plane is (nearly) edge-on
    failures += sheettest::CheckGoal(sheettest::CompareWithReference(s, tri, "edge-on"), "edge-on");
    s.Camera(4.5, 0.6, 1.4, 0, 0, 0);
    failures += sheettest::CheckGoal(sheettest::CompareWithReference(s, tri, "grazing"), "grazing");
    s.Mapper->SetThinSheet(true);
    s.Camera(0.3, 0.2, 5.0, 0, 0, 0);
    failures += sheettest::CheckGoal(sheettest::CompareWithReference(s, tri, "thin face-on"), "thin face-on");
    s.Camera(4.5, 0.6, 1.4, 0, 0, 0);
    failures += sheettest::CheckGoal(sheettest::CompareWithReference(s, tri, "thin grazing"), "thin grazing");
  }
  {
    // sigma_b far larger than the triangle: a soft blob
    const double sa[3] = { -0.1, -0.05, 0 }, sb[3] = { 0.12, -0.02, 0.02 }, sc[3] = { 0.0, 0.1, 0 };
    auto tri = sheettest::Triangle(sa, sb, sc, { 20, 40, 30 });
    sheettest::Scene s(tri, W, H);
    s.Mapper->SetDensityArrayName("density");
    s.Mapper->SetBlurRadius(0.4);
    s.Mapper->SetThickness(0.2);
    s.Camera(0.4, 0.3, 5.0, 0, 0, 0);
    failures += sheettest::CheckGoal(sheettest::CompareWithReference(s, tri, "sigma_b >> triangle"), "big sigma");
  }
  {
    // sigmas far below a pixel: the 1/3-pixel lower bound decides the width
    auto tri = sheettest::Triangle(a, b, c, { 0.3, 0.6, 0.45 });
    sheettest::Scene s(tri, W, H);
    s.Mapper->SetDensityArrayName("density");
    s.Mapper->SetBlurRadius(1e-5);
    s.Mapper->SetThickness(1e-5);
    s.Camera(0.3, 0.2, 5.0, 0, 0, 0);
    failures += sheettest::CheckGoal(sheettest::CompareWithReference(s, tri, "sigma below a pixel"), "small sigma");
  }
  {
    // RGB absorption: channels darken differently
    auto tri = sheettest::Triangle(a, b, c, { 1, 1, 1 });
    vtkNew<vtkDoubleArray> rgb;
    rgb->SetName("absorption");
    rgb->SetNumberOfComponents(3);
    rgb->InsertNextTuple3(0.2, 0.8, 1.5);
    rgb->InsertNextTuple3(1.2, 0.5, 0.1);
    rgb->InsertNextTuple3(0.6, 1.0, 0.4);
    tri->GetPointData()->AddArray(rgb);
    sheettest::Scene s(tri, W, H);
    s.Mapper->SetAbsorptionArrayName("absorption");
    s.Mapper->SetBlurRadius(0.12);
    s.Mapper->SetThickness(0.05);
    s.Camera(-0.6, 0.4, 5.0, 0, 0, 0);
    failures += sheettest::CheckGoal(sheettest::CompareWithReference(s, tri, "RGB absorption"), "rgb");
  }
  {
    // a closed vortex-ring-like torus, seen obliquely (many overlapping layers)
    const double centre[3] = { 0.1, 0, 0 };
    auto ring = sheettest::Ring(14, 6, 0.8, 0.25, centre);
    sheettest::Scene s(ring, W, H);
    s.Mapper->SetDensityArrayName("density");
    s.Mapper->SetDensityScale(0.15);
    s.Mapper->SetBlurRadius(0.06);
    s.Mapper->SetThickness(0.04);
    s.Camera(1.0, 3.0, 3.6, 0, 0, 0, 35);
    failures += sheettest::CheckGoal(sheettest::CompareWithReference(s, ring, "closed ring"), "ring");
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
