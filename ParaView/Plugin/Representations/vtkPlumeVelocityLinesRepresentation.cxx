#include "vtkPlumeVelocityLinesRepresentation.h"

#include "vtkActor.h"
#include "vtkCommunicator.h"
#include "vtkDataSet.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkPlumeImageInput.h"
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkRenderer.h"
#include "vtkResampleToImage.h"
#include "vtkScalarsToColors.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <vector>

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
  int owned[6];
  int whole[6] = { 0, -1, 0, -1, 0, -1 }; // unknown: each piece is its own grid
  bool ownedKnown = false;
  if (inputVector[0]->GetNumberOfInformationObjects() == 1)
  {
    vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
    vtkSmartPointer<vtkImageData> image = vtkPlumeImageInput::Extract(input, this);
    vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
    if (image && vtkImageData::SafeDownCast(input) &&
      inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
    {
      // Pieces of one image share their seam's nodes: each counts once, on
      // the piece below the seam.
      inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
      image->GetExtent(owned);
      for (int a = 0; a < 3; ++a)
      {
        if (owned[2 * a + 1] < whole[2 * a + 1])
        {
          --owned[2 * a + 1];
        }
      }
      ownedKnown = true;
    }
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
  // Screen-adaptive roots (and lattice roots) on the whole image's lattice,
  // with the stride from its footprint and moving nodes: every rank picks
  // the roots a serial render picks.
  this->Mapper->SetWholeExtent(whole);
  this->ReduceAutomaticScaleSpeed(ownedKnown ? owned : nullptr);
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

void vtkPlumeVelocityLinesRepresentation::ReduceAutomaticScaleSpeed(const int* owned)
{
  // The automatic glyph scale from the robust maximum speed over every
  // rank's piece: each rank's own would draw the same speed at different
  // lengths on each rank. Exact (vtkPlumePercentile: 4 all-reduced counts);
  // every rank runs RequestData, data or not, so every rank reduces.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  vtkPlumePercentile::Sum sum;
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    sum = [controller](std::vector<vtkIdType>& counts) {
      const std::vector<vtkIdType> local(counts);
      controller->AllReduce(local.data(), counts.data(), static_cast<vtkIdType>(counts.size()),
        vtkCommunicator::SUM_OP);
    };
  }
  auto* image = vtkImageData::SafeDownCast(this->Cache);
  // and the moving nodes over all ranks (seams once), for the screen-adaptive
  // stride, from one pass over the piece's speeds; pieces not of one image
  // (resampled, merged leaves) keep their own.
  vtkIdType moving = 0;
  const double speed = this->Mapper->ComputeRobustMaximumSpeed(image, owned, sum, &moving);
  this->Mapper->SetAutomaticScaleSpeed(speed > 0.0 ? speed : vtkMath::Nan());
  this->Mapper->SetMovingNodeCount(owned ? moving : -1);
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
