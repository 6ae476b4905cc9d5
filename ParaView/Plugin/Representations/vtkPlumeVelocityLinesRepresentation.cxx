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
  this->Prop = this->Actor; // opaque lines: ranks composite by depth
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
    vtkSmartPointer<vtkImageData> image = vtkPlumeImageInput::Extract(input, this);
    auto* dataset = vtkDataSet::SafeDownCast(input);
    if (!image && (dataset ? dataset->GetNumberOfPoints() > 0 : input != nullptr))
    {
      // Not an image: resample onto one over the (local) bounds.
      vtkNew<vtkResampleToImage> resample;
      resample->SetInputDataObject(input);
      resample->SetSamplingDimensions(this->ResampleDimensions);
      resample->SetUseInputBounds(true);
      resample->Update();
      image = vtkSmartPointer<vtkImageData>::New();
      image->ShallowCopy(resample->GetOutput());
    }
    if (image && image->GetNumberOfPoints() > 0)
    {
      image->GetBounds(this->DataBounds);
    }
    this->Cache = image;
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

bool vtkPlumeVelocityLinesRepresentation::PrepareRender(vtkDataObject* piece)
{
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
  return piece != nullptr;
}

void vtkPlumeVelocityLinesRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mapper: " << this->Mapper.Get() << "\n";
}
