// Helpers for the Plume::Splatting tests: random splat inputs and the error
// of a splatter output against the double-precision reference (PLUME_CHECK
// comes from PlumeTestSupport).
#ifndef plumeSplatTestUtil_h
#define plumeSplatTestUtil_h

#include "plumeTestSupport.h"
#include "vtkPlumeGaussianSplatter.h"
#include "vtkPlumeSplatReference.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <iostream>

namespace splattest
{
/** n points uniform in [lo, hi]³ with a random vector array "v", a scalar "s" and radii "sigma" in [s0, s1]. */
inline vtkSmartPointer<vtkPolyData> RandomPoints(int n, double lo, double hi, double s0, double s1, int seed = 7)
{
  vtkNew<vtkMinimalStandardRandomSequence> rng;
  rng->SetSeed(seed);
  auto next = [&](double a, double b) {
    rng->Next();
    return rng->GetRangeValue(a, b);
  };
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkFloatArray> v, s, sigma;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  s->SetName("s");
  sigma->SetName("sigma");
  for (int i = 0; i < n; ++i)
  {
    // One draw per statement: the evaluation order of function arguments is
    // unspecified (gcc draws z first, clang x), so next() inside one argument
    // list gave each compiler different points.
    double p[3], w[3];
    for (double& x : p)
    {
      x = next(lo, hi);
    }
    for (double& x : w)
    {
      x = next(-1, 1);
    }
    pts->InsertNextPoint(p);
    v->InsertNextTuple(w);
    s->InsertNextValue(static_cast<float>(next(0.2, 2)));
    sigma->InsertNextValue(static_cast<float>(next(s0, s1)));
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(pts);
  poly->GetPointData()->SetVectors(v);
  poly->GetPointData()->SetScalars(s);
  poly->GetPointData()->AddArray(sigma);
  return poly;
}

struct Error
{
  double Max = 0;  // max |ours - reference| over voxels and components
  double RMS = 0;
  double Peak = 0; // max |reference|
  bool Finite = true;
};

/** Error of a splatter's current output against its reference (computed here). */
inline Error Against(vtkPlumeGaussianSplatter* splatter, vtkImageData* reference)
{
  Error e;
  vtkDataArray* ours = splatter->GetOutput()->GetPointData()->GetArray(0);
  vtkDataArray* ref = reference->GetPointData()->GetArray(0);
  if (!ours || !ref || ours->GetNumberOfValues() != ref->GetNumberOfValues())
  {
    e.Finite = false;
    e.Max = e.RMS = HUGE_VAL;
    return e;
  }
  double sum2 = 0;
  const vtkIdType n = ours->GetNumberOfValues();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double a = ours->GetVariantValue(i).ToDouble();
    const double b = ref->GetVariantValue(i).ToDouble();
    e.Finite = e.Finite && std::isfinite(a);
    e.Max = std::max(e.Max, std::fabs(a - b));
    e.Peak = std::max(e.Peak, std::fabs(b));
    sum2 += (a - b) * (a - b);
  }
  e.RMS = n ? std::sqrt(sum2 / n) : 0;
  return e;
}

/** Max |a - b| between two float outputs (same grid). */
inline double Difference(vtkImageData* a, vtkImageData* b)
{
  auto* x = vtkFloatArray::SafeDownCast(a->GetPointData()->GetArray(0));
  auto* y = vtkFloatArray::SafeDownCast(b->GetPointData()->GetArray(0));
  if (!x || !y || x->GetNumberOfValues() != y->GetNumberOfValues())
  {
    return HUGE_VAL;
  }
  double m = 0;
  for (vtkIdType i = 0; i < x->GetNumberOfValues(); ++i)
  {
    m = std::max(m, std::fabs(double(x->GetValue(i)) - y->GetValue(i)));
  }
  return m;
}

/** Sum of an output array's component c over all voxels. */
inline double Total(vtkImageData* image, int c = 0)
{
  vtkDataArray* a = image->GetPointData()->GetArray(0);
  double t = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    t += a->GetComponent(i, c);
  }
  return t;
}
}

#endif
