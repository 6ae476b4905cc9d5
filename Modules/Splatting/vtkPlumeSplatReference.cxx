#include "vtkPlumeSplatReference.h"

#include "vtkPlumeGaussianSplatter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace
{
struct RefSplat
{
  double c[3];
  double v[3];
  double r;
};

bool AllFinite(const double* a, int n)
{
  for (int i = 0; i < n; ++i)
  {
    if (!std::isfinite(a[i]))
    {
      return false;
    }
  }
  return true;
}

// Φ(b) − Φ(a) for the unit normal, evaluated on the side where erfc does not cancel.
double Mass(double a, double b)
{
  const double s = 1.0 / std::sqrt(2.0);
  if (b <= 0)
  {
    return 0.5 * std::erfc(-b * s) - 0.5 * std::erfc(-a * s);
  }
  if (a >= 0)
  {
    return 0.5 * std::erfc(a * s) - 0.5 * std::erfc(b * s);
  }
  return 1.0 - 0.5 * std::erfc(-a * s) - 0.5 * std::erfc(b * s);
}
}

class vtkPlumeSplatReference::Internals
{
public:
  std::vector<RefSplat> Splats;
  int Mode = 0;
  bool Integrate = true;
  double Origin[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
  int Dims[3] = { 1, 1, 1 };
  std::string Name = "velocity";
};

vtkStandardNewMacro(vtkPlumeSplatReference);

vtkPlumeSplatReference::vtkPlumeSplatReference()
  : Impl(new Internals)
{
}

vtkPlumeSplatReference::~vtkPlumeSplatReference() = default;

size_t vtkPlumeSplatReference::GetNumberOfSplats() const
{
  return this->Impl->Splats.size();
}

void vtkPlumeSplatReference::Configure(vtkPlumeGaussianSplatter* splatter)
{
  Internals& d = *this->Impl;
  d.Splats.clear();
  d.Mode = splatter->GetMode();
  d.Integrate = splatter->GetIntegrateOverVoxel();
  vtkImageData* out = splatter->GetOutput();
  out->GetOrigin(d.Origin);
  out->GetSpacing(d.Spacing);
  out->GetDimensions(d.Dims);
  d.Name = d.Mode == vtkPlumeGaussianSplatter::VECTOR_SUM
    ? "velocity"
    : d.Mode == vtkPlumeGaussianSplatter::SCALAR_SUM ? "density" : "distance";
  const std::string radiusName = splatter->GetRadiusArrayName();
  const double radius = splatter->GetRadius();
  auto keep = [&](const double c[3], const double v[3], double r) {
    if (AllFinite(c, 3) && AllFinite(v, 3) && std::isfinite(r) && r > 0)
    {
      RefSplat s = { { c[0], c[1], c[2] }, { v[0], v[1], v[2] }, r };
      d.Splats.push_back(s);
    }
  };

  if (auto* points = vtkPointSet::SafeDownCast(splatter->GetInputDataObject(0, 0)))
  {
    vtkPointData* pd = points->GetPointData();
    vtkDataArray* values;
    if (d.Mode == vtkPlumeGaussianSplatter::VECTOR_SUM)
    {
      const std::string name = splatter->GetVectorArrayName();
      values = name.empty() ? pd->GetVectors() : pd->GetArray(name.c_str());
    }
    else
    {
      const std::string name = splatter->GetScalarArrayName();
      values = name.empty() ? pd->GetScalars() : pd->GetArray(name.c_str());
    }
    vtkDataArray* radii = radiusName.empty() ? nullptr : pd->GetArray(radiusName.c_str());
    // points owned by another piece (ghosts) are not splatted here
    vtkDataArray* ghostType = pd->GetArray(vtkDataSetAttributes::GhostArrayName());
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      if (ghostType && i < ghostType->GetNumberOfTuples() &&
        (static_cast<int>(ghostType->GetComponent(i, 0)) & vtkDataSetAttributes::DUPLICATEPOINT))
      {
        continue;
      }
      double c[3];
      points->GetPoint(i, c);
      double v[3] = { 1, 0, 0 };
      if (values && d.Mode == vtkPlumeGaussianSplatter::VECTOR_SUM)
      {
        for (int k = 0; k < 3; ++k)
        {
          v[k] = values->GetComponent(i, k);
        }
      }
      else if (values)
      {
        v[0] = values->GetComponent(i, 0);
      }
      keep(c, v, radii ? radii->GetComponent(i, 0) : radius);
    }
  }

