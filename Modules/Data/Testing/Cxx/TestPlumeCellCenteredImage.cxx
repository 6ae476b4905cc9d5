// vtkPlumeCellCenteredImage: every cell value, exactly, at its cell's centre.
// - an analytic image (f = i + 10 j + 100 k per cell, a vector cell array, a
//   non-zero extent start, a flat axis): dims - 1, origin + spacing / 2, and
//   the value at each output point is f of the cell whose centre it is,
//   computed from the point's position alone;
// - the OpenFOAM cavity (an unstructured grid of 20 x 20 x 1 hexahedra): the
//   uniform box lattice is found (exact), and for every cell its p and U are
//   found at the output point nearest its centroid (the mean of its points);
// - the same analytic cells split into tetrahedra (no box lattice): the probe
//   fallback, not exact, still gives each box's value at its centre;
// - no cell arrays: an error naming it.
#include "plumeDataTestUtilities.h"

#include "vtkPlumeCellCenteredImage.h"

#include "vtkCell.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>

using plumetest::Checker;

namespace
{
double F(int i, int j, int k)
{
  return i + 10.0 * j + 100.0 * k;
}

/** An image of nx x ny x nz points whose cells hold f (scalar "f") and (f, -f, 2f) ("v"). */
vtkSmartPointer<vtkImageData> AnalyticImage(int nx, int ny, int nz)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(2, 2 + nx - 1, -1, -1 + ny - 1, 0, nz - 1); // extents need not start at 0
  image->SetOrigin(1.0, 2.0, 3.0);
  image->SetSpacing(0.5, 0.25, 2.0);
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  vtkNew<vtkFloatArray> v;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  const int cx = std::max(1, nx - 1), cy = std::max(1, ny - 1), cz = std::max(1, nz - 1);
  for (int k = 0; k < cz; ++k)
  {
    for (int j = 0; j < cy; ++j)
    {
      for (int i = 0; i < cx; ++i)
      {
        f->InsertNextValue(F(i, j, k));
        v->InsertNextTuple3(F(i, j, k), -F(i, j, k), 2 * F(i, j, k));
      }
    }
  }
  image->GetCellData()->AddArray(f);
  image->GetCellData()->SetScalars(f);
  image->GetCellData()->AddArray(v);
  return image;
}

/** Each output point's value is f of the input cell whose centre the point is (from its position). */
void CheckAnalytic(Checker& check, vtkImageData* out, int cx, int cy, int cz, bool vectors)
{
  int dims[3];
  out->GetDimensions(dims);
  check.Equal(dims[0], cx, "dims x");
  check.Equal(dims[1], cy, "dims y");
  check.Equal(dims[2], cz, "dims z");
  vtkDataArray* f = out->GetPointData()->GetArray("f");
  vtkDataArray* v = out->GetPointData()->GetArray("v");
  if (!check.True(f && (!vectors || v), "point arrays f and v"))
  {
    return;
  }
  int wrong = 0;
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    double x[3];
    out->GetPoint(p, x);
    // cell (i, j, k) of the input spans points (2 + i, -1 + j, k) .. +1: centre at origin + (index + 0.5) spacing
    const double fi = (x[0] - 1.0) / 0.5 - 2 - 0.5;
    const double fj = (x[1] - 2.0) / 0.25 + 1 - 0.5;
    const double fk = cz == 1 && dims[2] == 1 && std::abs(x[2] - 3.0) < 1e-12 ? 0.0 : (x[2] - 3.0) / 2.0 - 0.5;
    const int i = static_cast<int>(std::lround(fi)), j = static_cast<int>(std::lround(fj)),
              k = static_cast<int>(std::lround(fk));
    if (std::abs(fi - i) > 1e-9 || std::abs(fj - j) > 1e-9 || std::abs(fk - k) > 1e-9)
    {
      ++wrong; // not at a cell centre
      continue;
    }
    if (f->GetComponent(p, 0) != F(i, j, k) ||
      (vectors && (v->GetComponent(p, 1) != -F(i, j, k) || v->GetComponent(p, 2) != 2 * F(i, j, k))))
    {
      ++wrong;
    }
  }
  check.Equal(wrong, 0, "points not at their cell's centre with its value");
  check.True(out->GetPointData()->GetScalars() == f, "f stays the active scalars");
}
}

