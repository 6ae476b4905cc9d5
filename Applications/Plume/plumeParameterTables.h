// The parameter tables of the classes the scene format exposes (dataset
// sources, derived datasets, representations, the medium), in the
// order Documentation/SceneFormat.md lists them (`plume params`).
#ifndef plumeParameterTables_h
#define plumeParameterTables_h

#include <vector>

class vtkPlumeParameterTable;

namespace plume
{
/** Every renderer table a scene representation applies. */
const std::vector<const vtkPlumeParameterTable*>& ParameterTables();
}

#endif