  if (auto* lines = vtkPolyData::SafeDownCast(splatter->GetInputDataObject(1, 0)))
  {
    vtkDataArray* radii = radiusName.empty() ? nullptr : lines->GetPointData()->GetArray(radiusName.c_str());
    const double factor = splatter->GetLineScaleFactor();
    vtkCellArray* cells = lines->GetLines();
    // pieces of cut lines: ghost cells and ghost vertices belong to another
    // piece; an open line's end where another open line starts is that one's
    vtkDataArray* cellGhost = lines->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName());
    vtkDataArray* pointGhost = lines->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName());
    auto flagged = [](vtkDataArray* ghost, vtkIdType id, int bits) {
      return ghost && id < ghost->GetNumberOfTuples() && (static_cast<int>(ghost->GetComponent(id, 0)) & bits);
    };
    auto cellSkipped = [&](vtkIdType cell) {
      return flagged(cellGhost, lines->GetNumberOfVerts() + cell, vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL);
    };
    std::vector<std::array<double, 3>> openStarts;
    for (vtkIdType cell = 0; cells && cell < cells->GetNumberOfCells(); ++cell)
    {
      vtkIdType n;
      const vtkIdType* ids;
      cells->GetCellAtId(cell, n, ids);
      if (n < 2 || cellSkipped(cell) || flagged(pointGhost, ids[0], vtkDataSetAttributes::DUPLICATEPOINT))
      {
        continue;
      }
      std::array<double, 3> a, b;
      lines->GetPoint(ids[0], a.data());
      lines->GetPoint(ids[n - 1], b.data());
      if (ids[0] != ids[n - 1] && a != b)
      {
        openStarts.push_back(a);
      }
    }
    for (vtkIdType cell = 0; cells && cell < cells->GetNumberOfCells(); ++cell)
    {
      vtkIdType n;
      const vtkIdType* ids;
      cells->GetCellAtId(cell, n, ids);
      if (n == 0 || cellSkipped(cell))
      {
        continue;
      }
      std::vector<std::array<double, 3>> p(n);
      for (vtkIdType i = 0; i < n; ++i)
      {
        lines->GetPoint(ids[i], p[i].data());
      }
      bool closed = n > 1 && (ids[0] == ids[n - 1] || p[0] == p[n - 1]);
      const vtkIdType m = closed ? n - 1 : n;
      bool continues = false;
      for (const auto& start : openStarts)
      {
        continues = continues || (!closed && n > 1 && start == p[n - 1]);
      }
      for (vtkIdType i = 0; i < m; ++i)
      {
        if (flagged(pointGhost, ids[i], vtkDataSetAttributes::DUPLICATEPOINT) || (continues && i == m - 1))
        {
          continue;
        }
        // velocity: to the next vertex (wrapping on a loop), backward at an open end
        double vel[3] = { 0, 0, 0 };
        const std::array<double, 3>* from = nullptr;
        const std::array<double, 3>* to = nullptr;
        if (i + 1 < m)
        {
          from = &p[i];
          to = &p[i + 1];
        }
        else if (closed)
        {
          from = &p[i];
          to = &p[0];
        }
        else if (i > 0)
        {
          from = &p[i - 1];
          to = &p[i];
        }
        if (from)
        {
          for (int k = 0; k < 3; ++k)
          {
            vel[k] = (*to)[k] - (*from)[k];
          }
        }
        double v[3] = { 1, 0, 0 };
        if (d.Mode == vtkPlumeGaussianSplatter::VECTOR_SUM)
        {
          for (int k = 0; k < 3; ++k)
          {
            v[k] = factor * vel[k];
          }
        }
        else if (d.Mode == vtkPlumeGaussianSplatter::SCALAR_SUM)
        {
          v[0] = std::fabs(factor) * std::sqrt(vel[0] * vel[0] + vel[1] * vel[1] + vel[2] * vel[2]);
        }
        keep(p[i].data(), v, radii ? radii->GetComponent(ids[i], 0) : radius);
      }
    }
  }
}

