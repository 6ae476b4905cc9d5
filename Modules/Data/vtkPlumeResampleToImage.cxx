#include "vtkPlumeResampleToImage.h"

#include "vtkPlumeInputValidation.h"
#include "vtkPlumeWholeInput.h"

#include "vtkCellData.h"
#include "vtkCellDataToPointData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkResampleToImage.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPlumeResampleToImage);

vtkPlumeResampleToImage::vtkPlumeResampleToImage()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

int vtkPlumeResampleToImage::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  return 1;
}

bool vtkPlumeResampleToImage::ExplicitDimensions() const
{
  return this->SamplingDimensions[0] >= 1 && this->SamplingDimensions[1] >= 1 &&
    this->SamplingDimensions[2] >= 1;
}

void vtkPlumeResampleToImage::ComputeAutomaticDimensions(
  const double bounds[6], int maximumDimension, int dimensions[3])
{
  const int m = std::max(maximumDimension, 2);
  double length[3];
  double longest = 0;
  for (int a = 0; a < 3; ++a)
  {
    length[a] = bounds[2 * a + 1] - bounds[2 * a];
    if (!(length[a] > 0)) // also catches NaN and uninitialised (inverted) bounds
    {
      length[a] = 0;
    }
    longest = std::max(longest, length[a]);
  }
  for (int a = 0; a < 3; ++a)
  {
    // An axis shorter than 1e-9 of the longest one counts as flat.
    if (longest <= 0 || length[a] <= 1e-9 * longest)
    {
      dimensions[a] = 1;
    }
    else if (length[a] >= longest)
    {
      dimensions[a] = m;
    }
    else
    {
      const int n = static_cast<int>(std::lround(length[a] / longest * (m - 1))) + 1;
      dimensions[a] = std::min(std::max(n, 2), m);
    }
  }
}

namespace
{
bool DataObjectBounds(vtkDataObject* data, double bounds[6])
{
  vtkMath::UninitializeBounds(bounds);
  bool any = false;
  auto merge = [&](vtkDataSet* ds) {
    if (!ds || ds->GetNumberOfPoints() == 0)
    {
      return;
    }
    double b[6];
    ds->GetBounds(b);
    if (!any)
    {
      std::copy(b, b + 6, bounds);
      any = true;
      return;
    }
    for (int a = 0; a < 3; ++a)
    {
      bounds[2 * a] = std::min(bounds[2 * a], b[2 * a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], b[2 * a + 1]);
    }
  };
  if (auto* cds = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(cds->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      merge(vtkDataSet::SafeDownCast(it->GetCurrentDataObject()));
    }
  }
  else
  {
    merge(vtkDataSet::SafeDownCast(data));
  }
  return any;
}

// Drop cell arrays that shadow a point array of the same name; returns true if cell arrays
// remain that need converting.
bool PrepareDataSet(vtkDataSet* ds)
{
  vtkCellData* cd = ds->GetCellData();
  vtkPointData* pd = ds->GetPointData();
  std::vector<std::string> drop;
  for (int i = 0; i < cd->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* array = cd->GetAbstractArray(i);
    const char* name = array ? array->GetName() : nullptr;
    if (!name || !vtkDataArray::SafeDownCast(array) || pd->HasArray(name) ||
      std::string(name) == vtkDataSetAttributes::GhostArrayName())
    {
      if (name && std::string(name) != vtkDataSetAttributes::GhostArrayName())
      {
        drop.emplace_back(name);
      }
      continue;
    }
  }
  for (const auto& name : drop)
  {
    cd->RemoveArray(name.c_str());
  }
  for (int i = 0; i < cd->GetNumberOfArrays(); ++i)
  {
    const char* name = cd->GetArrayName(i);
    if (name && std::string(name) != vtkDataSetAttributes::GhostArrayName())
    {
      return true;
    }
  }
  return false;
}

// A shallow copy of the input where cell arrays are converted to point arrays.
vtkSmartPointer<vtkDataObject> CellsToPoints(vtkDataObject* input)
{
  vtkSmartPointer<vtkDataObject> copy;
  copy.TakeReference(input->NewInstance());
  copy->ShallowCopy(input);
  bool needed = false;
  if (auto* cds = vtkCompositeDataSet::SafeDownCast(copy))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(cds->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      auto* ds = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
      if (!ds)
      {
        continue;
      }
      // The leaves are shared with the input: copy the leaf before touching its attributes.
      vtkSmartPointer<vtkDataSet> leaf;
      leaf.TakeReference(ds->NewInstance());
      leaf->ShallowCopy(ds);
      needed = PrepareDataSet(leaf) || needed;
      cds->SetDataSet(it, leaf);
    }
  }
  else if (auto* ds = vtkDataSet::SafeDownCast(copy))
  {
    needed = PrepareDataSet(ds);
  }
  if (!needed)
  {
    return copy;
  }
  vtkNew<vtkCellDataToPointData> c2p;
  c2p->SetInputDataObject(copy);
  c2p->PassCellDataOff();
  c2p->ProcessAllArraysOn();
  c2p->Update();
  return c2p->GetOutputDataObject(0);
}

