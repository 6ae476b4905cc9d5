#include "vtkPlumeImageInput.h"

#include "vtkAlgorithm.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPlumeInputValidation.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace
{
// The point extent of the cells not marked as ghosts.
void NonGhostExtent(vtkImageData* image, int extent[6])
{
  image->GetExtent(extent);
  auto* ghosts = vtkUnsignedCharArray::SafeDownCast(
    image->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  if (!ghosts)
  {
    return;
  }
  int pointExtent[6];
  std::copy(extent, extent + 6, pointExtent);
  int lo[3] = { VTK_INT_MAX, VTK_INT_MAX, VTK_INT_MAX };
  int hi[3] = { VTK_INT_MIN, VTK_INT_MIN, VTK_INT_MIN };
  const vtkIdType n = ghosts->GetNumberOfTuples();
  for (vtkIdType c = 0; c < n; ++c)
  {
    if (ghosts->GetValue(c) & vtkDataSetAttributes::DUPLICATECELL)
    {
      continue;
    }
    int ijk[3];
    vtkStructuredData::ComputeCellStructuredCoordsForExtent(c, pointExtent, ijk);
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], ijk[a]);
      hi[a] = std::max(hi[a], ijk[a]);
    }
  }
  if (lo[0] > hi[0])
  {
    return; // all ghosts: keep it whole
  }
  for (int a = 0; a < 3; ++a)
  {
    extent[2 * a] = lo[a];
    extent[2 * a + 1] = std::min(hi[a] + 1, pointExtent[2 * a + 1]);
  }
}

vtkSmartPointer<vtkImageData> Copy(vtkImageData* image)
{
  auto copy = vtkSmartPointer<vtkImageData>::New();
  copy->ShallowCopy(image);
  if (image->HasAnyGhostCells())
  {
    int extent[6];
    NonGhostExtent(copy, extent);
    copy->Crop(extent);
  }
  return copy;
}

// The trilinear value of `name` at x in the first of `pieces` (finest first)
// whose point bounds contain x.
bool Interpolate(const std::vector<vtkSmartPointer<vtkImageData>>& pieces, const char* name, const double x[3],
  double* value)
{
  for (const auto& p : pieces)
  {
    const double* o = p->GetOrigin();
    const double* h = p->GetSpacing();
    const int* e = p->GetExtent();
    int i0[3];
    double t[3];
    bool inside = true;
    for (int a = 0; a < 3 && inside; ++a)
    {
      const double f = (x[a] - o[a]) / h[a]; // structured coordinate
      const double tol = 1e-6;
      inside = f >= e[2 * a] - tol && f <= e[2 * a + 1] + tol;
      if (e[2 * a] == e[2 * a + 1])
      {
        i0[a] = e[2 * a];
        t[a] = 0;
        continue;
      }
      i0[a] = std::min(std::max(static_cast<int>(std::floor(f)), e[2 * a]), e[2 * a + 1] - 1);
      t[a] = std::min(std::max(f - i0[a], 0.0), 1.0);
    }
    if (!inside)
    {
      continue;
    }
    vtkDataArray* array = p->GetPointData()->GetArray(name);
    const int comps = array->GetNumberOfComponents();
    std::fill(value, value + comps, 0.0);
    for (int corner = 0; corner < 8; ++corner)
    {
      int ijk[3];
      double w = 1;
      for (int a = 0; a < 3; ++a)
      {
        const int up = (corner >> a) & 1;
        ijk[a] = std::min(i0[a] + up, e[2 * a + 1]);
        w *= up ? t[a] : 1 - t[a];
      }
      if (w == 0)
      {
        continue;
      }
      const vtkIdType id = p->ComputePointId(ijk);
      for (int c = 0; c < comps; ++c)
      {
        value[c] += w * array->GetComponent(id, c);
      }
    }
    return true;
  }
  return false;
}

// Point arrays every piece has (same name and component count): the ones a
// resampled image can carry.
std::vector<std::pair<std::string, int>> CommonPointArrays(const std::vector<vtkSmartPointer<vtkImageData>>& pieces)
{
  std::vector<std::pair<std::string, int>> common;
  vtkPointData* pd = pieces[0]->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (!array || !array->GetName() ||
      std::string(array->GetName()) == vtkDataSetAttributes::GhostArrayName())
    {
      continue;
    }
    bool everywhere = true;
    for (const auto& p : pieces)
    {
      vtkDataArray* other = p->GetPointData()->GetArray(array->GetName());
      everywhere = everywhere && other && other->GetNumberOfComponents() == array->GetNumberOfComponents();
    }
    if (everywhere)
    {
      common.emplace_back(array->GetName(), array->GetNumberOfComponents());
    }
  }
  return common;
}

