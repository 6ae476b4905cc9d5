#include "vtkPlumeSheetRepresentation.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkPlumeSheetMapper.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkPlumeSheetRepresentation);

vtkPlumeSheetRepresentation::vtkPlumeSheetRepresentation()
  : Mapper(vtkSmartPointer<vtkPlumeSheetMapper>::New())
  , Actor(vtkSmartPointer<vtkActor>::New())
{
  this->Actor->SetMapper(this->Mapper);
  vtkMath::UninitializeBounds(this->DataBounds);
}

vtkPlumeSheetRepresentation::~vtkPlumeSheetRepresentation() = default;

void vtkPlumeSheetRepresentation::SetMapper(vtkPlumeSheetMapper* mapper)
{
  if (mapper && mapper != this->Mapper)
  {
    this->Mapper = mapper;
    this->Actor->SetMapper(mapper);
    this->Modified();
  }
}

vtkPlumeSheetMapper* vtkPlumeSheetRepresentation::GetMapper()
{
  return this->Mapper;
}

int vtkPlumeSheetRepresentation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkPlumeSheetRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkMath::UninitializeBounds(this->DataBounds);
  this->Cache = vtkSmartPointer<vtkPolyData>::New();
  if (inputVector[0]->GetNumberOfInformationObjects() == 1)
  {
    vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
    if (auto* poly = vtkPolyData::SafeDownCast(input))
    {
      this->Cache->ShallowCopy(poly);
    }
    else if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
    {
      // One mesh per rank: the mapper sorts nothing, so blocks can be merged.
      vtkNew<vtkAppendPolyData> append;
      vtkSmartPointer<vtkCompositeDataIterator> it;
      it.TakeReference(composite->NewIterator());
      for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      {
        if (auto* leaf = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
        {
          append->AddInputData(leaf);
        }
      }
      if (append->GetNumberOfInputConnections(0) > 0)
      {
        append->Update();
        this->Cache->ShallowCopy(append->GetOutput());
      }
    }
    if (this->Cache->GetNumberOfPoints() > 0)
    {
      this->Cache->GetBounds(this->DataBounds);
    }
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

int vtkPlumeSheetRepresentation::ProcessViewRequest(
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
    // The smoke blends over what is behind it: the ranks' images need
    // blending, not a depth test (ordered compositing does that).
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
    auto* poly = vtkPolyData::SafeDownCast(piece);
    this->Actor->SetVisibility(this->GetVisibility() && poly && poly->GetNumberOfCells() > 0);
  }
  return 1;
}

bool vtkPlumeSheetRepresentation::AddToView(vtkView* view)
{
  vtkPVRenderView* rview = vtkPVRenderView::SafeDownCast(view);
  if (rview)
  {
    rview->GetRenderer()->AddActor(this->Actor);
    return this->Superclass::AddToView(view);
  }
  return false;
}

bool vtkPlumeSheetRepresentation::RemoveFromView(vtkView* view)
{
  vtkPVRenderView* rview = vtkPVRenderView::SafeDownCast(view);
  if (rview)
  {
    rview->GetRenderer()->RemoveActor(this->Actor);
    return this->Superclass::RemoveFromView(view);
  }
  return false;
}

void vtkPlumeSheetRepresentation::SetVisibility(bool visible)
{
  this->Superclass::SetVisibility(visible);
  this->Actor->SetVisibility(visible);
}

void vtkPlumeSheetRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mapper: " << this->Mapper.Get() << "\n";
}
