// Numeric test (no baseline): ghost cells are not drawn. A plane sheet, and
// the same sheet with a vertex cell in front (so polygon cell ids start at 1),
// a duplicate copy of part of its quads flagged DUPLICATECELL and a strip over
// the same area flagged HIDDENCELL in the vtkGhostType cell array: the exact
// mode, the grid mode and vtkPlumeSheetReference give the same result for both
// (bit-identical: the same triangles in the same order), and a darker one once
// the ghost array is removed (so the copies really are on screen).
#include "plumeSheetMeshes.h"
#include "plumeSheetTestUtil.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkUnsignedCharArray.h"

#include <cstdio>

namespace
{
/** `plane` plus ghosts: a vertex cell first, duplicate quads, a hidden strip. */
vtkSmartPointer<vtkPolyData> WithGhosts(vtkPolyData* plane, int nx)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->ShallowCopy(plane);
  vtkNew<vtkCellArray> verts;
  const vtkIdType v = 0;
  verts->InsertNextCell(1, &v);
  poly->SetVerts(verts);
  vtkNew<vtkCellArray> polys;
  polys->DeepCopy(plane->GetPolys());
  const vtkIdType owned = polys->GetNumberOfCells();
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->InsertNextValue(0); // the vertex
  for (vtkIdType i = 0; i < owned; ++i)
  {
    ghosts->InsertNextValue(0);
  }
  // the first two rows of quads again, as another piece's duplicates
  for (vtkIdType i = 0; i < 2 * nx; ++i)
  {
    vtkIdType n;
    const vtkIdType* ids;
    plane->GetPolys()->GetCellAtId(i, n, ids);
    polys->InsertNextCell(n, ids);
    ghosts->InsertNextValue(vtkDataSetAttributes::DUPLICATECELL);
  }
  poly->SetPolys(polys);
  // a strip along the first row, hidden
  vtkNew<vtkCellArray> strips;
  std::vector<vtkIdType> strip;
  for (int i = 0; i <= nx; ++i)
  {
    strip.push_back(i);
    strip.push_back(i + nx + 1);
  }
  strips->InsertNextCell(static_cast<vtkIdType>(strip.size()), strip.data());
  poly->SetStrips(strips);
  ghosts->InsertNextValue(vtkDataSetAttributes::HIDDENCELL);
  poly->GetCellData()->AddArray(ghosts);
  return poly;
}

plume::test::FloatImage Render(vtkPolyData* mesh, int mode)
{
  sheettest::Scene s(mesh, 64, 52);
  s.Mapper->SetRenderMode(mode);
  s.Mapper->SetDensityArrayName("density");
  s.Mapper->SetBlurRadius(0.08);
  s.Mapper->SetThickness(0.1);
  s.Camera(0.6, 0.4, 4.5, 0, 0, 0);
  s.Renderer->ResetCameraClippingRange();
  return plume::test::ReadBack(s.Window);
}

std::vector<double> Reference(vtkPolyData* mesh)
{
  sheettest::Scene s(mesh, 40, 32);
  s.Mapper->SetDensityArrayName("density");
  s.Mapper->SetBlurRadius(0.08);
  s.Mapper->SetThickness(0.1);
  s.Camera(0.6, 0.4, 4.5, 0, 0, 0);
  s.Renderer->ResetCameraClippingRange();
  s.Actor->SetVisibility(false);
  const plume::test::FloatImage base = plume::test::ReadBack(s.Window);
  vtkNew<vtkPlumeSheetReference> ref;
  sheettest::Configure(ref, s.Mapper, mesh);
  // every 2nd pixel along x and y (a quarter of the cost, most of this
  // test's): the ghost quads cover several pixels each way
  ref->SetPixelStride(2);
  ref->Compute(s.Renderer, base.Depth.data());
  return ref->GetTransmittance();
}

double MaxDiff(const std::vector<double>& a, const std::vector<double>& b)
{
  double d = a.size() == b.size() ? 0.0 : 1e300;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    d = std::max(d, std::fabs(a[i] - b[i]));
  }
  return d;
}
}

int TestSheetGhostCells(int, char*[])
{
  sheettest::UseThreads();
  int failures = 0;
  const int nx = 6, ny = 5;
  auto plane = sheettest::Plane(nx, ny, -1.2, 1.2, -0.9, 0.9, 0.0);
  auto ghosted = WithGhosts(plane, nx);
  auto unflagged = vtkSmartPointer<vtkPolyData>::New();
  unflagged->DeepCopy(ghosted);
  unflagged->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());

  const struct
  {
    int Mode;
    const char* Name;
  } modes[] = { { vtkPlumeSheetMapper::RENDER_EXACT, "exact" }, { vtkPlumeSheetMapper::RENDER_GRID, "grid" } };
  for (const auto& m : modes)
  {
    const auto alone = Render(plane, m.Mode);
    const auto ghost = Render(ghosted, m.Mode);
    const auto drawn = Render(unflagged, m.Mode);
    const double same = plume::test::Compare(alone, ghost).Max;
    const double diff = plume::test::Compare(alone, drawn).Max;
    std::printf("%s: sheet vs sheet+ghosts max %.3g; vs ghosts unflagged max %.3g\n", m.Name, same, diff);
    PLUME_CHECK(!plume::test::HasNonFinite(ghost));
    PLUME_CHECK(same == 0.0);
    PLUME_CHECK(diff > 0.05);
  }

  const auto refAlone = Reference(plane);
  const auto refGhost = Reference(ghosted);
  const auto refDrawn = Reference(unflagged);
  const double same = MaxDiff(refAlone, refGhost), diff = MaxDiff(refAlone, refDrawn);
  std::printf("reference: T max diff with ghosts %.3g; unflagged %.3g\n", same, diff);
  PLUME_CHECK(same == 0.0);
  PLUME_CHECK(diff > 0.05);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
