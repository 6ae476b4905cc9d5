#include "vtkPlumeVelocityLinesRepresentation.h"

#include "vtkActor.h"
#include "vtkDataSet.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkPlumeImageInput.h"
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkRenderer.h"
#include "vtkResampleToImage.h"
#include "vtkScalarsToColors.h"

vtkStandardNewMacro(vtkPlumeVelocityLinesRepresentation);

vtkPlumeVelocityLinesRepresentation::vtkPlumeVelocityLinesRepresentation()
  : Mapper(vtkSmartPointer<vtkPlumeVelocityGlyphMapper>::New())
  , Actor(vtkSmartPointer<vtkActor>::New())
{
  this->Actor->SetMapper(this->Mapper);
  vtkMath::UninitializeBounds(this->DataBounds);
}

vtkPlumeVelocityLinesRepresentation::~vtkPlumeVelocityLinesRepresentation() = default;

void vtkPlumeVelocityLinesRepresentation::SetMapper(vtkPlumeVelocityGlyphMapper* mapper)
{
  if (mapper && mapper != this->Mapper)
  {
    this->Mapper = mapper;
    this->Actor->SetMapper(mapper);
    this->Modified();
  }
}

vtkPlumeVelocityGlyphMapper* vtkPlumeVelocityLinesRepresentation::GetMapper()
{
  return this->Mapper;
}

void vtkPlumeVelocityLinesRepresentation::SetLookupTable(vtkScalarsToColors* lut)
{
  this->LookupTable = lut;
  this->Modified();
}

int vtkPlumeVelocityLinesRepresentation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkPlumeVelocityLinesRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkMath::UninitializeBounds(this->DataBounds);
  this->Cache = nullptr;
  if (inputVector[0]->GetNumberOfInformationObjects() == 1)
  {
    vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
    this->Cache = vtkPlumeImageInput::Extract(input, this);
    auto* dataset = vtkDataSet::SafeDownCast(input);
    if (!this->Cache && (dataset ? dataset->GetNumberOfPoints() > 0 : input != nullptr))
    {
      // Not an image: resample onto one over the (local) bounds.
      vtkNew<vtkResampleToImage> resample;
      resample->SetInputDataObject(input);
      resample->SetSamplingDimensions(this->ResampleDimensions);
      resample->SetUseInputBounds(true);
      resample->Update();
      this->Cache = vtkSmartPointer<vtkImageData>::New();
      this->Cache->ShallowCopy(resample->GetOutput());
    }
    if (this->Cache && this->Cache->GetNumberOfPoints() > 0)
    {
      this->Cache->GetBounds(this->DataBounds);
    }
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

int vtkPlumeVelocityLinesRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  if (request_type == vtkPVView::REQUEST_UPDATE())
  {
    // Opaque lines: depth compositing across ranks, no ordering needed.
    vtkPVView::SetPiece(inInfo, this, this->Cache);
    vtkPVRenderView::SetGeometryBounds(inInfo, this, this->DataBounds);
    vtkPVRenderView::SetRequiresDistributedRendering(inInfo, this, true);
  }
  else if (request_type == vtkPVView::REQUEST_UPDATE_LOD())
  {
    vtkPVRenderView::SetRequiresDistributedRenderingLOD(inInfo, this, true);
  }
  else if (request_type == vtkPVView::REQUEST_RENDER())
  {
    vtkDataObject* piece = vtkPVView::GetDeliveredPiece(inInfo, this);
    this->Mapper->SetInputDataObject(piece);
    if (this->LookupTable)
    {
      // ParaView's colour map and its range, the same on every rank (the
      // mapper would otherwise set the table's range to its local speeds).
      this->Mapper->SetLookupTable(this->LookupTable);
      this->Mapper->SetUseDataRange(false);
      this->Mapper->SetScalarRange(this->LookupTable->GetRange());
    }
    else
    {
      this->Mapper->SetUseDataRange(true);
    }
    this->Actor->SetVisibility(this->GetVisibility() && piece != nullptr);
  }
  return 1;
}

bool vtkPlumeVelocityLinesRepresentation::AddToView(vtkView* view)
{
  vtkPVRenderView* rview = vtkPVRenderView::SafeDownCast(view);
  if (rview)
  {
    rview->GetRenderer()->AddActor(this->Actor);
    return this->Superclass::AddToView(view);
  }
  return false;
}

bool vtkPlumeVelocityLinesRepresentation::RemoveFromView(vtkView* view)
{
  vtkPVRenderView* rview = vtkPVRenderView::SafeDownCast(view);
  if (rview)
  {
    rview->GetRenderer()->RemoveActor(this->Actor);
    return this->Superclass::RemoveFromView(view);
  }
  return false;
}

void vtkPlumeVelocityLinesRepresentation::SetVisibility(bool visible)
{
  this->Superclass::SetVisibility(visible);
  this->Actor->SetVisibility(visible);
}

void vtkPlumeVelocityLinesRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mapper: " << this->Mapper.Get() << "\n";
}
