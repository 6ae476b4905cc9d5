#include "plumeParameterTables.h"

#include "vtkPlumeParameterTable.h"
#include "vtkPlumeSheetMapper.h"
#include "vtkPlumeVolumeMapper.h"

namespace plume
{
const std::vector<const vtkPlumeParameterTable*>& ParameterTables()
{
  static const std::vector<const vtkPlumeParameterTable*> tables = {
    &vtkPlumeVolumeMapper::GetParameterTable(),
    &vtkPlumeSheetMapper::GetParameterTable(),
  };
  return tables;
}
}
