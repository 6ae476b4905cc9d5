#include "vtkPlumeRepresentation.h"

#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkPVRenderView.h"
#include "vtkProp3D.h"
#include "vtkRenderer.h"

vtkPlumeRepresentation::vtkPlumeRepresentation()
{
  vtkMath::UninitializeBounds(this->DataBounds);
}

vtkPlumeRepresentation::~vtkPlumeRepresentation() = default;

int vtkPlumeRepresentation::ProcessViewRequest(
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
    if (this->OrderedCompositing)
    {
      // the ranks' images blend front to back: the view sorts them by these local bounds
      outInfo->Set(vtkPVRenderView::NEED_ORDERED_COMPOSITING(), 1);
      vtkPVRenderView::SetOrderedCompositingConfiguration(
        inInfo, this, vtkPVRenderView::USE_BOUNDS_FOR_REDISTRIBUTION, this->DataBounds);
    }
    vtkPVRenderView::SetRequiresDistributedRendering(inInfo, this, true);
  }
  else if (request_type == vtkPVView::REQUEST_UPDATE_LOD())
  {
    vtkPVRenderView::SetRequiresDistributedRenderingLOD(inInfo, this, true);
  }
  else if (request_type == vtkPVView::REQUEST_RENDER())
  {
    const bool draw = this->PrepareRender(vtkPVView::GetDeliveredPiece(inInfo, this));
    this->Prop->SetVisibility(this->GetVisibility() && draw);
  }
  return 1;
}

bool vtkPlumeRepresentation::AddToView(vtkView* view)
{
  vtkPVRenderView* rview = vtkPVRenderView::SafeDownCast(view);
  if (!rview)
  {
    return false;
  }
  rview->GetRenderer()->AddViewProp(this->Prop);
  return this->Superclass::AddToView(view);
}

bool vtkPlumeRepresentation::RemoveFromView(vtkView* view)
{
  vtkPVRenderView* rview = vtkPVRenderView::SafeDownCast(view);
  if (!rview)
  {
    return false;
  }
  rview->GetRenderer()->RemoveViewProp(this->Prop);
  return this->Superclass::RemoveFromView(view);
}

void vtkPlumeRepresentation::SetVisibility(bool visible)
{
  this->Superclass::SetVisibility(visible);
  this->Prop->SetVisibility(visible);
}

void vtkPlumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OrderedCompositing: " << this->OrderedCompositing << "\n";
}
