// The executive a Plume algorithm that reports its own one-line errors uses:
// VTK's composite-data pipeline with its "returned failure for request" dump
// swallowed (the algorithm has already said what went wrong); every other
// error reaches the output window as usual. Shared by the dataset reader and
// the smoke solver.
#ifndef vtkPlumeQuietExecutive_h
#define vtkPlumeQuietExecutive_h

#include "PlumeCoreModule.h" // For export macro

class vtkExecutive;

namespace plume
{
/** A new vtkCompositeDataPipeline (caller owns the reference, as CreateDefaultExecutive wants). */
PLUMECORE_EXPORT vtkExecutive* NewQuietExecutive();
}

#endif
// VTK-HeaderTest-Exclude: vtkPlumeQuietExecutive.h
