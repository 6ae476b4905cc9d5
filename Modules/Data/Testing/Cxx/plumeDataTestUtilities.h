// Small helpers shared by the Plume::Data tests (header only).
#ifndef plumeDataTestUtilities_h
#define plumeDataTestUtilities_h

#include "vtkPlumeDatasetReader.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

namespace plumetest
{
/** The shared data folder: $PLUME_DATA_DIR, else the configured PLUME_DATA_DIR. */
inline std::string DataDir()
{
  const char* env = std::getenv("PLUME_DATA_DIR");
  return (env && *env) ? std::string(env) : std::string(PLUME_DATA_DIR);
}

inline std::string Data(const std::string& relative)
{
  return DataDir() + "/" + relative;
}

/** Counts failures; every check prints what it expected. */
struct Checker
{
  int Failures = 0;
  std::string Context;

  bool Fail(const std::string& what)
  {
    std::cerr << "FAIL [" << this->Context << "] " << what << "\n";
    ++this->Failures;
    return false;
  }

  bool True(bool condition, const std::string& what)
  {
    return condition ? true : this->Fail(what);
  }

  template <typename T>
  bool Equal(const T& actual, const T& expected, const std::string& what)
  {
    if (actual == expected)
    {
      return true;
    }
    std::ostringstream s;
    s << what << ": got " << actual << ", expected " << expected;
    return this->Fail(s.str());
  }

  /** |actual - expected| <= absTol + relTol * |expected|. */
  bool Near(double actual, double expected, double relTol, double absTol, const std::string& what)
  {
    if (std::fabs(actual - expected) <= absTol + relTol * std::fabs(expected))
    {
      return true;
    }
    std::ostringstream s;
    s.precision(10);
    s << what << ": got " << actual << ", expected " << expected << " (rel " << relTol
      << ", abs " << absTol << ")";
    return this->Fail(s.str());
  }

  /** Bounds within `tol` of the given ones (README values are rounded to ~3 digits). */
  bool Bounds(vtkDataSet* ds, const double expected[6], double tol)
  {
    if (!ds)
    {
      return this->Fail("no dataset for bounds");
    }
    double b[6];
    ds->GetBounds(b);
    bool ok = true;
    for (int i = 0; i < 6; ++i)
    {
      ok = this->Near(b[i], expected[i], 0, tol, "bounds[" + std::to_string(i) + "]") && ok;
    }
    return ok;
  }

  /**
   * Array `name` in point (or cell) data with `components` components whose range (the
   * magnitude for vectors) is [lo, hi] within rel/abs tolerance of the README's rounded values.
   */
  bool Array(vtkDataSet* ds, const char* name, int components, double lo, double hi,
    bool cellData = false, double relTol = 5e-3, double absTol = 1e-6)
  {
    if (!ds)
    {
      return this->Fail(std::string("no dataset for array ") + name);
    }
    vtkDataArray* array =
      cellData ? ds->GetCellData()->GetArray(name) : ds->GetPointData()->GetArray(name);
    const std::string where = std::string(cellData ? "cell" : "point") + " array " + name;
    if (!array)
    {
      return this->Fail(where + " missing");
    }
    if (!this->Equal(array->GetNumberOfComponents(), components, where + " components"))
    {
      return false;
    }
    double range[2];
    array->GetRange(range, components == 1 ? 0 : -1);
    bool ok = this->Near(range[0], lo, relTol, absTol, where + " min");
    ok = this->Near(range[1], hi, relTol, absTol, where + " max") && ok;
    return ok;
  }

  bool HasArray(vtkDataSet* ds, const char* name, bool cellData = false)
  {
    const bool has = ds &&
      (cellData ? ds->GetCellData()->GetArray(name) : ds->GetPointData()->GetArray(name));
    return this->True(has, std::string(cellData ? "cell" : "point") + " array " + name + " missing");
  }
};

/** A configured reader for a data-folder file; Update() not called. */
inline vtkSmartPointer<vtkPlumeDatasetReader> Reader(const std::string& relative)
{
  auto reader = vtkSmartPointer<vtkPlumeDatasetReader>::New();
  reader->SetFileName(Data(relative).c_str());
  return reader;
}
}

#endif
