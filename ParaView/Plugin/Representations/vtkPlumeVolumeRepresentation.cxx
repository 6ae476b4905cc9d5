#include "vtkPlumeVolumeRepresentation.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkImageData.h"
#include "vtkMultiProcessController.h"
#include "vtkCommunicator.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPlumeImageInput.h"
#include "vtkPlumeVolumeMapper.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <limits>

vtkStandardNewMacro(vtkPlumeVolumeRepresentation);

vtkPlumeVolumeRepresentation::vtkPlumeVolumeRepresentation()
  : Mapper(vtkSmartPointer<vtkPlumeVolumeMapper>::New())
  , Volume(vtkSmartPointer<vtkVolume>::New())
  , Property(vtkSmartPointer<vtkVolumeProperty>::New())
{
  this->Volume->SetProperty(this->Property);
  this->Volume->SetMapper(this->Mapper);
  this->Property->SetInterpolationTypeToLinear();
  // the mapper's own OpacityUnitDistance (PlumeVolumeOpacityUnitDistance) if
  // set, else automatic (one voxel), not VTK's default of one world unit
  this->Property->SetScalarOpacityUnitDistance(0.0);
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
  this->ReduceScalarRange(vtkImageData::SafeDownCast(this->Cache));
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

void vtkPlumeVolumeRepresentation::ReduceScalarRange(vtkImageData* image)
{
  // The default look's range, over every rank's piece: each rank's own
  // range would colour the same value differently on each rank. Every rank
  // runs RequestData (ParaView updates representations collectively), so
  // every rank reaches the reduction, with or without data.
  constexpr double inf = std::numeric_limits<double>::infinity();
  double local[2] = { inf, inf }; // min and -max, both reduced by MIN
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (scalars && scalars->GetNumberOfTuples() > 0)
  {
    double range[2];
    scalars->GetRange(range, scalars->GetNumberOfComponents() == 1 ? 0 : -1);
    local[0] = range[0];
    local[1] = -range[1];
  }
  double global[2] = { local[0], local[1] };
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    controller->AllReduce(local, global, 2, vtkCommunicator::MIN_OP);
  }
  this->ScalarRange[0] = global[0];
  this->ScalarRange[1] = -global[1];
}

void vtkPlumeVolumeRepresentation::SetLookupTable(vtkScalarsToColors* lut)
{
  this->ColorMap = vtkColorTransferFunction::SafeDownCast(lut);
  this->Modified();
}

void vtkPlumeVolumeRepresentation::SetScalarOpacity(vtkPiecewiseFunction* pwf)
{
  this->OpacityFunction = pwf;
  this->Modified();
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
    this->Property->SetColor(this->ColorMap);
    this->Property->SetScalarOpacity(this->OpacityFunction);
  }
  else
  {
    this->Mapper->SetScalarModeToDefault();
    this->ApplyDefaultLook(vtkImageData::SafeDownCast(piece));
  }
  return piece != nullptr;
}

void vtkPlumeVolumeRepresentation::ApplyDefaultLook(vtkImageData* image)
{
  // ParaView picks an array and its colour map only for representations
  // named "Volume" or "Slice" (vtkSMPVRepresentationProxy::
  // SetRepresentationType); without this the first Apply of "Plume Volume"
  // drew VTK's default grey ramp over 0-1024: a near-black box.
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!scalars || !(this->ScalarRange[0] <= this->ScalarRange[1]))
  {
    return;
  }
  // over all ranks (ReduceScalarRange): the same value, the same colour
  double range[2] = { this->ScalarRange[0], this->ScalarRange[1] };
  if (!(range[1] > range[0]))
  {
    range[1] = range[0] + 1.0;
  }
  if (range[0] != this->DefaultRange[0] || range[1] != this->DefaultRange[1])
  {
    std::copy(range, range + 2, this->DefaultRange);
    // ParaView's default colour map ("Cool to Warm") and opacity ramp
    this->DefaultColor->RemoveAllPoints();
    this->DefaultColor->SetColorSpaceToDiverging();
    this->DefaultColor->AddRGBPoint(range[0], 0.231373, 0.298039, 0.752941);
    this->DefaultColor->AddRGBPoint(0.5 * (range[0] + range[1]), 0.865003, 0.865003, 0.865003);
    this->DefaultColor->AddRGBPoint(range[1], 0.705882, 0.0156863, 0.14902);
    this->DefaultOpacity->RemoveAllPoints();
    this->DefaultOpacity->AddPoint(range[0], 0.0);
    this->DefaultOpacity->AddPoint(range[1], 1.0);
  }
  this->Property->SetColor(this->DefaultColor);
  this->Property->SetScalarOpacity(this->DefaultOpacity);
}

void vtkPlumeVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mapper: " << this->Mapper.Get() << "\n";
}
