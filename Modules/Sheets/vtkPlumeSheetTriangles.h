// The triangles a sheet is made of: polygons as fans from their first point,
// triangle strips as consecutive triples, in cell order. Shared by the sheet
// mapper (vertex data) and vtkPlumeSheetDensityGrid (grid mode), which must
// see the same triangles. vtkPlumeSheetReference walks the cells itself: it
// shares no code with the renderer it checks.
#ifndef vtkPlumeSheetTriangles_h
#define vtkPlumeSheetTriangles_h

#include "vtkCellArray.h"
#include "vtkPolyData.h"

namespace plume
{
/** Call add(a, b, c) with the point ids of every triangle of `poly`'s polygons and strips. */
template <typename AddTriangle>
void ForEachSheetTriangle(vtkPolyData* poly, AddTriangle&& add)
{
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  vtkCellArray* polys = poly->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts);)
  {
    for (vtkIdType k = 1; k + 1 < npts; ++k)
    {
      add(pts[0], pts[k], pts[k + 1]);
    }
  }
  vtkCellArray* strips = poly->GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(npts, pts);)
  {
    for (vtkIdType k = 0; k + 2 < npts; ++k)
    {
      add(pts[k], pts[k + 1], pts[k + 2]);
    }
  }
}
}

#endif
