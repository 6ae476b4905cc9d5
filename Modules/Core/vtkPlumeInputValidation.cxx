#include "vtkPlumeInputValidation.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRectilinearGrid.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnsignedCharArray.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace
{
std::string Num(double v)
{
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

template <typename T>
std::string CheckStorage(const T* offsets, vtkIdType numberOfOffsets, const T* conn, vtkIdType connSize,
  vtkIdType numberOfPoints, const char* what)
{
  if (numberOfOffsets == 0)
  {
    return connSize == 0 ? std::string()
                         : std::string(what) + ": " + std::to_string(connSize) + " point ids but no cells";
  }
  if (offsets[0] != 0)
  {
    return std::string(what) + ": the first cell starts at offset " + std::to_string(offsets[0]) + ", not 0";
  }
  for (vtkIdType c = 1; c < numberOfOffsets; ++c)
  {
    if (offsets[c] < offsets[c - 1] || static_cast<vtkIdType>(offsets[c]) > connSize)
    {
      return std::string(what) + ": cell " + std::to_string(c - 1) + " has offset " +
        std::to_string(offsets[c]) + " out of order or beyond the " + std::to_string(connSize) +
        " point ids";
    }
  }
  for (vtkIdType c = 0; c + 1 < numberOfOffsets; ++c)
  {
    for (vtkIdType k = offsets[c]; k < static_cast<vtkIdType>(offsets[c + 1]); ++k)
    {
      const vtkIdType id = static_cast<vtkIdType>(conn[k]);
      if (id < 0 || id >= numberOfPoints)
      {
        return std::string(what) + ": cell " + std::to_string(c) + " references point id " +
          std::to_string(id) + ", but the dataset has " + std::to_string(numberOfPoints) +
          " points (valid ids 0 to " + std::to_string(numberOfPoints - 1) + ")";
      }
    }
  }
  return std::string();
}

// The points a cell of VTK type `type` needs: exactly `exact` (when > 0), else
// at least `least`; false for a number that is no VTK cell type.
bool CellSize(int type, vtkIdType& exact, vtkIdType& least)
{
  exact = 0;
  least = 1;
  switch (type)
  {
    case VTK_EMPTY_CELL: least = 0; return true;
    case VTK_VERTEX: exact = 1; return true;
    case VTK_LINE: exact = 2; return true;
    case VTK_TRIANGLE: exact = 3; return true;
    case VTK_PIXEL: case VTK_QUAD: case VTK_TETRA: case VTK_CUBIC_LINE: exact = 4; return true;
    case VTK_PYRAMID: exact = 5; return true;
    case VTK_WEDGE: case VTK_QUADRATIC_TRIANGLE: case VTK_QUADRATIC_LINEAR_QUAD: exact = 6; return true;
    case VTK_BIQUADRATIC_TRIANGLE: exact = 7; return true;
    case VTK_VOXEL: case VTK_HEXAHEDRON: case VTK_QUADRATIC_QUAD: exact = 8; return true;
    case VTK_BIQUADRATIC_QUAD: exact = 9; return true;
    case VTK_PENTAGONAL_PRISM: case VTK_QUADRATIC_TETRA: exact = 10; return true;
    case VTK_HEXAGONAL_PRISM: case VTK_QUADRATIC_LINEAR_WEDGE: exact = 12; return true;
    case VTK_QUADRATIC_PYRAMID: exact = 13; return true;
    case VTK_QUADRATIC_WEDGE: exact = 15; return true;
    case VTK_BIQUADRATIC_QUADRATIC_WEDGE: exact = 18; return true;
    case VTK_TRIQUADRATIC_PYRAMID: exact = 19; return true;
    case VTK_QUADRATIC_HEXAHEDRON: exact = 20; return true;
    case VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON: exact = 24; return true;
    case VTK_TRIQUADRATIC_HEXAHEDRON: exact = 27; return true;
    case VTK_QUADRATIC_EDGE: exact = 3; return true;
    case VTK_POLY_VERTEX: case VTK_CONVEX_POINT_SET: return true;
    case VTK_POLY_LINE: case VTK_LAGRANGE_CURVE: case VTK_BEZIER_CURVE: case VTK_HIGHER_ORDER_EDGE:
      least = 2; return true;
    case VTK_TRIANGLE_STRIP: case VTK_POLYGON: case VTK_LAGRANGE_TRIANGLE: case VTK_BEZIER_TRIANGLE:
    case VTK_HIGHER_ORDER_TRIANGLE: case VTK_HIGHER_ORDER_POLYGON:
      least = 3; return true;
    case VTK_LAGRANGE_QUADRILATERAL: case VTK_BEZIER_QUADRILATERAL: case VTK_HIGHER_ORDER_QUAD:
    case VTK_LAGRANGE_TETRAHEDRON: case VTK_BEZIER_TETRAHEDRON: case VTK_HIGHER_ORDER_TETRAHEDRON:
    case VTK_POLYHEDRON:
      least = 4; return true;
    case VTK_LAGRANGE_PYRAMID: case VTK_BEZIER_PYRAMID: case VTK_HIGHER_ORDER_PYRAMID: least = 5; return true;
    case VTK_LAGRANGE_WEDGE: case VTK_BEZIER_WEDGE: case VTK_HIGHER_ORDER_WEDGE: least = 6; return true;
    case VTK_QUADRATIC_POLYGON: least = 6; return true;
    case VTK_LAGRANGE_HEXAHEDRON: case VTK_BEZIER_HEXAHEDRON: case VTK_HIGHER_ORDER_HEXAHEDRON:
      least = 8; return true;
    case VTK_PARAMETRIC_CURVE: case VTK_PARAMETRIC_SURFACE: case VTK_PARAMETRIC_TRI_SURFACE:
    case VTK_PARAMETRIC_QUAD_SURFACE: case VTK_PARAMETRIC_TETRA_REGION: case VTK_PARAMETRIC_HEX_REGION:
      return true;
    default: return false;
  }
}

// "" if every cell of `cells` has at least `least` points (VTK's cell classes
// index a cell's first points without looking at its size).
std::string CheckLeast(vtkCellArray* cells, vtkIdType least, const char* what, const char* one)
{
  const vtkIdType count = cells ? cells->GetNumberOfCells() : 0;
  for (vtkIdType c = 0; c < count; ++c)
  {
    const vtkIdType size = cells->GetCellSize(c);
    if (size < least)
    {
      return std::string(what) + ": cell " + std::to_string(c) + " has " + std::to_string(size) + " point" +
        (size == 1 ? "" : "s") + "; " + one + " needs at least " + std::to_string(least);
    }
  }
  return std::string();
}

std::string CheckCount(vtkIdType count, const int extent[6], const char* kind)
{
  double expected = 1;
  for (int a = 0; a < 3; ++a)
  {
    expected *= std::max(0.0, double(extent[2 * a + 1]) - double(extent[2 * a]) + 1.0);
  }
  if (double(count) != expected)
  {
    return std::string(kind) + " extent [" + std::to_string(extent[0]) + ", " + std::to_string(extent[1]) + ", " +
      std::to_string(extent[2]) + ", " + std::to_string(extent[3]) + ", " + std::to_string(extent[4]) + ", " +
      std::to_string(extent[5]) + "] means " + Num(expected) + " points, but it has " + std::to_string(count);
  }
  return std::string();
}

double PositiveEnv(const char* name, double fallback)
{
  if (const char* env = std::getenv(name))
  {
    double v = 0;
    if (vtkPlumeInputValidation::ParseFinite(env, v) && v > 0)
    {
      return v;
    }
  }
  return fallback;
}

// Three significant digits below 100 MB (1.19 MB), whole megabytes up to
// 10^7 MB (28160 MB), then three significant digits in scientific notation
// (3.81e+09 MB): a header that lies about its size must not print 12 digits.
std::string Megabytes(double bytes)
{
  const double mb = bytes / (1 << 20);
  std::ostringstream s;
  if (std::isfinite(mb) && mb >= 100 && mb < 1e7)
  {
    s << std::fixed;
    s.precision(0);
  }
  else
  {
    s.precision(3);
  }
  s << mb << " MB";
  return s.str();
}
}

//------------------------------------------------------------------------------
std::string vtkPlumeInputValidation::CheckRegularFile(const std::string& path)
{
  if (path.find('\0') != std::string::npos)
  {
    return "the path '" + std::string(path.c_str()) + "\\u0000...' holds a NUL character";
  }
  if (path.empty())
  {
    return "the path is empty";
  }
  struct stat st;
  if (stat(path.c_str(), &st) != 0)
  {
    return "file not found: " + path;
  }
  if (S_ISDIR(st.st_mode))
  {
    return "'" + path + "' is a directory, not a file";
  }
  if (S_ISFIFO(st.st_mode))
  {
    return "'" + path + "' is a FIFO (named pipe), not a regular file; reading it could block forever";
  }
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode))
  {
    return "'" + path + "' is a device, not a regular file";
  }
  if (S_ISSOCK(st.st_mode))
  {
    return "'" + path + "' is a socket, not a regular file";
  }
  if (!S_ISREG(st.st_mode))
  {
    return "'" + path + "' is not a regular file";
  }
  if (access(path.c_str(), R_OK) != 0)
  {
    return "'" + path + "' is not readable (permission denied)";
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string vtkPlumeInputValidation::CheckCellArray(
  vtkCellArray* cells, vtkIdType numberOfPoints, const char* what)
{
  if (!cells)
  {
    return std::string();
  }
  if (cells->IsStorage64Bit())
  {
    auto* o = cells->GetOffsetsArray64();
    auto* c = cells->GetConnectivityArray64();
    return CheckStorage(o->GetPointer(0), o->GetNumberOfValues(), c->GetPointer(0), c->GetNumberOfValues(),
      numberOfPoints, what);
  }
  auto* o = cells->GetOffsetsArray32();
  auto* c = cells->GetConnectivityArray32();
  return CheckStorage(
    o->GetPointer(0), o->GetNumberOfValues(), c->GetPointer(0), c->GetNumberOfValues(), numberOfPoints, what);
}

//------------------------------------------------------------------------------
std::string vtkPlumeInputValidation::CheckCells(vtkDataSet* data, bool polyDataSizes)
{
  if (!data)
  {
    return std::string();
  }
  const vtkIdType n = data->GetNumberOfPoints();
  if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    const std::pair<vtkCellArray*, const char*> arrays[] = { { poly->GetVerts(), "vertices" },
      { poly->GetLines(), "lines" }, { poly->GetPolys(), "polygons" }, { poly->GetStrips(), "triangle strips" } };
    // without polyDataSizes only empty cells (no consumer wants one; the splatter
    // skips a single-vertex line by design)
    const vtkIdType line = polyDataSizes ? 2 : 1, face = polyDataSizes ? 3 : 1;
    const std::pair<vtkIdType, const char*> least[] = { { 1, "a vertex" }, { line, "a line" }, { face, "a polygon" },
      { face, "a triangle strip" } };
    for (int i = 0; i < 4; ++i)
    {
      std::string error = CheckCellArray(arrays[i].first, n, arrays[i].second);
      if (error.empty())
      {
        error = CheckLeast(arrays[i].first, least[i].first, arrays[i].second, least[i].second);
      }
      if (!error.empty())
      {
        return error;
      }
    }
    return std::string();
  }
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data))
  {
    vtkCellArray* cells = grid->GetCells();
    std::string error = CheckCellArray(cells, n, "cells");
    if (!error.empty())
    {
      return error;
    }
    vtkUnsignedCharArray* types = grid->GetCellTypesArray();
    const vtkIdType cellCount = cells ? cells->GetNumberOfCells() : 0;
    const vtkIdType typeCount = types ? types->GetNumberOfValues() : 0;
    if (cellCount != typeCount)
    {
      return "cells: " + std::to_string(cellCount) + " cells but " + std::to_string(typeCount) + " cell types";
    }
    // each cell's point count against its type: VTK's cell classes read as
    // many points as the type has (a 4-point "hexahedron" is a SEGV in the
    // surface and probe filters)
    for (vtkIdType c = 0; c < cellCount; ++c)
    {
      const int type = types->GetValue(c);
      const vtkIdType size = cells->GetCellSize(c);
      vtkIdType exact = 0, least = 0;
      if (!CellSize(type, exact, least))
      {
        return "cells: cell " + std::to_string(c) + " has type " + std::to_string(type) +
          ", which is no VTK cell type";
      }
      const std::string name = vtkCellTypes::GetClassNameFromTypeId(type);
      if (exact > 0 ? size != exact : size < least)
      {
        return "cells: cell " + std::to_string(c) + " (" + name + ", type " + std::to_string(type) + ") has " +
          std::to_string(size) + " point" + (size == 1 ? "" : "s") + "; it needs " +
          (exact > 0 ? std::to_string(exact) : "at least " + std::to_string(least));
      }
      if (type == VTK_POLYHEDRON)
      {
        // its face stream: [faces, (points, ids...) per face], inside the faces array
        vtkIdTypeArray* faces = grid->GetFaces();
        vtkIdTypeArray* locations = grid->GetFaceLocations();
        const vtkIdType total = faces ? faces->GetNumberOfValues() : 0;
        vtkIdType at = locations && c < locations->GetNumberOfValues() ? locations->GetValue(c) : -1;
        const std::string polyhedron = "cells: cell " + std::to_string(c) + " is a polyhedron (type 42) but ";
        if (at < 0 || at >= total)
        {
          return polyhedron + "the grid has no faces for it";
        }
        const vtkIdType faceCount = faces->GetValue(at++);
        for (vtkIdType f = 0; f < faceCount; ++f)
        {
          const vtkIdType count = at < total ? faces->GetValue(at++) : -1;
          if (count < 0 || count > total - at)
          {
            return polyhedron + "its face " + std::to_string(f) + " lies beyond the grid's " +
              std::to_string(total) + " face values";
          }
          for (vtkIdType k = 0; k < count; ++k, ++at)
          {
            const vtkIdType id = faces->GetValue(at);
            if (id < 0 || id >= n)
            {
              return polyhedron + "its face " + std::to_string(f) + " references point id " + std::to_string(id) +
                ", but the dataset has " + std::to_string(n) + " points";
            }
          }
        }
        if (faceCount < 4)
        {
          return polyhedron + "it has " + std::to_string(faceCount) + " faces; it needs at least 4";
        }
      }
    }
    return std::string();
  }
  int extent[6];
  if (auto* image = vtkImageData::SafeDownCast(data))
  {
    image->GetExtent(extent);
    return CheckCount(n, extent, "image");
  }
  if (auto* sg = vtkStructuredGrid::SafeDownCast(data))
  {
    sg->GetExtent(extent);
    return CheckCount(n, extent, "structured grid");
  }
  if (auto* rg = vtkRectilinearGrid::SafeDownCast(data))
  {
    rg->GetExtent(extent);
    return CheckCount(n, extent, "rectilinear grid");
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string vtkPlumeInputValidation::CheckArrays(vtkDataSet* data)
{
  if (!data)
  {
    return std::string();
  }
  const vtkIdType counts[2] = { data->GetNumberOfPoints(), data->GetNumberOfCells() };
  vtkDataSetAttributes* attributes[2] = { data->GetPointData(), data->GetCellData() };
  const char* kinds[2] = { "point", "cell" };
  for (int k = 0; k < 2; ++k)
  {
    for (int i = 0; attributes[k] && i < attributes[k]->GetNumberOfArrays(); ++i)
    {
      vtkAbstractArray* array = attributes[k]->GetAbstractArray(i);
      if (array && array->GetNumberOfTuples() != counts[k])
      {
        return std::string(kinds[k]) + " array '" + (array->GetName() ? array->GetName() : "(unnamed)") +
          "' has " + std::to_string(array->GetNumberOfTuples()) + " tuples, but the dataset has " +
          std::to_string(counts[k]) + " " + kinds[k] + "s";
      }
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string vtkPlumeInputValidation::CheckFinitePoints(vtkDataSet* data)
{
  if (auto* ps = vtkPointSet::SafeDownCast(data))
  {
    if (vtkPoints* points = ps->GetPoints())
    {
      vtkDataArray* coords = points->GetData();
      const vtkIdType n = coords->GetNumberOfTuples();
      for (vtkIdType i = 0; i < n; ++i)
      {
        for (int c = 0; c < 3; ++c)
        {
          const double v = coords->GetComponent(i, c);
          if (!std::isfinite(v))
          {
            return "point " + std::to_string(i) + " has a non-finite coordinate (" + Num(v) + ")";
          }
        }
      }
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string vtkPlumeInputValidation::CheckDataObject(vtkDataObject* data, bool polyDataSizes)
{
  if (auto* ds = vtkDataSet::SafeDownCast(data))
  {
    std::string error = CheckCells(ds, polyDataSizes);
    return error.empty() ? CheckArrays(ds) : error;
  }
  if (auto* cds = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(cds->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      std::string error = CheckDataObject(it->GetCurrentDataObject(), polyDataSizes);
      if (!error.empty())
      {
        return "block " + std::to_string(it->GetCurrentFlatIndex()) + ": " + error;
      }
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
bool vtkPlumeInputValidation::FiniteRange(
  vtkDataArray* array, int component, double range[2], vtkIdType* nonFinite, const unsigned char* mask)
{
  range[0] = std::numeric_limits<double>::infinity();
  range[1] = -std::numeric_limits<double>::infinity();
  vtkIdType bad = 0;
  if (array)
  {
    const int nc = array->GetNumberOfComponents();
    const vtkIdType n = array->GetNumberOfTuples();
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (mask && !mask[i])
      {
        continue;
      }
      double v;
      if (component < 0)
      {
        double s = 0;
        for (int c = 0; c < nc; ++c)
        {
          const double x = array->GetComponent(i, c);
          s += x * x;
        }
        v = std::sqrt(s);
        // the norm of finite components can overflow: that tuple is not finite either
      }
      else
      {
        v = array->GetComponent(i, component);
      }
      if (!std::isfinite(v))
      {
        ++bad;
        continue;
      }
      range[0] = std::min(range[0], v);
      range[1] = std::max(range[1], v);
    }
  }
  if (nonFinite)
  {
    *nonFinite = bad;
  }
  if (!(range[0] <= range[1]))
  {
    range[0] = range[1] = 0;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkPlumeInputValidation::ParseInteger(
  const std::string& text, long long min, long long max, long long& value)
{
  if (text.empty() || text.find('\0') != std::string::npos)
  {
    return false;
  }
  size_t i = 0;
  const bool negative = text[0] == '-';
  if (negative)
  {
    ++i;
  }
  if (i >= text.size())
  {
    return false;
  }
  unsigned long long magnitude = 0;
  const unsigned long long limit = negative
    ? static_cast<unsigned long long>(std::numeric_limits<long long>::max()) + 1ULL
    : static_cast<unsigned long long>(std::numeric_limits<long long>::max());
  for (; i < text.size(); ++i)
  {
    const char ch = text[i];
    if (ch < '0' || ch > '9')
    {
      return false;
    }
    const unsigned digit = static_cast<unsigned>(ch - '0');
    if (magnitude > (limit - digit) / 10)
    {
      return false; // overflow
    }
    magnitude = magnitude * 10 + digit;
  }
  long long v;
  if (negative)
  {
    v = magnitude == limit ? std::numeric_limits<long long>::min() : -static_cast<long long>(magnitude);
  }
  else
  {
    v = static_cast<long long>(magnitude);
  }
  if (v < min || v > max)
  {
    return false;
  }
  value = v;
  return true;
}

//------------------------------------------------------------------------------
bool vtkPlumeInputValidation::ParseFinite(const std::string& text, double& value)
{
  if (text.empty() || text.find('\0') != std::string::npos || std::isspace(static_cast<unsigned char>(text[0])))
  {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
  {
    return false;
  }
  value = v;
  return true;
}

//------------------------------------------------------------------------------
bool vtkPlumeInputValidation::ParseSize(const std::string& text, int maxSide, int& width, int& height)
{
  const size_t x = text.find_first_of("xX");
  if (x == std::string::npos)
  {
    return false;
  }
  long long w = 0, h = 0;
  if (!ParseInteger(text.substr(0, x), 1, maxSide, w) || !ParseInteger(text.substr(x + 1), 1, maxSide, h))
  {
    return false;
  }
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return true;
}

//------------------------------------------------------------------------------
std::string vtkPlumeInputValidation::CheckFinite(double value, const std::string& what)
{
  return std::isfinite(value) ? std::string() : what + " is " + Num(value) + " (not a finite number)";
}

//------------------------------------------------------------------------------
double vtkPlumeInputValidation::MemoryBudgetBytes()
{
  const double mb = PositiveEnv("PLUME_MEMORY_BUDGET_MB", 0);
  if (mb > 0)
  {
    return mb * (1 << 20);
  }
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? 0.5 * double(pages) * double(pageSize) : 4.0 * (1 << 30);
}

//------------------------------------------------------------------------------
std::string vtkPlumeInputValidation::CheckMemory(double bytes, const std::string& what)
{
  const double budget = MemoryBudgetBytes();
  if (!(bytes <= budget)) // NaN too
  {
    return what + " needs about " + Megabytes(bytes) + ", over the memory budget of " + Megabytes(budget) +
      " (PLUME_MEMORY_BUDGET_MB)";
  }
  return std::string();
}

//------------------------------------------------------------------------------
double vtkPlumeInputValidation::WorkBudget()
{
  return PositiveEnv("PLUME_WORK_BUDGET", 1e10);
}

//------------------------------------------------------------------------------
std::string vtkPlumeInputValidation::CheckWork(double operations, const std::string& what)
{
  const double budget = WorkBudget();
  if (!(operations <= budget))
  {
    std::ostringstream s;
    s.precision(3);
    s << what << " needs about " << operations << " operations, over the work budget of " << budget
      << " (PLUME_WORK_BUDGET)";
    return s.str();
  }
  return std::string();
}
