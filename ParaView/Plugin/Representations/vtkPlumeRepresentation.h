/**
 * @class   vtkPlumeRepresentation
 * @brief   what every Plume ParaView representation shares: one prop in the render view, one piece per rank
 *
 * A subclass prepares this rank's piece in RequestData (Cache, DataBounds),
 * sets the prop it draws (Prop: an actor or a volume) in its constructor and
 * hands the delivered piece to its mapper in PrepareRender. This class
 * answers the view's requests: the piece and its bounds on update,
 * distributed rendering on every rank, and, for media that blend over what
 * is behind them (OrderedCompositing), the view's ordered compositing by
 * these local bounds; opaque geometry composites by depth.
 */
#ifndef vtkPlumeRepresentation_h
#define vtkPlumeRepresentation_h

#include "PlumeParaViewRepresentationsModule.h" // For export macro
#include "vtkPVDataRepresentation.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

class vtkDataObject;
class vtkProp3D;

class PLUMEPARAVIEWREPRESENTATIONS_EXPORT vtkPlumeRepresentation : public vtkPVDataRepresentation
{
public:
  vtkTypeMacro(vtkPlumeRepresentation, vtkPVDataRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;
  void SetVisibility(bool visible) override;

protected:
  vtkPlumeRepresentation();
  ~vtkPlumeRepresentation() override;

  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;

  /** At REQUEST_RENDER: give `piece` (may be null) to the mapper; true if there is something to draw. */
  virtual bool PrepareRender(vtkDataObject* piece) = 0;

  vtkSmartPointer<vtkProp3D> Prop;     // the actor or volume the view draws
  vtkSmartPointer<vtkDataObject> Cache; // this rank's piece (RequestData)
  double DataBounds[6];                 // its bounds, uninitialised without one
  bool OrderedCompositing = false;      // blend ranks back to front (media) instead of by depth

private:
  vtkPlumeRepresentation(const vtkPlumeRepresentation&) = delete;
  void operator=(const vtkPlumeRepresentation&) = delete;
};

#endif
