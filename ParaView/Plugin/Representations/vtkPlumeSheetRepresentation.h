/**
 * @class   vtkPlumeSheetRepresentation
 * @brief   ParaView representation "Plume Smoke Sheet": vtkPlumeSheetMapper on polygonal data
 *
 * Any polygonal input (stream surfaces, ribbons, contours; composite inputs
 * are appended into one mesh per rank) is drawn as volumetric Gaussian smoke.
 * The mapper is the proxy's "Mapper" subproxy (its properties are generated
 * from vtkPlumeSheetMapper's parameter table).
 *
 * In parallel each rank draws the triangles it holds. The smoke only
 * multiplies what is behind it by its transmittance T (and, with a smoke
 * colour, adds colour (1 - T)): with one smoke colour the product over the
 * ranks does not depend on their order, so the ranks' images are composited
 * in any order (the view's ordered compositing, asked for here, gives the
 * same).
 */
#ifndef vtkPlumeSheetRepresentation_h
#define vtkPlumeSheetRepresentation_h

#include "PlumeParaViewRepresentationsModule.h" // For export macro
#include "vtkPlumeRepresentation.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

class vtkActor;
class vtkPlumeSheetMapper;
class vtkPolyData;

class PLUMEPARAVIEWREPRESENTATIONS_EXPORT vtkPlumeSheetRepresentation : public vtkPlumeRepresentation
{
public:
  static vtkPlumeSheetRepresentation* New();
  vtkTypeMacro(vtkPlumeSheetRepresentation, vtkPlumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The mapper (the proxy's "Mapper" subproxy sets it). Default: one of its own. */
  void SetMapper(vtkPlumeSheetMapper* mapper);
  vtkPlumeSheetMapper* GetMapper();

protected:
  vtkPlumeSheetRepresentation();
  ~vtkPlumeSheetRepresentation() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool PrepareRender(vtkDataObject* piece) override;

  vtkSmartPointer<vtkPlumeSheetMapper> Mapper;
  vtkSmartPointer<vtkActor> Actor;

private:
  vtkPlumeSheetRepresentation(const vtkPlumeSheetRepresentation&) = delete;
  void operator=(const vtkPlumeSheetRepresentation&) = delete;
};

#endif
