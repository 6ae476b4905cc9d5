#include "vtkPlumeImageInput.h"

#include "vtkAlgorithm.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
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
    if (owner)
    {
      vtkWarningWithObjectMacro(owner, << "the input holds " << pieces.size()
                                       << " images on this process that do not tile one box of one grid; Plume "
                                          "draws the first only");
    }
    return first;
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