// Pieces that are not one grid (AMR levels, blocks of different spacing or
// origin, overlapping pieces): one image over the union of their bounds at
// the finest spacing among them (coarsened evenly if that is over the memory
// budget); each point takes the trilinear value of the finest piece that
// contains it (AMR: the refined level where there is one), points no piece
// covers the minimum of the array (the transfer function's low end).
vtkSmartPointer<vtkImageData> Resample(std::vector<vtkSmartPointer<vtkImageData>> pieces, vtkAlgorithm* owner)
{
  auto cellVolume = [](vtkImageData* image) {
    const double* h = image->GetSpacing();
    return std::abs(h[0] * h[1] * h[2]);
  };
  std::stable_sort(pieces.begin(), pieces.end(),
    [&](const vtkSmartPointer<vtkImageData>& a, const vtkSmartPointer<vtkImageData>& b) {
      return cellVolume(a) < cellVolume(b);
    });
  double bounds[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX };
  double h[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  for (const auto& p : pieces)
  {
    double b[6];
    p->GetBounds(b);
    for (int a = 0; a < 3; ++a)
    {
      bounds[2 * a] = std::min(bounds[2 * a], b[2 * a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], b[2 * a + 1]);
      if (p->GetDimensions()[a] > 1)
      {
        h[a] = std::min(h[a], std::abs(p->GetSpacing()[a]));
      }
    }
  }
  const auto arrays = CommonPointArrays(pieces);
  int components = 0;
  for (const auto& array : arrays)
  {
    components += array.second;
  }
  int dims[3];
  double scale = 1;
  for (int attempt = 0; attempt < 64; ++attempt)
  {
    double points = 1;
    for (int a = 0; a < 3; ++a)
    {
      const double extent = bounds[2 * a + 1] - bounds[2 * a];
      dims[a] = (h[a] < VTK_DOUBLE_MAX && h[a] > 0 && extent > 0)
        ? static_cast<int>(std::ceil(extent / (h[a] * scale) - 1e-6)) + 1
        : 1;
      points *= dims[a];
    }
    const double bytes = points * std::max(1, components) * sizeof(float);
    if (vtkPlumeInputValidation::CheckMemory(bytes, "").empty())
    {
      break;
    }
    scale *= 1.25; // coarser, evenly on every axis, until it fits
  }
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetOrigin(bounds[0], bounds[2], bounds[4]);
  double spacing[3];
  for (int a = 0; a < 3; ++a)
  {
    spacing[a] = dims[a] > 1 ? (bounds[2 * a + 1] - bounds[2 * a]) / (dims[a] - 1) : 1.0;
  }
  out->SetSpacing(spacing);
  out->SetDimensions(dims);
  const vtkIdType n = out->GetNumberOfPoints();
  for (const auto& array : arrays)
  {
    vtkNew<vtkFloatArray> values;
    values->SetName(array.first.c_str());
    values->SetNumberOfComponents(array.second);
    values->SetNumberOfTuples(n);
    // the background: the array's minimum over the pieces, per component
    std::vector<double> low(array.second, VTK_DOUBLE_MAX);
    for (const auto& p : pieces)
    {
      vtkDataArray* source = p->GetPointData()->GetArray(array.first.c_str());
      for (int c = 0; c < array.second; ++c)
      {
        low[c] = std::min(low[c], source->GetRange(c)[0]);
      }
    }
    vtkSMPTools::For(0, dims[2], [&](vtkIdType k0, vtkIdType k1) {
      std::vector<double> value(array.second);
      for (vtkIdType k = k0; k < k1; ++k)
      {
        for (int j = 0; j < dims[1]; ++j)
        {
          for (int i = 0; i < dims[0]; ++i)
          {
            const double x[3] = { bounds[0] + i * spacing[0], bounds[2] + j * spacing[1],
              bounds[4] + k * spacing[2] };
            const bool found = Interpolate(pieces, array.first.c_str(), x, value.data());
            const vtkIdType id = i + static_cast<vtkIdType>(dims[0]) * (j + static_cast<vtkIdType>(dims[1]) * k);
            for (int c = 0; c < array.second; ++c)
            {
              values->SetTypedComponent(id, c, static_cast<float>(found ? value[c] : low[c]));
            }
          }
        }
      }
    });
    out->GetPointData()->AddArray(values);
  }
  vtkPointData* firstPD = pieces[0]->GetPointData();
  for (int attribute : { vtkDataSetAttributes::SCALARS, vtkDataSetAttributes::VECTORS })
  {
    vtkDataArray* active = firstPD->GetAttribute(attribute);
    if (active && active->GetName() && out->GetPointData()->GetArray(active->GetName()))
    {
      out->GetPointData()->SetActiveAttribute(active->GetName(), attribute);
    }
  }
  if (owner)
  {
    vtkWarningWithObjectMacro(owner, << "the input holds " << pieces.size()
                                     << " images on this process that are not pieces of one grid (different "
                                        "spacing or origin, or overlapping: e.g. AMR levels); Plume resampled them "
                                        "onto one "
                                     << dims[0] << "x" << dims[1] << "x" << dims[2] << " image with spacing "
                                     << spacing[0] << ", " << spacing[1] << ", " << spacing[2]
                                     << (scale > 1 ? " (coarser than the finest piece's, to fit the memory budget "
                                                     "PLUME_MEMORY_BUDGET_MB)"
                                                   : " (the finest piece's)")
                                     << ", each point from the finest piece that holds it, trilinear; "
                                     << arrays.size() << " point array(s) common to all pieces, as float");
  }
  return out;
}
}

