// Numeric test (no baseline): vtkPlumeSheetMapper's grid mode (RENDER_GRID:
// the smoke computed once on a grid, raycast by vtkPlumeVolumeMapper) against
// vtkPlumeSheetReference on the accuracy scenes: face-on, edge-on, grazing,
// sigma_b >> triangle, varying d/sigma_b/sigma_t, a closed ring, an opaque
// sphere across the sheet, a rotated + scaled actor, the camera inside the
// smoke and near the sheet; stated bound RMS
// <= 1 %, max <= 5 % of the reference's transmittance range (the issue's
// interactive goal) at the default 2 nodes per sigma. Then: camera moves
// compute no grid; changes of blur, thickness, density, the arrays and the
// mesh recompute it and the frame follows (no stale frame); stress inputs
// (NaN, huge sigmas, degenerate triangles) give finite pixels. The real
// office stream sheet is measured by `plume bench sheets` (its grid takes
// tens of seconds to compute here: too slow for the suite; RMS 0.52 %, max
// 3.7 % at 64x52 when it was run once).
#include "plumeSheetMeshes.h"
#include "plumeSheetTestUtil.h"

#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTransform.h"

#include <cmath>
#include <limits>

namespace
{
int Check(sheettest::Scene& s, vtkPolyData* mesh, const std::string& name)
{
  s.Mapper->SetRenderMode(vtkPlumeSheetMapper::RENDER_GRID);
  // The reference at every 2nd pixel along x and y (a quarter of its cost,
  // most of this test's): the grid's errors come from its spacing (2 nodes per
  // sigma, several pixels here) and span many pixels. With the spacing 4x
  // coarser every scene fails on this lattice (RMS 1.7-54 %, max 13-88 %).
  const sheettest::Result r = sheettest::CompareWithReference(s, 2, mesh, name);
  std::printf("%-28s grid spacing %.4g, %d grids\n", "", s.Mapper->GetGridSpacing(), s.Mapper->GetGridComputeCount());
  return sheettest::CheckGoal(r, name);
}
}

