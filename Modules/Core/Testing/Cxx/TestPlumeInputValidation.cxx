// vtkPlumeInputValidation: cells naming points that do not exist, offsets out of
// order, arrays shorter than their dataset, non-finite values left out of
// ranges (and counted), integer parsing that would wrap, FIFOs/devices/
// directories/NUL paths refused, budgets named in the message.
#include "vtkPlumeInputValidation.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <initializer_list>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>
#include <sys/stat.h>
#include <unistd.h>

namespace
{
int failures = 0;
#define CHECK(cond)                                                                                 \
  do                                                                                                \
  {                                                                                                 \
    if (!(cond))                                                                                    \
    {                                                                                               \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #cond "\n";                    \
      ++failures;                                                                                   \
    }                                                                                               \
  } while (false)

bool Has(const std::string& text, const std::string& part)
{
  if (text.find(part) == std::string::npos)
  {
    std::cerr << "  '" << text << "' does not contain '" << part << "'\n";
    return false;
  }
  return true;
}

vtkSmartPointer<vtkPolyData> Square(vtkIdType lastId)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(1, 1, 0);
  poly->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  const vtkIdType a[3] = { 0, 1, 2 };
  const vtkIdType b[3] = { 1, 3, lastId };
  polys->InsertNextCell(3, a);
  polys->InsertNextCell(3, b);
  poly->SetPolys(polys);
  return poly;
}
}

