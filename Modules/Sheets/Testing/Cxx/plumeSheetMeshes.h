// Small meshes for the sheet tests.
#ifndef plumeSheetMeshes_h
#define plumeSheetMeshes_h

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <initializer_list>

namespace sheettest
{
/** One triangle with per-corner density (array "density"). */
inline vtkSmartPointer<vtkPolyData> Triangle(const double a[3], const double b[3], const double c[3],
  std::initializer_list<double> density = { 1, 1, 1 })
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->InsertNextPoint(a);
  pts->InsertNextPoint(b);
  pts->InsertNextPoint(c);
  vtkNew<vtkCellArray> cells;
  const vtkIdType ids[3] = { 0, 1, 2 };
  cells->InsertNextCell(3, ids);
  poly->SetPoints(pts);
  poly->SetPolys(cells);
  vtkNew<vtkDoubleArray> d;
  d->SetName("density");
  for (double v : density)
  {
    d->InsertNextValue(v);
  }
  poly->GetPointData()->AddArray(d);
  return poly;
}

/** A closed torus (vortex-ring-like) of nu x nv quads, radii R, r, centred at c, axis z. */
inline vtkSmartPointer<vtkPolyData> Ring(int nu, int nv, double R, double r, const double c[3])
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> d;
  d->SetName("density");
  const double twoPi = 2.0 * 3.14159265358979323846;
  for (int i = 0; i < nu; ++i)
  {
    const double u = twoPi * i / nu;
    for (int j = 0; j < nv; ++j)
    {
      const double v = twoPi * j / nv;
      pts->InsertNextPoint(c[0] + (R + r * std::cos(v)) * std::cos(u),
        c[1] + (R + r * std::cos(v)) * std::sin(u), c[2] + r * std::sin(v));
      d->InsertNextValue(0.6 + 0.4 * std::cos(u)); // asymmetric density around the ring
    }
  }
  vtkNew<vtkCellArray> cells;
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const vtkIdType q[4] = { i * nv + j, ((i + 1) % nu) * nv + j, ((i + 1) % nu) * nv + (j + 1) % nv,
        i * nv + (j + 1) % nv };
      cells->InsertNextCell(4, q);
    }
  }
  poly->SetPoints(pts);
  poly->SetPolys(cells);
  poly->GetPointData()->AddArray(d);
  return poly;
}

/** A flat nx x ny grid of quads in the plane z = z0 over [x0,x1]x[y0,y1]. */
inline vtkSmartPointer<vtkPolyData> Plane(int nx, int ny, double x0, double x1, double y0, double y1, double z0)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> d;
  d->SetName("density");
  for (int j = 0; j <= ny; ++j)
  {
    for (int i = 0; i <= nx; ++i)
    {
      const double x = x0 + (x1 - x0) * i / nx;
      const double y = y0 + (y1 - y0) * j / ny;
      pts->InsertNextPoint(x, y, z0);
      d->InsertNextValue(0.5 + 0.5 * (x - x0) / (x1 - x0));
    }
  }
  vtkNew<vtkCellArray> cells;
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const vtkIdType a = j * (nx + 1) + i;
      const vtkIdType q[4] = { a, a + 1, a + nx + 2, a + nx + 1 };
      cells->InsertNextCell(4, q);
    }
  }
  poly->SetPoints(pts);
  poly->SetPolys(cells);
  poly->GetPointData()->AddArray(d);
  return poly;
}
}

#endif