int TestSheetGridMode(int, char*[])
{
  sheettest::UseThreads();
  int failures = 0;
  const int W = 64, H = 52;
  const double a[3] = { -0.8, -0.6, 0.0 }, b[3] = { 0.9, -0.4, 0.1 }, c[3] = { -0.2, 0.8, -0.1 };
  {
    auto tri = sheettest::Triangle(a, b, c, { 0.4, 1.0, 0.7 });
    sheettest::Scene s(tri, W, H);
    s.Mapper->SetDensityArrayName("density");
    s.Mapper->SetDensityScale(1.5);
    s.Mapper->SetBlurRadius(0.15);
    s.Mapper->SetThickness(0.1);
    s.Camera(0.3, 0.2, 5.0, 0, 0, 0);
    failures += Check(s, tri, "grid face-on");
    s.Camera(5.0, 0.3, 0.45, 0, 0, 0);
    failures += Check(s, tri, "grid edge-on");
    s.Camera(4.5, 0.6, 1.4, 0, 0, 0);
    failures += Check(s, tri, "grid grazing");
    // camera inside the smoke, near the sheet, looking along it (the ray
    // starts at the near plane)
    s.Camera(-0.3, -0.25, 0.06, 1.5, 1.0, -0.2, 70);
    s.Renderer->GetActiveCamera()->SetClippingRange(0.01, 10);
    failures += sheettest::CheckGoal([&] {
      s.Mapper->SetRenderMode(vtkPlumeSheetMapper::RENDER_GRID);
      // (CompareWithReference resets the clipping range from the bounds: the
      // camera is inside them, so VTK puts the near plane close to the eye)
      return sheettest::CompareWithReference(s, 2, tri, "grid camera inside");
    }(), "grid camera inside");
    // the actor moved, rotated and scaled (sigmas scale, densities stay per world area)
    vtkNew<vtkTransform> xf;
    xf->Translate(0.3, -0.2, 0.1);
    xf->RotateWXYZ(35, 0.3, 1.0, 0.2);
    xf->Scale(1.4, 1.4, 1.4);
    s.Actor->SetUserTransform(xf);
    s.Camera(0.5, 0.8, 6.0, 0.3, -0.2, 0.1);
    failures += Check(s, tri, "grid actor matrix");
  }
  {
    const double sa[3] = { -0.1, -0.05, 0 }, sb[3] = { 0.12, -0.02, 0.02 }, sc[3] = { 0.0, 0.1, 0 };
    auto tri = sheettest::Triangle(sa, sb, sc, { 20, 40, 30 });
    sheettest::Scene s(tri, W, H);
    s.Mapper->SetDensityArrayName("density");
    s.Mapper->SetBlurRadius(0.4);
    s.Mapper->SetThickness(0.2);
    s.Camera(0.4, 0.3, 5.0, 0, 0, 0);
    failures += Check(s, tri, "grid sigma_b >> triangle");
  }
  {
    // d, sigma_b, sigma_t all vary over a tilted triangle
    const double p0[3] = { -1.0, -0.78, -0.45 }, p1[3] = { 1.15, -0.48, -0.28 }, p2[3] = { -0.15, 0.87, 0.5 };
    auto tri = sheettest::Triangle(p0, p1, p2, { 0.4, 1.2, 0.8 });
    vtkNew<vtkDoubleArray> bl, th;
    bl->SetName("blur");
    th->SetName("thickness");
    const double sbv[3] = { 0.14, 0.05, 0.09 }, stv[3] = { 0.02, 0.09, 0.05 };
    for (int k = 0; k < 3; ++k)
    {
      bl->InsertNextValue(sbv[k]);
      th->InsertNextValue(stv[k]);
    }
    tri->GetPointData()->AddArray(bl);
    tri->GetPointData()->AddArray(th);
    sheettest::Scene s(tri, W, H);
    s.Mapper->SetDensityArrayName("density");
    s.Mapper->SetBlurArrayName("blur");
    s.Mapper->SetThicknessArrayName("thickness");
    s.Camera(0.4, -0.3, 5.0, 0, 0, 0);
    failures += Check(s, tri, "grid varying sigmas");
  }
  {
    const double centre[3] = { 0.1, 0, 0 };
    auto ring = sheettest::Ring(14, 6, 0.8, 0.25, centre);
    sheettest::Scene s(ring, W, H);
    s.Mapper->SetDensityArrayName("density");
    s.Mapper->SetDensityScale(0.15);
    s.Mapper->SetBlurRadius(0.06);
    s.Mapper->SetThickness(0.04);
    s.Camera(1.0, 3.0, 3.6, 0, 0, 0, 35);
    failures += Check(s, ring, "grid closed ring");
  }
  {
    // an opaque sphere through the sheet: rays stop at its depth
    auto plane = sheettest::Plane(6, 5, -1.2, 1.2, -0.9, 0.9, 0.0);
    sheettest::Scene s(plane, W, H);
    s.AddOpaqueSphere(0.2, -0.1, 0.0, 0.45, 0.9, 0.5, 0.2);
    s.Mapper->SetDensityArrayName("density");
    s.Mapper->SetBlurRadius(0.08);
    s.Mapper->SetThickness(0.15);
    s.Camera(1.6, 0.9, 4.2, 0, 0, 0);
    failures += Check(s, plane, "grid opaque crossing");
  }
  {
    // invalidation: camera moves compute nothing; data and sigma changes recompute, frames follow
    const double centre[3] = { 0, 0, 0 };
    auto ring = sheettest::Ring(12, 6, 0.8, 0.25, centre);
    sheettest::Scene s(ring, 64, 56);
    s.Mapper->SetRenderMode(vtkPlumeSheetMapper::RENDER_GRID);
    s.Mapper->SetDensityArrayName("density");
    s.Mapper->SetBlurRadius(0.05);
    s.Camera(1, 2, 4, 0, 0, 0);
    auto frame = plume::test::ReadBack(s.Window);
    PLUME_CHECK(s.Mapper->GetGridComputeCount() == 1);
    for (int i = 0; i < 3; ++i)
    {
      s.Renderer->GetActiveCamera()->Azimuth(20);
      s.Window->Render();
    }
    PLUME_CHECK(s.Mapper->GetGridComputeCount() == 1);
    s.Camera(1, 2, 4, 0, 0, 0);
    frame = plume::test::ReadBack(s.Window);
    int count = 1;
    auto changed = [&](const char* what) {
      const auto next = plume::test::ReadBack(s.Window);
      const double d = plume::test::Compare(frame, next).Max;
      std::printf("%s: grids %d, image change %.3f\n", what, s.Mapper->GetGridComputeCount(), d);
      PLUME_CHECK(s.Mapper->GetGridComputeCount() == ++count);
      PLUME_CHECK(d > 0.01);
      frame = next;
    };
    s.Mapper->SetBlurRadius(0.08);
    changed("blur 0.05 -> 0.08");
    s.Mapper->SetThickness(0.09);
    changed("thickness 0.05 -> 0.09");
    s.Mapper->SetDensityScale(1.7);
    changed("density scale 1 -> 1.7");
    s.Mapper->SetDensityArrayName("");
    changed("density array -> constant 1");
    auto* pts = ring->GetPoints();
    for (vtkIdType i = 0; i < pts->GetNumberOfPoints(); ++i)
    {
      double p[3];
      pts->GetPoint(i, p);
      pts->SetPoint(i, p[0] * 1.2, p[1], p[2]);
    }
    pts->Modified();
    changed("mesh points moved");
    // the reference agrees with the last frame (not a stale one)
    failures += sheettest::CheckGoal(sheettest::CompareWithReference(s, 2, ring, "grid after changes"), "grid after changes");
  }
  {
    // stress: NaN density and position, huge sigma, zero-area triangle: finite pixels, no GL error
    auto ring = sheettest::Ring(8, 4, 0.8, 0.25, std::array<double, 3>{ 0, 0, 0 }.data());
    auto* d = ring->GetPointData()->GetArray("density");
    d->SetTuple1(0, std::numeric_limits<double>::quiet_NaN());
    d->SetTuple1(1, -3.0);
    d->SetTuple1(2, 1e30);
    ring->GetPoints()->SetPoint(5, std::numeric_limits<double>::infinity(), 0, 0);
    ring->GetPoints()->SetPoint(9, ring->GetPoints()->GetPoint(10));
    sheettest::Scene s(ring, 48, 40);
    s.Mapper->SetRenderMode(vtkPlumeSheetMapper::RENDER_GRID);
    s.Mapper->SetDensityArrayName("density");
    s.Mapper->SetGridMaximumNodes(1e6); // tiny sigmas: the spacing grows to fit (and sigma is raised to it)
    s.Camera(1, 2, 4, 0, 0, 0);
    for (double blur : { 1e-12, 0.05, 1e12 })
    {
      s.Mapper->SetBlurRadius(blur);
      s.Renderer->ResetCameraClippingRange();
      const auto img = plume::test::ReadBack(s.Window);
      const std::string gl = plume::test::GLErrors(s.Window);
      std::printf("stress blur %g: finite %d, GL '%s', spacing %g\n", blur, !plume::test::HasNonFinite(img),
        gl.c_str(), s.Mapper->GetGridSpacing());
      PLUME_CHECK(!plume::test::HasNonFinite(img));
      PLUME_CHECK(gl.empty());
      PLUME_CHECK(s.Mapper->GetGridSpacing() > 0.0);
    }
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
