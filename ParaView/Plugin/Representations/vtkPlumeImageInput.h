/**
 * @class   vtkPlumeImageInput
 * @brief   the image a Plume representation draws, from what ParaView hands it
 *
 * ParaView gives representations a vtkImageData or a composite dataset
 * (multiblock, partitioned). Plume's image mappers draw one image: this
 * takes the image itself, or the first non-empty image leaf of a composite
 * (warning through `owner` when a rank holds more than one), shallow-copied
 * with cells marked as ghosts cropped away (pieces of a distributed image
 * then meet without overlap). Other datasets give nullptr.
 */
#ifndef vtkPlumeImageInput_h
#define vtkPlumeImageInput_h

#include "vtkSmartPointer.h" // For vtkSmartPointer

class vtkAlgorithm;
class vtkDataObject;
class vtkImageData;

class vtkPlumeImageInput
{
public:
  static vtkSmartPointer<vtkImageData> Extract(vtkDataObject* input, vtkAlgorithm* owner);
};

#endif
// VTK-HeaderTest-Exclude: vtkPlumeImageInput.h
