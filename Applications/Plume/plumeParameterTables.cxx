#include "plumeParameterTables.h"

#include "vtkPlumeDerivedGeometry.h"
#include "vtkPlumeParameterTable.h"
#include "vtkPlumeSheetMapper.h"
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkPlumeVolumeMapper.h"

namespace plume
{
const std::vector<const vtkPlumeParameterTable*>& ParameterTables()
{
  static const std::vector<const vtkPlumeParameterTable*> tables = {
    &vtkPlumeVelocityGlyphMapper::GetParameterTable(),
    &vtkPlumeVolumeMapper::GetParameterTable(),
    &vtkPlumeSheetMapper::GetParameterTable(),
    &vtkPlumeDerivedGeometry::GetParameterTable(),
  };
  return tables;
}
}
