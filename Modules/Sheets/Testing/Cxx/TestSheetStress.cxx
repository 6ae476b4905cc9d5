// Stress test (no baseline): degenerate triangles, rays parallel to the
// plane, sigma -> 0 and sigma >> scene, density 1e-6..1e6, a 1e6 offset,
// the camera inside a triangle's box and behind the near plane, NaN/Inf in
// every array: no NaN pixel, no GL error, no crash; plus what each case
// must look like where that is known (documented policy: bad values count
// as zero density, triangles with a non-finite corner are skipped).
#include "plumeSheetMeshes.h"
#include "plumeSheetTestUtil.h"

#include "vtkDoubleArray.h"
#include "vtkPointData.h"

#include <limits>

namespace
{
int Clean(sheettest::Scene& s, const char* what, plume::test::FloatImage* out = nullptr)
{
  int failures = 0;
  s.Renderer->ResetCameraClippingRange();
  const plume::test::FloatImage img = plume::test::ReadBack(s.Window);
  const std::string gl = plume::test::GLErrors(s.Window);
  if (plume::test::HasNonFinite(img) || !gl.empty())
  {
    std::cerr << what << ": non-finite pixel or GL error '" << gl << "'\n";
    ++failures;
  }
  if (out)
  {
    *out = img;
  }
  return failures;
}

double Darkest(const plume::test::FloatImage& img)
{
  double lo = 1.0;
  for (size_t i = 0; i < img.RGBA.size(); i += 4)
  {
    lo = std::min(lo, double(img.RGBA[i]));
  }
  return lo;
}
}

