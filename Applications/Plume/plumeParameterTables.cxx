#include "plumeParameterTables.h"

#include "vtkPlumeAirlightPass.h"
#include "vtkPlumeDerivedGeometry.h"
#include "vtkPlumeGaussianSplatter.h"
#include "vtkPlumeParameterTable.h"
#include "vtkPlumeSheetMapper.h"
#include "vtkPlumeSmokeSolver.h"
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkPlumeVolumeMapper.h"

namespace plume
{
const std::vector<const vtkPlumeParameterTable*>& ParameterTables()
{
  static const std::vector<const vtkPlumeParameterTable*> tables = {
    &vtkPlumeGaussianSplatter::GetParameterTable(),
    &vtkPlumeSmokeSolver::GetParameterTable(),
    &vtkPlumeDerivedGeometry::GetParameterTable(),
    &vtkPlumeVelocityGlyphMapper::GetParameterTable(),
    &vtkPlumeVolumeMapper::GetParameterTable(),
    &vtkPlumeSheetMapper::GetParameterTable(),
    &vtkPlumeAirlightPass::GetParameterTable(),
  };
  return tables;
}
}
