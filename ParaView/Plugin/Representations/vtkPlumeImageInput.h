/**
 * @class   vtkPlumeImageInput
 * @brief   the image a Plume representation draws, from what ParaView hands it
 *
 * ParaView gives representations a vtkImageData or a composite dataset
 * (multiblock, partitioned). Plume's image mappers draw one image: this
 * takes the image itself, or the non-empty image leaves of a composite,
 * each shallow-copied with cells marked as ghosts cropped away (pieces of a
 * distributed image then meet without overlap). Several leaves on one rank
 * are merged into one image (vtkImageAppend, extents preserved) when they
 * are pieces of one grid that tile a box. Other pieces (AMR levels, blocks
 * of different spacing or origin, overlapping ones) are resampled onto one
 * image over the union of their bounds at the finest spacing among them
 * (coarsened evenly when over the memory budget, PLUME_MEMORY_BUDGET_MB):
 * each point takes the trilinear value of the finest piece that contains it,
 * points no piece covers the array's minimum; the point arrays common to all
 * pieces, as float. A warning through `owner` says what was done. Other
 * datasets give nullptr.
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
