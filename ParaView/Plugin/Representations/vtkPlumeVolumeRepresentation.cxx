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
  this->Prop = this->Volume;
  // ray casting per rank: the ranks' images blend back to front
  this->OrderedCompositing = true;
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
    vtkSmartPointer<vtkImageData> image = vtkPlumeImageInput::Extract(vtkDataObject::GetData(inputVector[0], 0), this);
    if (image)
    {
      image->GetBounds(this->DataBounds);
    }
    this->Cache = image;
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
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

bool vtkPlumeVolumeRepresentation::PrepareRender(vtkDataObject* piece)
{
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
  return piece != nullptr;
}

void vtkPlumeVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mapper: " << this->Mapper.Get() << "\n";
}
