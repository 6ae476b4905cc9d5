#include "plumeParameterTables.h"

#include "vtkPlumeParameterTable.h"
#include "vtkPlumeSheetMapper.h"

namespace plume
{
const std::vector<const vtkPlumeParameterTable*>& ParameterTables()
{
  static const std::vector<const vtkPlumeParameterTable*> tables = {
    &vtkPlumeSheetMapper::GetParameterTable(),
  };
  return tables;
}
}