vtkSmartPointer<vtkImageData> vtkPlumeImageInput::Extract(vtkDataObject* input, vtkAlgorithm* owner)
{
  if (auto* image = vtkImageData::SafeDownCast(input))
  {
    return image->GetNumberOfPoints() > 0 ? Copy(image) : nullptr;
  }
  auto* composite = vtkCompositeDataSet::SafeDownCast(input);
  if (!composite)
  {
    return nullptr;
  }
  std::vector<vtkSmartPointer<vtkImageData>> pieces;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    auto* image = vtkImageData::SafeDownCast(it->GetCurrentDataObject());
    if (image && image->GetNumberOfPoints() > 0)
    {
      pieces.push_back(Copy(image));
    }
  }
  if (pieces.empty())
  {
    return nullptr;
  }
  if (pieces.size() == 1)
  {
    return pieces[0];
  }
  // Several pieces on this rank (a reader or partitioner that made more
  // pieces than ranks): one image when they are pieces of one grid (same
  // origin, spacing and arrays) that tile a box without overlap, i.e. their
  // cells add up to the cells of their bounding extent.
  const vtkSmartPointer<vtkImageData>& first = pieces[0];
  int box[6];
  first->GetExtent(box);
  vtkIdType cells = first->GetNumberOfCells();
  bool tiles = true;
  for (size_t i = 1; i < pieces.size() && tiles; ++i)
  {
    const vtkSmartPointer<vtkImageData>& p = pieces[i];
    for (int a = 0; a < 3; ++a)
    {
      const double h = first->GetSpacing()[a];
      tiles = tiles && std::abs(p->GetSpacing()[a] - h) <= 1e-6 * std::abs(h) &&
        std::abs(p->GetOrigin()[a] - first->GetOrigin()[a]) <= 1e-6 * std::abs(h);
    }
    tiles = tiles && p->GetPointData()->GetNumberOfArrays() == first->GetPointData()->GetNumberOfArrays();
    const int* e = p->GetExtent();
    for (int a = 0; a < 3; ++a)
    {
      box[2 * a] = std::min(box[2 * a], e[2 * a]);
      box[2 * a + 1] = std::max(box[2 * a + 1], e[2 * a + 1]);
    }
    cells += p->GetNumberOfCells();
  }
  vtkIdType boxCells = 1;
  for (int a = 0; a < 3; ++a)
  {
    boxCells *= std::max(1, box[2 * a + 1] - box[2 * a]);
  }
  if (!tiles || cells != boxCells)
  {
    return Resample(pieces, owner);
  }
  vtkNew<vtkImageAppend> append;
  append->PreserveExtentsOn(); // each piece at its place in the box
  for (const auto& p : pieces)
  {
    append->AddInputData(p);
  }
  append->Update();
  auto merged = vtkSmartPointer<vtkImageData>::New();
  merged->ShallowCopy(append->GetOutput());
  return merged;
}
