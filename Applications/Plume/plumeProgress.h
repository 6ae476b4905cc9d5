// A progress bar on stderr for long VTK work; silent when stderr is not a terminal
// (PLUME_PROGRESS=1 forces it, 0 turns it off).
#ifndef plumeProgress_h
#define plumeProgress_h

#include <string>

class vtkAlgorithm;

namespace plume
{
/** True when progress should be drawn (stderr is a terminal, or PLUME_PROGRESS=1; not with PLUME_PROGRESS=0). */
bool ProgressEnabled();
/** Show `label` and the algorithm's ProgressEvent as a bar while it runs. */
void AttachProgress(vtkAlgorithm* algorithm, const std::string& label);
/** Draw a bar for `fraction` (0..1) of `label` now. */
void DrawProgress(const std::string& label, double fraction);
}

#endif
