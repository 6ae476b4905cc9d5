#include "vtkPlumePGaussianSplatter.h"

#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkExtentTranslator.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <array>
#include <vector>

vtkStandardNewMacro(vtkPlumePGaussianSplatter);
vtkCxxSetObjectMacro(vtkPlumePGaussianSplatter, Controller, vtkMultiProcessController);

vtkPlumePGaussianSplatter::vtkPlumePGaussianSplatter()
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkPlumePGaussianSplatter::~vtkPlumePGaussianSplatter()
{
  this->SetController(nullptr);
}

int vtkPlumePGaussianSplatter::RequestInformation(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestInformation(request, inputVector, outputVector))
  {
    return 0;
  }
  // pieces are cut from the combined grid here (RequestData), not by the executive
  outputVector->GetInformationObject(0)->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

int vtkPlumePGaussianSplatter::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkMultiProcessController* c = this->Controller;
  const int ranks = c ? c->GetNumberOfProcesses() : 1;
  if (ranks <= 1)
  {
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  // Lines cut over the ranks: where a rank's line ends on the start of
  // another rank's line, the line continues there (the start splats the
  // vertex; see the class documentation of vtkPlumeGaussianSplatter). Every
  // rank's open-line starts go to every rank, 3 doubles each.
  {
    std::vector<double> starts;
    CollectLineStarts(vtkPolyData::GetData(inputVector[1], 0), starts);
    const vtkIdType mine = static_cast<vtkIdType>(starts.size());
    std::vector<vtkIdType> lengths(ranks), offsets(ranks);
    c->AllGather(&mine, lengths.data(), 1);
    vtkIdType total = 0;
    for (int r = 0; r < ranks; ++r)
    {
      offsets[r] = total;
      total += lengths[r];
    }
    this->LineContinuations.assign(static_cast<size_t>(total), 0.0);
    if (total > 0)
    {
      c->AllGatherV(starts.data(), this->LineContinuations.data(), mine, lengths.data(), offsets.data());
    }
  }
  struct ClearContinuations
  {
    std::vector<double>& Starts;
    ~ClearContinuations() { this->Starts.clear(); }
  } clearAfter{ this->LineContinuations };

  const bool sum = this->Mode != DISTANCE_MAX;
  const double* mb = this->ModelBounds;
  const bool boundsGiven = this->GetReferenceImage() ||
    (mb[0] < mb[1] && mb[2] < mb[3] && mb[4] < mb[5]);
  std::array<double, 6> saved;
  std::copy(mb, mb + 6, saved.begin());
  if (!boundsGiven)
  {
    // This rank's automatic bounds: a splat onto 2x2x2 nodes, whose origin
    // and far corner are those bounds. Members are set directly: a Set call
    // would mark the filter modified and re-run it on every update.
    const std::array<int, 3> dims = { this->Dimensions[0], this->Dimensions[1], this->Dimensions[2] };
    std::fill(this->Dimensions, this->Dimensions + 3, 2);
    const int ok = this->Superclass::RequestData(request, inputVector, outputVector);
    std::copy(dims.begin(), dims.end(), this->Dimensions);
    double local[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX,
      VTK_DOUBLE_MAX }; // (-min x, max x, -min y, ...): one MAX reduction
    if (ok && this->SplatCount > 0)
    {
      vtkImageData* probe = vtkImageData::GetData(outputVector, 0);
      double bounds[6];
      probe->GetBounds(bounds);
      for (int a = 0; a < 3; ++a)
      {
        local[2 * a] = -bounds[2 * a];
        local[2 * a + 1] = bounds[2 * a + 1];
      }
    }
    else
    {
      std::fill(local, local + 6, -VTK_DOUBLE_MAX); // no splats: no say in the bounds
    }
    double global[6];
    c->AllReduce(local, global, 6, vtkCommunicator::MAX_OP);
    if (global[1] > -VTK_DOUBLE_MAX) // some rank has splats
    {
      for (int a = 0; a < 3; ++a)
      {
        this->ModelBounds[2 * a] = -global[2 * a];
        this->ModelBounds[2 * a + 1] = global[2 * a + 1];
      }
    }
  }
  int ok = this->Superclass::RequestData(request, inputVector, outputVector);
  std::copy(saved.begin(), saved.end(), this->ModelBounds);
  // every rank takes part in the reduction, even one whose splat failed
  int allOk = 0;
  c->AllReduce(&ok, &allOk, 1, vtkCommunicator::MIN_OP);
  if (!allOk)
  {
    return 0;
  }
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  // the field is the active vectors in VECTOR_SUM, the active scalars otherwise
  const bool vectors = this->Mode == VECTOR_SUM;
  vtkDataArray* field = vectors ? output->GetPointData()->GetVectors() : output->GetPointData()->GetScalars();
  if (!field)
  {
    vtkErrorMacro(<< "the splat produced no field to combine over ranks");
    return 0;
  }
  vtkSmartPointer<vtkDataArray> combined;
  combined.TakeReference(field->NewInstance());
  combined->SetNumberOfComponents(field->GetNumberOfComponents());
  combined->SetNumberOfTuples(field->GetNumberOfTuples());
  combined->SetName(field->GetName());
  if (!c->AllReduce(field, combined, sum ? vtkCommunicator::SUM_OP : vtkCommunicator::MAX_OP))
  {
    vtkErrorMacro(<< "combining the ranks' grids failed");
    return 0;
  }
  if (vectors)
  {
    output->GetPointData()->SetVectors(combined);
  }
  else
  {
    output->GetPointData()->SetScalars(combined);
  }

  // this rank's piece of the grid
  const int piece = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    : 0;
  const int pieces = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    : 1;
  if (pieces > 1)
  {
    vtkNew<vtkExtentTranslator> translator;
    int whole[6], extent[6];
    output->GetExtent(whole);
    translator->PieceToExtentThreadSafe(
      piece, pieces, 0, whole, extent, vtkExtentTranslator::BLOCK_MODE, 0);
    output->Crop(extent);
  }
  return 1;
}

void vtkPlumePGaussianSplatter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
}
