// The one "ask for the whole input" request of Plume's image filters
// (vtkPlumeResampleToImage, vtkPlumeCellCenteredImage), whose output extents
// are not in the input's index space, so no part of the input can be chosen.
#ifndef vtkPlumeWholeInput_h
#define vtkPlumeWholeInput_h

class vtkInformation;

namespace plume
{
/**
 * In RequestUpdateExtent: replace the input's update extent with its whole
 * extent (`inInfo` is the input's information; nothing is set when it has no
 * whole extent, e.g. a data set that is not structured).
 */
void RequestWholeExtent(vtkInformation* inInfo);
}

#endif
