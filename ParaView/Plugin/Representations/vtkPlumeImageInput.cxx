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

// Where x lies in `piece`: its structured coordinate along each axis; false
// if x is outside the piece's point bounds.
bool Locate(vtkImageData* piece, const double x[3], double f[3])
{
  const double* o = piece->GetOrigin();
  const double* h = piece->GetSpacing();
  const int* e = piece->GetExtent();
  for (int a = 0; a < 3; ++a)
  {
    f[a] = (x[a] - o[a]) / h[a];
    const double tol = 1e-6;
    if (f[a] < e[2 * a] - tol || f[a] > e[2 * a + 1] + tol)
    {
      return false;
    }
  }
  return true;
}

// The trilinear value of point array `name` at x in the first of `pieces`
// (finest first) whose point bounds contain x.
bool Interpolate(const std::vector<vtkSmartPointer<vtkImageData>>& pieces, const char* name, const double x[3],
  double* value)
{
  for (const auto& p : pieces)
  {
    double f[3];
    if (!Locate(p, x, f))
    {
      continue;
    }
    const int* e = p->GetExtent();
    int i0[3];
    double t[3];
    for (int a = 0; a < 3; ++a)
    {
      if (e[2 * a] == e[2 * a + 1])
      {
        i0[a] = e[2 * a];
        t[a] = 0;
        continue;
      }
      i0[a] = std::min(std::max(static_cast<int>(std::floor(f[a])), e[2 * a]), e[2 * a + 1] - 1);
      t[a] = std::min(std::max(f[a] - i0[a], 0.0), 1.0);
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

// The value of cell array `name` of the cell holding x in the first of
// `pieces` (finest first) whose bounds contain x: cell values are constant
// over their cell (no interpolation), as vtkProbeFilter samples them.
bool CellValue(const std::vector<vtkSmartPointer<vtkImageData>>& pieces, const char* name, const double x[3],
  double* value)
{
  for (const auto& p : pieces)
  {
    double f[3];
    if (!Locate(p, x, f))
    {
      continue;
    }
    const int* e = p->GetExtent();
    int ijk[3];
    for (int a = 0; a < 3; ++a)
    {
      ijk[a] = e[2 * a] == e[2 * a + 1]
        ? e[2 * a]
        : std::min(std::max(static_cast<int>(std::floor(f[a])), e[2 * a]), e[2 * a + 1] - 1);
    }
    vtkDataArray* array = p->GetCellData()->GetArray(name);
    const vtkIdType id = p->ComputeCellId(ijk);
    for (int c = 0; c < array->GetNumberOfComponents(); ++c)
    {
      value[c] = array->GetComponent(id, c);
    }
    return true;
  }
  return false;
}

// Arrays of one attribute (point or cell data) that every piece has (same
// name and component count): the ones a resampled image can carry. The ghost
// array is not one of them (nor, for cell data, a name a point array has).
std::vector<std::pair<std::string, int>> CommonArrays(
  const std::vector<vtkSmartPointer<vtkImageData>>& pieces, int association)
{
  auto attributes = [association](vtkImageData* image) -> vtkDataSetAttributes* {
    return association == vtkDataObject::FIELD_ASSOCIATION_CELLS
      ? static_cast<vtkDataSetAttributes*>(image->GetCellData())
      : static_cast<vtkDataSetAttributes*>(image->GetPointData());
  };
  std::vector<std::pair<std::string, int>> common;
  vtkDataSetAttributes* first = attributes(pieces[0]);
  for (int a = 0; a < first->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = first->GetArray(a);
    if (!array || !array->GetName() ||
      std::string(array->GetName()) == vtkDataSetAttributes::GhostArrayName() ||
      (association == vtkDataObject::FIELD_ASSOCIATION_CELLS &&
        pieces[0]->GetPointData()->GetArray(array->GetName())))
    {
      continue;
    }
    bool everywhere = true;
    for (const auto& p : pieces)
    {
      vtkDataArray* other = attributes(p)->GetArray(array->GetName());
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
// origin, overlapping pieces), or an image whose data are cell arrays only:
// one image over the union of their bounds at the finest spacing among them
// (coarsened evenly if that is over the memory budget), as point data.
// - Point arrays: each point takes the trilinear value of the finest piece
//   that contains it (AMR: the refined level where there is one).
// - Cell arrays: the points are then the centres of the cells of that finest
//   lattice (half a spacing inside the union's bounds), each taking the value
//   of the finest piece's cell holding it. At the finest spacing every such
//   centre lies inside exactly one cell of each piece whose cells it refines
//   (AMR levels nest), so the cell values are kept exactly, where sampling
//   at cell corners would have to pick one of up to eight cells. Point arrays
//   are interpolated at those centres.
// Points no piece covers take the array's minimum (the transfer function's
// low end).
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
  const auto pointArrays = CommonArrays(pieces, vtkDataObject::FIELD_ASSOCIATION_POINTS);
  const auto cellArrays = CommonArrays(pieces, vtkDataObject::FIELD_ASSOCIATION_CELLS);
  const bool centres = !cellArrays.empty();
  int components = 0;
  for (const auto& array : pointArrays)
  {
    components += array.second;
  }
  for (const auto& array : cellArrays)
  {
    components += array.second;
  }
  // dims[a]: points along axis a; with cell arrays, cells of the lattice
  // (their centres are the points)
  int dims[3];
  double scale = 1;
  for (int attempt = 0; attempt < 64; ++attempt)
  {
    double points = 1;
    for (int a = 0; a < 3; ++a)
    {
      const double extent = bounds[2 * a + 1] - bounds[2 * a];
      const bool flat = !(h[a] < VTK_DOUBLE_MAX && h[a] > 0 && extent > 0);
      const double cells = flat ? 0 : std::ceil(extent / (h[a] * scale) - 1e-6);
      dims[a] = flat ? 1 : static_cast<int>(centres ? std::max(1.0, cells) : cells + 1);
      points *= dims[a];
    }
    const double bytes = points * std::max(1, components) * sizeof(float);
    if (vtkPlumeInputValidation::CheckMemory(bytes, "").empty())
    {
      break;
    }
    scale *= 1.25; // coarser, evenly on every axis, until it fits
  }
  double origin[3];
  double spacing[3];
  for (int a = 0; a < 3; ++a)
  {
    const double extent = bounds[2 * a + 1] - bounds[2 * a];
    if (centres)
    {
      spacing[a] = extent > 0 ? extent / dims[a] : 1.0;
      origin[a] = bounds[2 * a] + (extent > 0 ? 0.5 * spacing[a] : 0.0);
    }
    else
    {
      spacing[a] = dims[a] > 1 ? extent / (dims[a] - 1) : 1.0;
      origin[a] = bounds[2 * a];
    }
  }
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetOrigin(origin);
  out->SetSpacing(spacing);
  out->SetDimensions(dims);
  const vtkIdType n = out->GetNumberOfPoints();
  for (int association : { vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataObject::FIELD_ASSOCIATION_CELLS })
  {
    const bool cell = association == vtkDataObject::FIELD_ASSOCIATION_CELLS;
    for (const auto& array : cell ? cellArrays : pointArrays)
    {
      vtkNew<vtkFloatArray> values;
      values->SetName(array.first.c_str());
      values->SetNumberOfComponents(array.second);
      values->SetNumberOfTuples(n);
      // the background: the array's minimum over the pieces, per component
      std::vector<double> low(array.second, VTK_DOUBLE_MAX);
      for (const auto& p : pieces)
      {
        vtkDataArray* source = cell ? p->GetCellData()->GetArray(array.first.c_str())
                                    : p->GetPointData()->GetArray(array.first.c_str());
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
              const double x[3] = { origin[0] + i * spacing[0], origin[1] + j * spacing[1],
                origin[2] + k * spacing[2] };
              const bool found = cell ? CellValue(pieces, array.first.c_str(), x, value.data())
                                      : Interpolate(pieces, array.first.c_str(), x, value.data());
              const vtkIdType id =
                i + static_cast<vtkIdType>(dims[0]) * (j + static_cast<vtkIdType>(dims[1]) * k);
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
  }
  // the first piece's active scalars and vectors stay active (a cell
  // attribute only where no point array is)
  for (int attribute : { vtkDataSetAttributes::SCALARS, vtkDataSetAttributes::VECTORS })
  {
    for (vtkDataSetAttributes* source :
      { static_cast<vtkDataSetAttributes*>(pieces[0]->GetPointData()),
        static_cast<vtkDataSetAttributes*>(pieces[0]->GetCellData()) })
    {
      vtkDataArray* active = source->GetAttribute(attribute);
      if (!out->GetPointData()->GetAttribute(attribute) && active && active->GetName() &&
        out->GetPointData()->GetArray(active->GetName()))
      {
        out->GetPointData()->SetActiveAttribute(active->GetName(), attribute);
      }
    }
  }
  if (owner)
  {
    vtkWarningWithObjectMacro(owner, << "the input holds " << pieces.size()
                                     << (pieces.size() == 1 ? " image with cell data only"
                                                            : " images on this process that are not pieces of "
                                                              "one grid (different spacing or origin, or "
                                                              "overlapping: e.g. AMR levels)")
                                     << "; Plume resampled them onto one "
                                     << dims[0] << "x" << dims[1] << "x" << dims[2] << " image with spacing "
                                     << spacing[0] << ", " << spacing[1] << ", " << spacing[2]
                                     << (scale > 1 ? " (coarser than the finest piece's, to fit the memory budget "
                                                     "PLUME_MEMORY_BUDGET_MB)"
                                                   : " (the finest piece's)")
                                     << (centres ? " at the centres of that lattice's cells" : "")
                                     << ", each point from the finest piece that holds it; " << pointArrays.size()
                                     << " point array(s) (trilinear) and " << cellArrays.size()
                                     << " cell array(s) (the value of the cell holding the point) common to all "
                                        "pieces, as float point data");
  }
  return out;
}

// Whether the image's data are cell arrays only (a finite-volume result, an
// AMR block): the volume and line mappers sample point data.
bool CellDataOnly(vtkImageData* image)
{
  auto named = [](vtkDataSetAttributes* attributes) {
    int count = 0;
    for (int a = 0; a < attributes->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* array = attributes->GetArray(a);
      count += array && array->GetName() && std::string(array->GetName()) != vtkDataSetAttributes::GhostArrayName();
    }
    return count;
  };
  return named(image->GetPointData()) == 0 && named(image->GetCellData()) > 0;
}
}

vtkSmartPointer<vtkImageData> vtkPlumeImageInput::Extract(vtkDataObject* input, vtkAlgorithm* owner)
{
  if (auto* image = vtkImageData::SafeDownCast(input))
  {
    if (image->GetNumberOfPoints() == 0)
    {
      return nullptr;
    }
    vtkSmartPointer<vtkImageData> copy = Copy(image);
    return CellDataOnly(copy) ? Resample({ copy }, owner) : copy;
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
    return CellDataOnly(pieces[0]) ? Resample(pieces, owner) : pieces[0];
  }
  // Several pieces on this rank (a reader or partitioner that made more
  // pieces than ranks): one image when they are pieces of one grid (same
  // origin, spacing and arrays) that tile a box without overlap, i.e. their
  // cells add up to the cells of their bounding extent.
  const vtkSmartPointer<vtkImageData>& first = pieces[0];
  int box[6];
  first->GetExtent(box);
  vtkIdType cells = first->GetNumberOfCells();
  // cell data only: the point samples come from a resample (vtkImageAppend
  // would carry no point data)
  bool tiles = !CellDataOnly(first);
  for (size_t i = 1; i < pieces.size() && tiles; ++i)
  {
    const vtkSmartPointer<vtkImageData>& p = pieces[i];
    for (int a = 0; a < 3; ++a)
    {
      const double h = first->GetSpacing()[a];
      tiles = tiles && std::abs(p->GetSpacing()[a] - h) <= 1e-6 * std::abs(h) &&
        std::abs(p->GetOrigin()[a] - first->GetOrigin()[a]) <= 1e-6 * std::abs(h);
    }
    tiles = tiles && p->GetPointData()->GetNumberOfArrays() == first->GetPointData()->GetNumberOfArrays() &&
      !CellDataOnly(p);
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
