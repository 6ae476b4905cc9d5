// The triangles a sheet is made of: polygons as fans from their first point,
// triangle strips as consecutive triples, in cell order. Shared by the sheet
// mapper (vertex data) and vtkPlumeSheetDensityGrid (grid mode), which must
// see the same triangles. vtkPlumeSheetReference walks the cells itself: it
// shares no code with the renderer it checks.
//
// Cells flagged in the vtkGhostType cell array as DUPLICATECELL (owned by
// another piece: ParaView ranks, D3) or HIDDENCELL are skipped, as VTK's own
// mappers do: a duplicate drawn twice darkens the sheet twice.
#ifndef vtkPlumeSheetTriangles_h
#define vtkPlumeSheetTriangles_h

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

namespace plume
{
/**
 * Call add(a, b, c) with the point ids of every triangle of `poly`'s polygons
 * and strips, except those of ghost cells (DUPLICATECELL or HIDDENCELL).
 */
template <typename AddTriangle>
void ForEachSheetTriangle(vtkPolyData* poly, AddTriangle&& add)
{
  // polydata cell ids run verts, lines, polys, strips
  const vtkUnsignedCharArray* ghosts = vtkUnsignedCharArray::SafeDownCast(
    poly->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  const unsigned char skip = vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL;
  vtkIdType cell = poly->GetNumberOfVerts() + poly->GetNumberOfLines();
  auto ghost = [&](vtkIdType id) {
    return ghosts && id < ghosts->GetNumberOfValues() && (ghosts->GetValue(id) & skip) != 0;
  };
  // the cells are read from the arrays' own storage (vtkCellArray::Visit):
  // the legacy InitTraversal/GetNextCell took seconds on a million triangles
  auto walk = [&](vtkCellArray* cells, bool strip) {
    cells->Visit([&](auto& state) {
      const auto* offsets = state.GetOffsets()->GetPointer(0);
      const auto* conn = state.GetConnectivity()->GetPointer(0);
      const vtkIdType n = state.GetNumberOfCells();
      for (vtkIdType c = 0; c < n; ++c)
      {
        if (ghost(cell++))
        {
          continue;
        }
        const vtkIdType begin = static_cast<vtkIdType>(offsets[c]);
        const vtkIdType npts = static_cast<vtkIdType>(offsets[c + 1]) - begin;
        const auto* pts = conn + begin;
        for (vtkIdType k = 0; k + 2 < npts; ++k)
        {
          if (strip)
          {
            add(static_cast<vtkIdType>(pts[k]), static_cast<vtkIdType>(pts[k + 1]), static_cast<vtkIdType>(pts[k + 2]));
          }
          else
          {
            add(static_cast<vtkIdType>(pts[0]), static_cast<vtkIdType>(pts[k + 1]), static_cast<vtkIdType>(pts[k + 2]));
          }
        }
      }
    });
  };
  walk(poly->GetPolys(), false);
  walk(poly->GetStrips(), true);
}
}

#endif