// Zero every point array (except the mask and the ghost array) where the mask is 0.
void ApplyMask(vtkImageData* image, const char* maskName)
{
  vtkPointData* pd = image->GetPointData();
  vtkDataArray* mask = pd->GetArray(maskName);
  if (!mask)
  {
    return;
  }
  const vtkIdType n = mask->GetNumberOfTuples();
  std::vector<vtkIdType> outside;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (mask->GetComponent(i, 0) == 0)
    {
      outside.push_back(i);
    }
  }
  if (outside.empty())
  {
    return;
  }
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (!array || array == mask || array->GetNumberOfTuples() != n ||
      (array->GetName() && std::string(array->GetName()) == vtkDataSetAttributes::GhostArrayName()))
    {
      continue;
    }
    const int nc = array->GetNumberOfComponents();
    vtkSMPTools::For(0, static_cast<vtkIdType>(outside.size()), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        for (int c = 0; c < nc; ++c)
        {
          array->SetComponent(outside[k], c, 0.0);
        }
      }
    });
    array->Modified();
  }
}
}

void vtkPlumeResampleToImage::ZeroOutsideMask(vtkImageData* image)
{
  if (image)
  {
    ApplyMask(image, GetMaskArrayName());
  }
}

int vtkPlumeResampleToImage::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);

  // The automatic dimensions depend on the input bounds, which only the data knows: bring
  // the input up to date now so the whole extent announced downstream is the real one. If
  // the upstream fails, announce an empty extent; the data pass then fails upstream again
  // (and reports there) without this filter executing.
  int upstreamPort = 0;
  vtkAlgorithm* upstream = this->GetInputAlgorithm(0, 0, upstreamPort);
  vtkDataObject* input = nullptr;
  if (upstream && upstream->GetExecutive()->Update(upstreamPort))
  {
    input = upstream->GetOutputDataObject(upstreamPort);
  }
  if (!input)
  {
    input = vtkDataObject::GetData(inInfo);
  }

  this->PassThrough = false;
  auto* image = vtkImageData::SafeDownCast(input);
  if (image && !this->ExplicitDimensions())
  {
    this->PassThrough = true;
    int extent[6];
    image->GetExtent(extent);
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    outInfo->Set(vtkDataObject::ORIGIN(), image->GetOrigin(), 3);
    outInfo->Set(vtkDataObject::SPACING(), image->GetSpacing(), 3);
    return 1;
  }

  if (!input || !DataObjectBounds(input, this->Bounds))
  {
    std::fill(this->Bounds, this->Bounds + 6, 0.0);
    const int empty[6] = { 0, -1, 0, -1, 0, -1 };
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), empty, 6);
    std::fill(this->Dimensions, this->Dimensions + 3, 0);
    return 1;
  }
  if (this->ExplicitDimensions())
  {
    std::copy(this->SamplingDimensions, this->SamplingDimensions + 3, this->Dimensions);
  }
  else
  {
    ComputeAutomaticDimensions(this->Bounds, this->MaximumDimension, this->Dimensions);
  }
  double origin[3], spacing[3];
  for (int a = 0; a < 3; ++a)
  {
    origin[a] = this->Bounds[2 * a];
    const double width = this->Bounds[2 * a + 1] - this->Bounds[2 * a];
    spacing[a] = this->Dimensions[a] > 1 ? width / (this->Dimensions[a] - 1) : 1.0;
  }
  const int extent[6] = { 0, this->Dimensions[0] - 1, 0, this->Dimensions[1] - 1, 0,
    this->Dimensions[2] - 1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  return 1;
}

