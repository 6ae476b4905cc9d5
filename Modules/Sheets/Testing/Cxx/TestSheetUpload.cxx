// Test (no baseline): camera moves and constant density/sigma/thin changes
// (uniforms) upload nothing; changing which arrays feed the mesh re-uploads; zero-density triangles are culled on the CPU and off-screen
// ones draw nothing; draws split into chunks give the same image, random grid
// offsets included (each triangle keeps its id); the bounds cover the smoke, not just the mesh (VTK sets
// the clipping range from them, and the sheet, like VTK's volume mappers,
// integrates from the near plane).
#include "plumeSheetMeshes.h"
#include "plumeSheetTestUtil.h"

#include <cmath>

int TestSheetUpload(int, char*[])
{
  int failures = 0;
  const double centre[3] = { 0, 0, 0 };
  auto ring = sheettest::Ring(12, 6, 0.8, 0.25, centre);
  sheettest::Scene s(ring, 64, 56);
  const double white[3] = { 1, 1, 1 }; // the background
  s.Mapper->SetDensityArrayName("density");
  s.Mapper->SetBlurRadius(0.05);
  s.Camera(1, 2, 4, 0, 0, 0);
  s.Window->Render();
  PLUME_CHECK(s.Mapper->GetUploadCount() == 1);
  PLUME_CHECK(s.Mapper->GetTriangleCount() == 12 * 6 * 2);
  for (int i = 0; i < 3; ++i)
  {
    s.Renderer->GetActiveCamera()->Azimuth(20);
    s.Window->Render();
  }
  PLUME_CHECK(s.Mapper->GetUploadCount() == 1); // camera only: no upload
  s.Mapper->SetSmokeColor(0.2, 0.3, 0.9);
  s.Mapper->SetGridA(5);
  s.Window->Render();
  PLUME_CHECK(s.Mapper->GetUploadCount() == 1); // shading settings: no upload
  {
    // constants are uniforms: a slider on blur, thickness, density scale or
    // thin uploads nothing, yet each takes effect
    auto frame = plume::test::ReadBack(s.Window);
    auto changed = [&](const char* what) {
      const auto next = plume::test::ReadBack(s.Window);
      const double d = plume::test::Compare(frame, next).Max;
      std::printf("%s: uploads %d, image change %.3f\n", what, s.Mapper->GetUploadCount(), d);
      PLUME_CHECK(s.Mapper->GetUploadCount() == 1);
      PLUME_CHECK(d > 0.01);
      frame = next;
    };
    s.Mapper->SetBlurRadius(0.07);
    changed("blur 0.05 -> 0.07");
    s.Mapper->SetThickness(0.09);
    changed("thickness 0.05 -> 0.09");
    s.Mapper->SetDensityScale(1.7);
    changed("density scale 1 -> 1.7");
    s.Mapper->ThinSheetOn();
    changed("thin on");
    s.Mapper->ThinSheetOff();
    changed("thin off");
    s.Mapper->SetDensityScale(1.0);
    s.Mapper->SetThickness(0.05);
    // which arrays feed the triangles is in the buffer: that uploads
    s.Mapper->SetDensityArrayName("");
    s.Mapper->SetDensity(0.5);
    s.Window->Render();
    PLUME_CHECK(s.Mapper->GetUploadCount() == 2);
    s.Mapper->SetDensity(0.8); // a constant again: no upload
    s.Window->Render();
    PLUME_CHECK(s.Mapper->GetUploadCount() == 2);
    s.Mapper->SetDensityArrayName("density");
    s.Window->Render();
    PLUME_CHECK(s.Mapper->GetUploadCount() == 3);
  }
  {
    // mesh bounds padded by Cutoff x the largest sigma (0.07 blur, 0.05 thickness)
    double mesh[6];
    ring->GetBounds(mesh);
    const double* b = s.Mapper->GetBounds();
    const double pad = s.Mapper->GetCutoff() * 0.07;
    for (int a = 0; a < 6; ++a)
    {
      PLUME_CHECK(std::fabs(b[a] - (mesh[a] + (a % 2 ? pad : -pad))) < 1e-9);
    }
  }
  {
    // chunked draws: bit-identical frames, with the paper's grid (whose
    // per-fragment random offsets are seeded by the triangle's id)
    s.Mapper->SetQuadrature(vtkPlumeSheetMapper::QUADRATURE_GRID);
    s.Mapper->SetGridA(2);
    s.Mapper->SetGridB(1);
    s.Mapper->SetMaximumTrianglesPerDraw(0);
    const auto one = plume::test::ReadBack(s.Window);
    PLUME_CHECK(s.Mapper->GetLastDrawCount() == 1);
    s.Mapper->SetMaximumTrianglesPerDraw(5); // 144 triangles: 29 draws
    const auto chunked = plume::test::ReadBack(s.Window);
    PLUME_CHECK(s.Mapper->GetLastDrawCount() == 29);
    const auto err = plume::test::Compare(one, chunked);
    std::printf("one draw vs 5 triangles per draw: max difference %g\n", err.Max);
    PLUME_CHECK(err.Max == 0.0);
    PLUME_CHECK(plume::test::CountForeground(one, white, 1.0 / 255) > 100); // the ring is drawn
    s.Mapper->SetQuadrature(vtkPlumeSheetMapper::QUADRATURE_ANALYTIC);
    s.Mapper->SetGridA(8);
    s.Mapper->SetMaximumTrianglesPerDraw(16384);
  }
  // zero density on one ring column: those triangles are culled
  auto* d = ring->GetPointData()->GetArray("density");
  for (vtkIdType i = 0; i < ring->GetNumberOfPoints(); ++i)
  {
    d->SetTuple1(i, i < 2 * 6 ? 0.0 : 1.0);
  }
  d->Modified();
  ring->Modified();
  s.Window->Render();
  PLUME_CHECK(s.Mapper->GetUploadCount() == 4);
  PLUME_CHECK(s.Mapper->GetTriangleCount() == (12 - 1) * 6 * 2);
  // looking away: nothing drawn, background only
  s.Camera(0, 0, 4, 0, 0, 10);
  s.Renderer->GetActiveCamera()->SetClippingRange(0.1, 20);
  const auto img = plume::test::ReadBack(s.Window);
  PLUME_CHECK(plume::test::CountForeground(img, white, 1.0 / 255) == 0);
  std::printf("uploads %d, triangles %lld\n", s.Mapper->GetUploadCount(),
    static_cast<long long>(s.Mapper->GetTriangleCount()));
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