int TestPlumeInputValidation(int, char*[])
{
  using V = vtkPlumeInputValidation;

  // ---- connectivity
  CHECK(V::CheckCells(Square(2)).empty());
  CHECK(V::CheckDataObject(Square(2)).empty());
  CHECK(Has(V::CheckCells(Square(4)), "polygons: cell 1 references point id 4, but the dataset has 4 points"));
  CHECK(Has(V::CheckCells(Square(-3)), "point id -3"));
  CHECK(Has(V::CheckDataObject(Square(1000000)), "point id 1000000"));
  {
    // offsets out of order: the cell would read connectivity backwards
    vtkNew<vtkIdTypeArray> offsets, conn;
    for (vtkIdType v : { 0, 3, 2 })
    {
      offsets->InsertNextValue(v);
    }
    for (vtkIdType v : { 0, 1, 2 })
    {
      conn->InsertNextValue(v);
    }
    vtkNew<vtkCellArray> cells;
    cells->SetData(offsets, conn);
    CHECK(Has(V::CheckCellArray(cells, 4, "lines"), "lines: cell 1 has offset 2 out of order"));
  }
  {
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(Square(2)->GetPoints());
    const vtkIdType tet[4] = { 0, 1, 2, 9 };
    grid->InsertNextCell(VTK_TETRA, 4, tet);
    CHECK(Has(V::CheckCells(grid), "cells: cell 0 references point id 9"));
  }
  // ---- each cell's size against its type (VTK's cell classes read as many points as the type has)
  {
    auto grid = [](int type, std::initializer_list<vtkIdType> ids) {
      vtkNew<vtkUnstructuredGrid> g;
      g->SetPoints(Square(2)->GetPoints());
      const std::vector<vtkIdType> v(ids);
      vtkNew<vtkCellArray> cells; // no face stream, as a reader that sets types and cells only
      cells->InsertNextCell(static_cast<vtkIdType>(v.size()), v.data());
      g->SetCells(type, cells);
      return vtkSmartPointer<vtkUnstructuredGrid>(g);
    };
    CHECK(V::CheckCells(grid(VTK_TETRA, { 0, 1, 2, 3 })).empty());
    CHECK(V::CheckCells(grid(VTK_POLYGON, { 0, 1, 2, 3 })).empty());
    CHECK(Has(V::CheckCells(grid(VTK_HEXAHEDRON, { 0, 1, 2, 3 })),
      "cells: cell 0 (vtkHexahedron, type 12) has 4 points; it needs 8"));
    CHECK(Has(V::CheckCells(grid(VTK_POLYGON, { 0, 1 })), "(vtkPolygon, type 7) has 2 points; it needs at least 3"));
    CHECK(Has(V::CheckCells(grid(250, { 0 })), "cells: cell 0 has type 250, which is no VTK cell type"));
    {
      // a tetrahedron as a polyhedron: 4 triangular faces; then one face naming point 9
      vtkNew<vtkUnstructuredGrid> g;
      g->SetPoints(Square(2)->GetPoints());
      vtkIdType stream[] = { 4, 3, 0, 1, 2, 3, 0, 1, 3, 3, 1, 2, 3, 3, 0, 2, 3 };
      g->InsertNextCell(VTK_POLYHEDRON, 4, stream);
      CHECK(V::CheckCells(g).empty());
      g->GetFaces()->SetValue(g->GetFaceLocations()->GetValue(0) + 3, 9);
      CHECK(Has(V::CheckCells(g), "is a polyhedron (type 42) but its face 0 references point id 9"));
    }
    auto poly = Square(2);
    vtkNew<vtkCellArray> lines;
    const vtkIdType one[1] = { 0 };
    lines->InsertNextCell(1, one);
    poly->SetLines(lines);
    CHECK(V::CheckCells(poly).empty()); // the splatter skips a single-vertex line
    CHECK(Has(V::CheckCells(poly, true), "lines: cell 0 has 1 point; a line needs at least 2"));
    CHECK(Has(V::CheckDataObject(poly, true), "lines: cell 0 has 1 point; a line needs at least 2"));
    vtkNew<vtkCellArray> empty;
    empty->InsertNextCell(0, one);
    poly->SetLines(empty);
    CHECK(Has(V::CheckCells(poly), "lines: cell 0 has 0 points; a line needs at least 1"));
  }

  // ---- tuple counts
  {
    auto poly = Square(2);
    vtkNew<vtkFloatArray> s;
    s->SetName("s");
    s->SetNumberOfTuples(3);
    poly->GetPointData()->AddArray(s);
    CHECK(Has(V::CheckArrays(poly), "point array 's' has 3 tuples, but the dataset has 4 points"));
    s->SetNumberOfTuples(4);
    CHECK(V::CheckArrays(poly).empty());
    vtkNew<vtkImageData> image;
    image->SetDimensions(4, 4, 4);
    vtkNew<vtkFloatArray> v;
    v->SetName("v");
    v->SetNumberOfComponents(3);
    v->SetNumberOfTuples(63);
    image->GetPointData()->AddArray(v);
    CHECK(Has(V::CheckDataObject(image), "point array 'v' has 63 tuples, but the dataset has 64 points"));
    auto nanPoly = Square(2);
    nanPoly->GetPoints()->SetPoint(2, 0, std::nan(""), 0);
    CHECK(Has(V::CheckFinitePoints(nanPoly), "point 2 has a non-finite coordinate"));
    CHECK(V::CheckFinitePoints(Square(2)).empty());
  }

  // ---- ranges over finite values only
  {
    vtkNew<vtkDoubleArray> a;
    for (double x : { 1.0, std::numeric_limits<double>::infinity(), -2.0, std::nan(""), 0.5 })
    {
      a->InsertNextValue(x);
    }
    double r[2];
    vtkIdType bad = 0;
    CHECK(V::FiniteRange(a, 0, r, &bad));
    CHECK(r[0] == -2.0 && r[1] == 1.0 && bad == 2);
    const unsigned char mask[5] = { 1, 0, 0, 1, 1 }; // masked tuples neither widen nor count
    CHECK(V::FiniteRange(a, 0, r, &bad, mask));
    CHECK(r[0] == 0.5 && r[1] == 1.0 && bad == 1);
    vtkNew<vtkDoubleArray> v;
    v->SetNumberOfComponents(3);
    v->InsertNextTuple3(3, 4, 0);
    v->InsertNextTuple3(1e200, 1e200, 0); // finite components, overflowing norm
    CHECK(V::FiniteRange(v, -1, r, &bad));
    CHECK(r[0] == 5.0 && r[1] == 5.0 && bad == 1);
    vtkNew<vtkDoubleArray> none;
    none->InsertNextValue(std::nan(""));
    CHECK(!V::FiniteRange(none, 0, r, &bad) && r[0] == 0 && r[1] == 0 && bad == 1);
  }

  // ---- checked parsing
  long long n = 0;
  CHECK(V::ParseInteger("12", 1, 16384, n) && n == 12);
  CHECK(!V::ParseInteger("4294967297", 1, 16384, n)); // sscanf("%d") gives 1
  CHECK(!V::ParseInteger("9223372036854775808", std::numeric_limits<long long>::min(),
    std::numeric_limits<long long>::max(), n));
  CHECK(V::ParseInteger("-9223372036854775808", std::numeric_limits<long long>::min(),
          std::numeric_limits<long long>::max(), n) &&
    n == std::numeric_limits<long long>::min());
  for (const char* bad : { "", " 12", "+12", "12x", "-", "1.5", "0x10" })
  {
    CHECK(!V::ParseInteger(bad, -100, 100, n));
  }
  int w = 0, h = 0;
  CHECK(V::ParseSize("640x480", 16384, w, h) && w == 640 && h == 480);
  CHECK(V::ParseSize("64X48", 16384, w, h) && w == 64 && h == 48);
  for (const char* bad : { "4294967297x10", "10x4294967297", "0x10", "16385x1", "10x", "x10", "10x10x", "10*10" })
  {
    CHECK(!V::ParseSize(bad, 16384, w, h));
  }
  double d = 0;
  CHECK(V::ParseFinite("1.5e3", d) && d == 1500);
  for (const char* bad : { "1e999", "nan", "inf", "-inf", "1.5x", "", " 1" })
  {
    CHECK(!V::ParseFinite(bad, d));
  }
  CHECK(Has(V::CheckFinite(std::numeric_limits<double>::infinity(), "'intensity' times 'color'"),
    "'intensity' times 'color' is inf (not a finite number)"));
  CHECK(V::CheckFinite(1e300, "x").empty());

  // ---- files that are not regular files
  const std::string folder = "/tmp/plume-validation-" + std::to_string(getpid());
  mkdir(folder.c_str(), 0700);
  const std::string fifo = folder + "/pipe.vtk";
  const std::string regular = folder + "/file.vtk";
  mkfifo(fifo.c_str(), 0600);
  std::ofstream(regular) << "x";
  CHECK(Has(V::CheckRegularFile(fifo), "is a FIFO (named pipe)"));
  CHECK(Has(V::CheckRegularFile("/dev/null"), "'/dev/null' is a device"));
  CHECK(Has(V::CheckRegularFile(folder), "is a directory"));
  CHECK(Has(V::CheckRegularFile(folder + "/missing.vtk"), "file not found"));
  CHECK(Has(V::CheckRegularFile(std::string(regular) + std::string("\0.junk", 6)), "holds a NUL character"));
  CHECK(V::CheckRegularFile(regular).empty());
  std::remove(fifo.c_str());
  std::remove(regular.c_str());
  rmdir(folder.c_str());

  // ---- budgets, named in the message
  setenv("PLUME_MEMORY_BUDGET_MB", "2", 1);
  CHECK(V::MemoryBudgetBytes() == 2.0 * (1 << 20));
  CHECK(V::CheckMemory(1 << 20, "a grid").empty());
  CHECK(Has(V::CheckMemory(3.0 * (1 << 20), "a grid"), "a grid needs about 3 MB, over the memory budget of 2 MB (PLUME_MEMORY_BUDGET_MB)"));
  CHECK(Has(V::CheckMemory(std::nan(""), "a grid"), "over the memory budget"));
  // sizes rounded sensibly: 3 significant digits, whole MB, then scientific (never 12 digits)
  CHECK(Has(V::CheckMemory(12.34 * (1 << 20), "a"), "needs about 12.3 MB, over"));
  CHECK(Has(V::CheckMemory(123.6 * (1 << 20), "a"), "needs about 124 MB, over"));
  CHECK(Has(V::CheckMemory(28160.0 * (1 << 20), "a"), "needs about 28160 MB, over"));
  CHECK(Has(V::CheckMemory(4e15, "a"), "needs about 3.81e+09 MB, over"));
  unsetenv("PLUME_MEMORY_BUDGET_MB");
  CHECK(V::MemoryBudgetBytes() > (1 << 20));
  setenv("PLUME_WORK_BUDGET", "1000", 1);
  CHECK(V::CheckWork(999, "splatting").empty());
  CHECK(Has(V::CheckWork(5000, "splatting"), "splatting needs about 5e+03 operations, over the work budget of 1e+03 (PLUME_WORK_BUDGET)"));
  unsetenv("PLUME_WORK_BUDGET");
  CHECK(V::WorkBudget() == 1e10);

  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return 1;
  }
  std::cout << "all vtkPlumeInputValidation checks passed\n";
  return 0;
}
