#include "vtkPlumeImageInput.h"

#include "vtkAlgorithm.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkImageData.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>

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
  vtkSmartPointer<vtkImageData> first;
  int count = 0;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    auto* image = vtkImageData::SafeDownCast(it->GetCurrentDataObject());
    if (image && image->GetNumberOfPoints() > 0)
    {
      if (!first)
      {
        first = Copy(image);
      }
      ++count;
    }
  }
  if (count > 1 && owner)
  {
    vtkWarningWithObjectMacro(owner, << "the input holds " << count
                                     << " images on this process; Plume draws the first only");
  }
  return first;
}
