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
  this->Prop = this->Actor;
  // the smoke blends over what is behind it: ranks composite back to front
  this->OrderedCompositing = true;
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
  vtkNew<vtkPolyData> cache;
  this->Cache = cache;
  if (inputVector[0]->GetNumberOfInformationObjects() == 1)
  {
    vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
    if (auto* poly = vtkPolyData::SafeDownCast(input))
    {
      cache->ShallowCopy(poly);
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
        cache->ShallowCopy(append->GetOutput());
      }
    }
    // Cells another rank owns (ghost cells, e.g. the seam layer of a
    // contour of image slabs) stay in the mesh: the mapper skips cells
    // flagged DUPLICATECELL or HIDDENCELL itself (TestSheetGhostCells).
    if (cache->GetNumberOfPoints() > 0)
    {
      cache->GetBounds(this->DataBounds);
    }
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

bool vtkPlumeSheetRepresentation::PrepareRender(vtkDataObject* piece)
{
  this->Mapper->SetInputDataObject(piece);
  auto* poly = vtkPolyData::SafeDownCast(piece);
  return poly && poly->GetNumberOfCells() > 0;
}

void vtkPlumeSheetRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mapper: " << this->Mapper.Get() << "\n";
}