int TestSheetStress(int, char*[])
{
  int failures = 0;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const double a[3] = { -0.8, -0.6, 0.0 }, b[3] = { 0.9, -0.4, 0.1 }, c[3] = { -0.2, 0.8, -0.1 };

  // reference image: one good triangle
  auto good = sheettest::Triangle(a, b, c, { 1, 1, 1 });
  plume::test::FloatImage goodImg;
  {
    sheettest::Scene s(good, 64, 56);
    s.Mapper->SetBlurRadius(0.1);
    s.Mapper->SetThickness(0.05);
    s.Camera(0.3, 0.2, 5.0, 0, 0, 0);
    failures += Clean(s, "good", &goodImg);
    PLUME_CHECK(Darkest(goodImg) < 0.6);
  }

  // degenerate triangles next to the good one: zero area, repeated and collinear corners
  {
    auto mesh = sheettest::Triangle(a, b, c, { 1, 1, 1 });
    vtkPoints* pts = mesh->GetPoints();
    const vtkIdType p3 = pts->InsertNextPoint(0.3, 0.3, 0.0);
    const vtkIdType p4 = pts->InsertNextPoint(0.6, 0.6, 0.0);
    const vtkIdType p5 = pts->InsertNextPoint(0.9, 0.9, 0.0);
    auto* d = vtkDoubleArray::SafeDownCast(mesh->GetPointData()->GetArray("density"));
    for (int i = 0; i < 3; ++i)
    {
      d->InsertNextValue(1.0);
    }
    const vtkIdType rep[3] = { p3, p3, p3 }, dup[3] = { p3, p4, p4 }, col[3] = { p3, p4, p5 };
    mesh->GetPolys()->InsertNextCell(3, rep);
    mesh->GetPolys()->InsertNextCell(3, dup);
    mesh->GetPolys()->InsertNextCell(3, col);
    sheettest::Scene s(mesh, 64, 56);
    s.Mapper->SetBlurRadius(0.1);
    s.Mapper->SetThickness(0.05);
    s.Camera(0.3, 0.2, 5.0, 0, 0, 0);
    plume::test::FloatImage img;
    failures += Clean(s, "degenerate", &img);
    PLUME_CHECK(s.Mapper->GetTriangleCount() == 1);
    PLUME_CHECK(plume::test::Compare(img, goodImg).Max < 1e-6);
  }

  sheettest::Scene s(good, 64, 56);
  s.Mapper->SetBlurRadius(0.1);
  s.Mapper->SetThickness(0.05);
  // view rays exactly parallel to the plane of an axis-aligned triangle (t+- denominators 0)
  {
    const double fa[3] = { -1, -1, 0 }, fb[3] = { 1, -1, 0 }, fc[3] = { 0, 1, 0 };
    auto flat = sheettest::Triangle(fa, fb, fc);
    sheettest::Scene e(flat, 64, 56);
    e.Mapper->SetBlurRadius(0.1);
    e.Mapper->SetThickness(0.05);
    e.Camera(5, 0, 0, 0, 0, 0);
    plume::test::FloatImage img;
    failures += Clean(e, "parallel thick", &img);
    PLUME_CHECK(Darkest(img) < 0.9); // a dark line where the rays run inside the sheet
    e.Mapper->ThinSheetOn();
    failures += Clean(e, "parallel thin", &img);
    e.Camera(5, 0.0, 1e-7, 0, 0, 0);
    failures += Clean(e, "nearly parallel thin");
  }
  s.Camera(0.3, 0.2, 5.0, 0, 0, 0);
  // sigma -> 0 and sigma >> scene
  for (double sigma : { 0.0, 1e-30, 1e-12, 1e6, 1e30 })
  {
    s.Mapper->SetBlurRadius(sigma);
    s.Mapper->SetThickness(sigma);
    failures += Clean(s, ("sigma " + std::to_string(sigma)).c_str());
    s.Mapper->ThinSheetOn();
    failures += Clean(s, ("thin sigma " + std::to_string(sigma)).c_str());
    s.Mapper->ThinSheetOff();
  }
  s.Mapper->SetBlurRadius(0.1);
  s.Mapper->SetThickness(0.05);
  // density across 1e-6 .. 1e6
  for (double d : { 1e-6, 1e-3, 1.0, 1e3, 1e6 })
  {
    s.Mapper->SetDensity(d);
    plume::test::FloatImage img;
    failures += Clean(s, ("density " + std::to_string(d)).c_str(), &img);
    if (d == 1e-6)
    {
      PLUME_CHECK(Darkest(img) > 0.99);
    }
    if (d == 1e6)
    {
      PLUME_CHECK(Darkest(img) < 0.01);
    }
  }
  s.Mapper->SetDensity(1.0);
  // camera inside the support of the triangle, and the triangle behind the near plane
  s.Camera(0.0, 0.0, 0.02, 0.1, 0.1, -1.0, 60);
  failures += Clean(s, "camera inside");
  s.Camera(0.0, 0.0, 0.02, 0.1, 0.1, -1.0, 60);
  s.Renderer->GetActiveCamera()->SetClippingRange(0.5, 10.0);
  s.Window->Render();
  {
    const auto img = plume::test::ReadBack(s.Window);
    PLUME_CHECK(!plume::test::HasNonFinite(img));
    PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
  }
  s.Camera(0.0, 0.0, -2.0, 0.0, 0.0, -5.0);
  failures += Clean(s, "triangle behind the camera");

  // 1e6 offset: the same scene shifted by 1e6 looks the same
  {
    auto shifted = sheettest::Triangle(a, b, c, { 1, 1, 1 });
    for (vtkIdType i = 0; i < 3; ++i)
    {
      double p[3];
      shifted->GetPoint(i, p);
      shifted->GetPoints()->SetPoint(i, p[0] + 1e6, p[1] + 1e6, p[2] + 1e6);
    }
    sheettest::Scene o(shifted, 64, 56);
    o.Mapper->SetBlurRadius(0.1);
    o.Mapper->SetThickness(0.05);
    o.Camera(0.3 + 1e6, 0.2 + 1e6, 5.0 + 1e6, 1e6, 1e6, 1e6);
    plume::test::FloatImage img;
    failures += Clean(o, "1e6 offset", &img);
    const auto err = plume::test::Compare(img, goodImg);
    std::printf("1e6 offset vs origin: RMS %.4f max %.4f\n", err.RMS, err.Max);
    PLUME_CHECK(err.RMS < 0.01 && err.Max < 0.05);
  }

  // NaN / Inf: in density and sigma arrays they count as zero; in positions the triangle is skipped
  {
    auto mesh = sheettest::Triangle(a, b, c, { 1, 1, 1 });
    vtkNew<vtkDoubleArray> sig;
    sig->SetName("sigma");
    for (int i = 0; i < 3; ++i)
    {
      sig->InsertNextValue(0.1);
    }
    mesh->GetPointData()->AddArray(sig);
    sheettest::Scene n(mesh, 64, 56);
    n.Mapper->SetDensityArrayName("density");
    n.Mapper->SetBlurArrayName("sigma");
    n.Mapper->SetThicknessArrayName("sigma");
    n.Mapper->SetAbsorptionArrayName("missing"); // warns, falls back to grey
    n.Camera(0.3, 0.2, 5.0, 0, 0, 0);
    auto* d = vtkDoubleArray::SafeDownCast(mesh->GetPointData()->GetArray("density"));
    for (double bad : { nan, inf, -inf, -1.0 })
    {
      d->SetValue(1, bad);
      d->Modified();
      plume::test::FloatImage img, zero;
      failures += Clean(n, "bad density", &img);
      d->SetValue(1, 0.0);
      d->Modified();
      failures += Clean(n, "zero density", &zero);
      PLUME_CHECK(plume::test::Compare(img, zero).Max < 1e-6); // treated as zero
      d->SetValue(1, 1.0);
    }
    d->Modified();
    for (double bad : { nan, inf, -inf })
    {
      sig->SetValue(2, bad);
      sig->Modified();
      failures += Clean(n, "bad sigma");
      sig->SetValue(2, 0.1);
      sig->Modified();
    }
    mesh->GetPoints()->SetPoint(0, nan, 0, 0);
    mesh->Modified();
    failures += Clean(n, "NaN position");
    PLUME_CHECK(n.Mapper->GetSkippedTriangles() == 1);
    mesh->GetPoints()->SetPoint(0, inf, 0, 0);
    mesh->Modified();
    failures += Clean(n, "Inf position");
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
