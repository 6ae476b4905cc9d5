#include "vtkPlumeVolumeRepresentation.h"

#include "vtkColorTransferFunction.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlumeImageInput.h"
#include "vtkPlumeVolumeMapper.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

vtkStandardNewMacro(vtkPlumeVolumeRepresentation);

vtkPlumeVolumeRepresentation::vtkPlumeVolumeRepresentation()
  : Mapper(vtkSmartPointer<vtkPlumeVolumeMapper>::New())
  , Volume(vtkSmartPointer<vtkVolume>::New())
  , Property(vtkSmartPointer<vtkVolumeProperty>::New())
{
  this->Volume->SetProperty(this->Property);
  this->Volume->SetMapper(this->Mapper);
  this->Property->SetInterpolationTypeToLinear();
  vtkMath::UninitializeBounds(this->DataBounds);
}

vtkPlumeVolumeRepresentation::~vtkPlumeVolumeRepresentation() = default;

void vtkPlumeVolumeRepresentation::SetMapper(vtkPlumeVolumeMapper* mapper)
{
  if (mapper && mapper != this->Mapper)
  {
    this->Mapper = mapper;
    this->Volume->SetMapper(mapper);
    this->Modified();
  }
}

vtkPlumeVolumeMapper* vtkPlumeVolumeRepresentation::GetMapper()
{
  return this->Mapper;
}

vtkVolume* vtkPlumeVolumeRepresentation::GetVolume()
{
  return this->Volume;
}

int vtkPlumeVolumeRepresentation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkPlumeVolumeRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkMath::UninitializeBounds(this->DataBounds);
  this->Cache = nullptr;
  if (inputVector[0]->GetNumberOfInformationObjects() == 1)
  {
    this->Cache = vtkPlumeImageInput::Extract(vtkDataObject::GetData(inputVector[0], 0), this);
    if (this->Cache)
    {
      this->Cache->GetBounds(this->DataBounds);
    }
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

int vtkPlumeVolumeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  if (request_type == vtkPVView::REQUEST_UPDATE())
  {
    vtkPVView::SetPiece(inInfo, this, this->Cache);
    vtkPVRenderView::SetGeometryBounds(inInfo, this, this->DataBounds);
    // Ray casting per rank needs the ranks' images blended front to back:
    // the view sorts the ranks by these local bounds.
    outInfo->Set(vtkPVRenderView::NEED_ORDERED_COMPOSITING(), 1);
    vtkPVRenderView::SetOrderedCompositingConfiguration(
      inInfo, this, vtkPVRenderView::USE_BOUNDS_FOR_REDISTRIBUTION, this->DataBounds);
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
    // ColorArrayName, applied here: the mapper subproxy may be set after it.
    vtkInformation* array = this->GetInputArrayInformation(0);
    const char* name = array && array->Has(vtkDataObject::FIELD_NAME())
      ? array->Get(vtkDataObject::FIELD_NAME())
      : nullptr;
    if (name && name[0])
    {
      this->Mapper->SetScalarModeToUsePointFieldData();
      this->Mapper->SelectScalarArray(name);
    }
    else
    {
      this->Mapper->SetScalarModeToDefault();
    }
    this->Volume->SetVisibility(this->GetVisibility() && piece != nullptr);
  }
  return 1;
}

bool vtkPlumeVolumeRepresentation::AddToView(vtkView* view)
{
  vtkPVRenderView* rview = vtkPVRenderView::SafeDownCast(view);
  if (rview)
  {
    rview->GetRenderer()->AddVolume(this->Volume);
    return this->Superclass::AddToView(view);
  }
  return false;
}

bool vtkPlumeVolumeRepresentation::RemoveFromView(vtkView* view)
{
  vtkPVRenderView* rview = vtkPVRenderView::SafeDownCast(view);
  if (rview)
  {
    rview->GetRenderer()->RemoveVolume(this->Volume);
    return this->Superclass::RemoveFromView(view);
  }
  return false;
}

void vtkPlumeVolumeRepresentation::SetVisibility(bool visible)
{
  this->Superclass::SetVisibility(visible);
  this->Volume->SetVisibility(visible);
}

void vtkPlumeVolumeRepresentation::SetLookupTable(vtkScalarsToColors* lut)
{
  this->Property->SetColor(vtkColorTransferFunction::SafeDownCast(lut));
}

void vtkPlumeVolumeRepresentation::SetScalarOpacity(vtkPiecewiseFunction* pwf)
{
  this->Property->SetScalarOpacity(pwf);
}

void vtkPlumeVolumeRepresentation::SetScalarOpacityUnitDistance(double distance)
{
  this->Property->SetScalarOpacityUnitDistance(distance);
}

void vtkPlumeVolumeRepresentation::SetInputArrayToProcess(
  int idx, int port, int connection, int fieldAssociation, const char* name)
{
  this->Superclass::SetInputArrayToProcess(idx, port, connection, fieldAssociation, name);
  this->Modified();
}

void vtkPlumeVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mapper: " << this->Mapper.Get() << "\n";
}