int TestPlumeCellCenteredImage(int, char*[])
{
  Checker check;
  {
    check.Context = "analytic image 5x4x3 points";
    vtkNew<vtkPlumeCellCenteredImage> filter;
    filter->SetInputData(AnalyticImage(5, 4, 3));
    filter->Update();
    check.True(filter->GetExact(), "exact");
    CheckAnalytic(check, filter->GetOutput(), 4, 3, 2, true);
    check.Equal(filter->GetOutput()->GetPointData()->GetArray("f")->GetNumberOfTuples(), vtkIdType(24), "24 values");
  }
  {
    check.Context = "analytic image 5x4x1 points (flat in z)";
    vtkNew<vtkPlumeCellCenteredImage> filter;
    filter->SetInputData(AnalyticImage(5, 4, 1));
    filter->Update();
    CheckAnalytic(check, filter->GetOutput(), 4, 3, 1, true);
  }
  {
    check.Context = "analytic cells as tetrahedra (probe fallback)";
    auto cube = AnalyticImage(9, 9, 9);
    cube->SetSpacing(1, 1, 1); // 8 unit cells along each axis: bounds [3, 11] x [1, 9] x [3, 11]
    vtkNew<vtkDataSetTriangleFilter> tets;
    tets->SetInputData(cube);
    tets->Update();
    vtkNew<vtkPlumeCellCenteredImage> filter;
    filter->SetInputConnection(tets->GetOutputPort());
    filter->SetMaximumDimension(8); // 8 boxes along each axis: the original cells' centres
    filter->Update();
    check.True(!filter->GetExact(), "not exact (not a box lattice)");
    vtkImageData* out = filter->GetOutput();
    int dims[3];
    out->GetDimensions(dims);
    check.Equal(dims[0] * 100 + dims[1] * 10 + dims[2], 888, "dims 8 x 8 x 8 (as 100x+10y+z)");
    vtkDataArray* f = out->GetPointData()->GetArray("f");
    vtkDataArray* mask = out->GetPointData()->GetArray("vtkValidPointMask");
    if (check.True(f && mask, "f and the mask"))
    {
      int wrong = 0;
      for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
      {
        double x[3];
        out->GetPoint(p, x);
        const int i = static_cast<int>(std::floor(x[0] - 3.0));
        const int j = static_cast<int>(std::floor(x[1] - 1.0));
        const int k = static_cast<int>(std::floor(x[2] - 3.0));
        if (mask->GetComponent(p, 0) != 1 || f->GetComponent(p, 0) != F(i, j, k))
        {
          ++wrong;
        }
      }
      check.Equal(wrong, 0, "samples without the value of the box containing them");
    }
  }
  {
    check.Context = "OpenFOAM cavity, cell p and U";
    auto reader = plumetest::Reader("openfoam_cavity/cavity/case.foam");
    reader->UpdateInformation();
    reader->SetTimeStep(reader->GetNumberOfTimeValues() - 1);
    reader->Update();
    auto* mesh = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
    vtkNew<vtkPlumeCellCenteredImage> filter;
    filter->SetInputData(mesh);
    filter->Update();
    vtkImageData* out = filter->GetOutput();
    check.True(filter->GetExact(), "a uniform box lattice: exact");
    int dims[3];
    out->GetDimensions(dims);
    check.Equal(dims[0] * 100 + dims[1] * 10 + dims[2], 20 * 100 + 20 * 10 + 1, "dims 20 x 20 x 1 (as 100x+10y+z)");
    vtkDataArray* p = out->GetPointData()->GetArray("p");
    vtkDataArray* u = out->GetPointData()->GetArray("U");
    vtkDataArray* cp = mesh ? mesh->GetCellData()->GetArray("p") : nullptr;
    vtkDataArray* cu = mesh ? mesh->GetCellData()->GetArray("U") : nullptr;
    if (check.True(p && u && cp && cu, "p and U in and out") &&
      check.Equal(mesh->GetNumberOfCells(), out->GetNumberOfPoints(), "one point per cell"))
    {
      int wrong = 0;
      double largest = 0;
      for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
      {
        vtkCell* cell = mesh->GetCell(c);
        double centroid[3] = { 0, 0, 0 };
        for (vtkIdType q = 0; q < cell->GetNumberOfPoints(); ++q)
        {
          double x[3];
          cell->GetPoints()->GetPoint(q, x);
          for (int a = 0; a < 3; ++a)
          {
            centroid[a] += x[a] / double(cell->GetNumberOfPoints());
          }
        }
        const vtkIdType at = out->FindPoint(centroid);
        double x[3];
        out->GetPoint(at, x);
        const double distance = std::sqrt(vtkMath::Distance2BetweenPoints(x, centroid));
        largest = std::max(largest, distance);
        if (at < 0 || p->GetComponent(at, 0) != cp->GetComponent(c, 0) ||
          u->GetComponent(at, 0) != cu->GetComponent(c, 0) || u->GetComponent(at, 1) != cu->GetComponent(c, 1))
        {
          ++wrong;
        }
      }
      check.Equal(wrong, 0, "cells whose p/U is not at their centroid");
      // the mesh's points are floats: centroids agree to float rounding (cells are 0.005 wide)
      check.True(largest < 1e-8, "every output point is a cell centroid (largest distance " + std::to_string(largest) + ")");
    }
  }
  {
    check.Context = "no cell arrays";
    auto image = AnalyticImage(3, 3, 3);
    image->GetCellData()->Initialize();
    vtkNew<vtkPlumeCellCenteredImage> filter;
    filter->SetInputData(image);
    filter->GlobalWarningDisplayOff(); // the error is expected (ctest fails on VTK's error lines)
    filter->Update();
    check.Equal(filter->GetLastError(), std::string("cell-centred image: the input has no cell arrays"), "error");
  }
  return check.Failures == 0 ? 0 : 1;
}
