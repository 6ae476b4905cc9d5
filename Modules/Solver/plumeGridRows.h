// The solvers' threaded loop over the rows (j, k) of a grid (internal).
#ifndef plumeGridRows_h
#define plumeGridRows_h

#include <functional>

namespace plume
{
namespace smoke
{
// Calls f(j, k) for every row of a grid with n[1] × n[2] rows of n[0] cells,
// threaded by vtkSMPTools. A row is one call, so a sum over rows that lands in
// its own slot and is added up in row order does not depend on the number of
// threads. Not a template: the solvers' many loop bodies share one
// vtkSMPTools::For instantiation (each backend's) instead of one per body,
// which cost a sixth of the smoke solver's compile under the sanitizers; an
// indirect call per row of n[0] cells costs nothing measurable.
void ForRows(const int n[3], const std::function<void(int, int)>& f);
}
}

#endif