void vtkPlumeSplatReference::Evaluate(int i, int j, int k, double value[3]) const
{
  const Internals& d = *this->Impl;
  const int idx[3] = { i, j, k };
  double x[3];
  for (int a = 0; a < 3; ++a)
  {
    x[a] = d.Origin[a] + idx[a] * d.Spacing[a];
  }
  value[0] = value[1] = value[2] = 0;
  const double pi = 3.14159265358979323846;
  for (const RefSplat& s : d.Splats)
  {
    if (d.Mode == vtkPlumeGaussianSplatter::DISTANCE_MAX)
    {
      const double r = std::sqrt((x[0] - s.c[0]) * (x[0] - s.c[0]) + (x[1] - s.c[1]) * (x[1] - s.c[1]) +
        (x[2] - s.c[2]) * (x[2] - s.c[2]));
      value[0] = std::max(value[0], s.v[0] * std::max(0.0, 1.0 - r / s.r));
      continue;
    }
    double g = 1;
    if (d.Integrate)
    {
      for (int a = 0; a < 3; ++a)
      {
        if (d.Dims[a] == 1)
        {
          // a one-point axis has no cell: the 1D density at the point
          const double u = (x[a] - s.c[a]) / s.r;
          g *= std::exp(-0.5 * u * u) / (std::sqrt(2 * pi) * s.r);
        }
        else
        {
          const double lo = (x[a] - 0.5 * d.Spacing[a] - s.c[a]) / s.r;
          const double hi = (x[a] + 0.5 * d.Spacing[a] - s.c[a]) / s.r;
          g *= Mass(lo, hi) / d.Spacing[a];
        }
      }
    }
    else
    {
      const double r2 = (x[0] - s.c[0]) * (x[0] - s.c[0]) + (x[1] - s.c[1]) * (x[1] - s.c[1]) +
        (x[2] - s.c[2]) * (x[2] - s.c[2]);
      g = std::exp(-0.5 * r2 / (s.r * s.r)) / (std::pow(2 * pi, 1.5) * s.r * s.r * s.r);
    }
    for (int c = 0; c < 3; ++c)
    {
      value[c] += s.v[c] * g;
    }
  }
}

vtkSmartPointer<vtkImageData> vtkPlumeSplatReference::Compute() const
{
  const Internals& d = *this->Impl;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(0, d.Dims[0] - 1, 0, d.Dims[1] - 1, 0, d.Dims[2] - 1);
  image->SetOrigin(d.Origin);
  image->SetSpacing(d.Spacing);
  const int comps = d.Mode == vtkPlumeGaussianSplatter::VECTOR_SUM ? 3 : 1;
  vtkNew<vtkDoubleArray> field;
  field->SetName(d.Name.c_str());
  field->SetNumberOfComponents(comps);
  field->SetNumberOfTuples(image->GetNumberOfPoints());
  double* out = field->GetPointer(0);
  // each z slice written by one task: the values do not depend on threads
  vtkSMPTools::For(0, d.Dims[2], [&](vtkIdType k0, vtkIdType k1) {
    for (vtkIdType k = k0; k < k1; ++k)
    {
      for (int j = 0; j < d.Dims[1]; ++j)
      {
        for (int i = 0; i < d.Dims[0]; ++i)
        {
          double v[3];
          this->Evaluate(i, j, static_cast<int>(k), v);
          const size_t id = (size_t(k) * d.Dims[1] + j) * d.Dims[0] + i;
          for (int c = 0; c < comps; ++c)
          {
            out[comps * id + c] = v[c];
          }
        }
      }
    }
  });
  if (comps == 3)
  {
    image->GetPointData()->SetVectors(field);
  }
  else
  {
    image->GetPointData()->SetScalars(field);
  }
  return image;
}
