/**
 * @class   vtkPlumeImageInput
 * @brief   the image a Plume representation draws, from what ParaView hands it
 *
 * ParaView gives representations a vtkImageData or a composite dataset
 * (multiblock, partitioned, overlapping or non-overlapping AMR). Plume's image
 * mappers draw one image of point data: this takes the image itself, or the
 * non-empty image leaves of a composite, each shallow-copied with cells
 * marked as ghosts cropped away (pieces of a distributed image then meet
 * without overlap). Several leaves on one rank are merged into one image
 * (vtkImageAppend, extents preserved) when they are pieces of one grid that
 * tile a box. Other pieces (AMR levels, blocks of different spacing or
 * origin, overlapping ones) are resampled onto one image over the union of
 * their bounds at the finest spacing among them (coarsened evenly when over
 * the memory budget, PLUME_MEMORY_BUDGET_MB), every sample from the finest
 * piece that contains it; samples no piece covers take the array's minimum.
 * The arrays common to all pieces become float point arrays:
 * - point arrays: trilinear, at the lattice's points;
 * - cell arrays (when there are any, e.g. an AMR source): the samples are
 *   then the centres of the lattice's cells, each taking the value of the
 *   cell that holds it (exact for nested AMR levels: no centre lies on a
 *   cell face), and point arrays are interpolated at those centres.
 * One image whose data are cell arrays only is resampled the same way (its
 * cell values at its cell centres). A warning through `owner` says what was
 * done. Other datasets give nullptr.
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