int vtkPlumeResampleToImage::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Always ask for the whole input (our extents are not in the input's index space).
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  plume::RequestWholeExtent(inInfo);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  return 1;
}

int vtkPlumeResampleToImage::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  if (!output)
  {
    return 0;
  }
  output->Initialize();
  this->LastError.clear();
  if (!input)
  {
    return 1;
  }
  // VTK's probe follows the input's cell connectivity unchecked: refuse bad cells before it does.
  this->LastError = vtkPlumeInputValidation::CheckDataObject(input);
  if (!this->LastError.empty())
  {
    this->LastError = "invalid input: " + this->LastError;
    vtkErrorMacro(<< this->LastError);
    return 0;
  }
  if (auto* image = vtkImageData::SafeDownCast(input))
  {
    if (!this->ExplicitDimensions())
    {
      output->ShallowCopy(image);
      return 1;
    }
  }
  // The bounds may have changed since RequestInformation (another time step): the extent
  // stays what was announced, the bounds follow the data.
  double bounds[6];
  if (!DataObjectBounds(input, bounds))
  {
    return 1; // no points: empty image
  }
  int dims[3];
  if (this->ExplicitDimensions())
  {
    std::copy(this->SamplingDimensions, this->SamplingDimensions + 3, dims);
  }
  else
  {
    std::copy(this->Dimensions, this->Dimensions + 3, dims);
    if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1)
    {
      ComputeAutomaticDimensions(bounds, this->MaximumDimension, dims);
    }
  }

  {
    // every input array becomes a point array of the image (doubles at most), plus the mask
    int components = 1;
    if (auto* ds = vtkDataSet::SafeDownCast(input))
    {
      for (vtkDataSetAttributes* a : { static_cast<vtkDataSetAttributes*>(ds->GetPointData()),
             static_cast<vtkDataSetAttributes*>(ds->GetCellData()) })
      {
        for (int i = 0; i < a->GetNumberOfArrays(); ++i)
        {
          components += a->GetArray(i) ? a->GetArray(i)->GetNumberOfComponents() : 0;
        }
      }
    }
    const double points = double(dims[0]) * double(dims[1]) * double(dims[2]);
    this->LastError = vtkPlumeInputValidation::CheckMemory(points * 8.0 * components,
      "resampling onto " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" +
        std::to_string(dims[2]) + " points");
    if (!this->LastError.empty())
    {
      vtkErrorMacro(<< this->LastError);
      return 0;
    }
  }
  vtkSmartPointer<vtkDataObject> pointInput = CellsToPoints(input);

  vtkNew<vtkResampleToImage> resample;
  resample->SetInputDataObject(pointInput);
  resample->UseInputBoundsOff();
  resample->SetSamplingBounds(bounds);
  resample->SetSamplingDimensions(dims);
  resample->Update();
  vtkImageData* sampled = resample->GetOutput();
  output->ShallowCopy(sampled);

  // vtkResampleToImage gives a flat axis spacing 0; an image needs a positive spacing.
  double spacing[3];
  output->GetSpacing(spacing);
  for (int a = 0; a < 3; ++a)
  {
    if (dims[a] <= 1 || !(spacing[a] > 0))
    {
      spacing[a] = 1.0;
    }
  }
  output->SetSpacing(spacing);

  // The arrays belong to this output only (the internal filter goes away): mask in place.
  ZeroOutsideMask(output);
  return 1;
}

void vtkPlumeResampleToImage::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SamplingDimensions: " << this->SamplingDimensions[0] << " "
     << this->SamplingDimensions[1] << " " << this->SamplingDimensions[2] << "\n";
  os << indent << "MaximumDimension: " << this->MaximumDimension << "\n";
}
