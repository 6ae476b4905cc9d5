// The `volume` representation: a vtkPlumeVolumeMapper on a vtkVolume, with
// the transfer functions and modes of Documentation/SceneFormat.md.
#include "plumeParameters.h"
#include "plumeRepresentationHelpers.h"
#include "plumeScene.h"
#include "plumeSceneError.h"

#include "vtkPlumeVolumeMapper.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace plume
{
namespace
{
void BuildVolume(Parameters& p, SceneDatasets& datasets, vtkRenderer* renderer)
{
  const std::string dataset = p.String("dataset", "");
  const std::string arrayName = p.String("array", "");
  // the mapper's own parameters (mode, iso_value, steps, jitter, opacity_unit_distance, ...)
  // come from its table; its defaults (one voxel as the opacity unit distance, the middle
  // of the colour map as the iso value) are the library's, and it warns about an iso value
  // outside the data
  vtkNew<vtkPlumeVolumeMapper> mapper;
  p.Apply(vtkPlumeVolumeMapper::GetParameterTable(), mapper);
  Coloring coloring;
  coloring.Read(p, { 1, 1, 1 });
  coloring.ReadLegend(p);
  const bool solid = p.Boolean("solid_color", false);
  const nlohmann::json* opacityPoints = p.Raw("opacity");
  // the mapper's lighting for its mode (smoke is lit more evenly); the scene may override each value
  vtkNew<vtkVolume> volume;
  vtkVolumeProperty* property = volume->GetProperty();
  mapper->ApplyDefaultLighting(property);
  // the opacity unit distance: the mapper's opacity_unit_distance if set,
  // else automatic (one voxel), never VTK's default of one world unit
  property->SetScalarOpacityUnitDistance(0.0);
  property->SetAmbient(p.Number("ambient", property->GetAmbient(), 0.0, 10.0));
  property->SetDiffuse(p.Number("diffuse", property->GetDiffuse(), 0.0, 10.0));
  property->SetSpecular(p.Number("specular", property->GetSpecular(), 0.0, 10.0));
  property->SetSpecularPower(p.Number("specular_power", property->GetSpecularPower(), 1.0, 1000.0));
  p.RejectUnknown();
  if (dataset.empty())
  {
    throw SceneError(p.Where() + ": 'dataset' is required");
  }

  vtkImageData* image = datasets.GetImage(dataset, p.Where());
  // the scene's memory budget (PLUME_MEMORY_BUDGET_MB) bounds the volume's 3D
  // texture too, unless the scene set the mapper's own: refused before rendering
  if (!(mapper->GetTextureMemoryBudgetMB() > 0))
  {
    mapper->SetTextureMemoryBudgetMB(MemoryBudgetBytes() / (1 << 20));
  }
  {
    int dims[3];
    image->GetDimensions(dims);
    const std::string over = vtkPlumeVolumeMapper::CheckTextureBudget(dims,
      image->GetPointData()->GetArray(mapper->GetValidMaskArrayName()) != nullptr, false,
      mapper->GetTextureMemoryBudgetMB());
    if (!over.empty())
    {
      throw SceneError(p.Where() + ": dataset '" + dataset + "': " + over +
        " (image_dimension), or raise PLUME_MEMORY_BUDGET_MB");
    }
  }
  vtkDataArray* array = RequirePointArray(image, arrayName, 0, p.Where(), dataset);
  const int component = mapper->GetScalarComponent();
  if (component >= array->GetNumberOfComponents())
  {
    throw SceneError(p.Where() + ": 'component' " + std::to_string(component) + " but array '" +
      (array->GetName() ? array->GetName() : "") + "' has " +
      std::to_string(array->GetNumberOfComponents()) + " component(s)");
  }
  const int rangeComponent = component >= 0 ? component : (array->GetNumberOfComponents() == 1 ? 0 : -1);
  // resampled data: the nodes outside it are left out of the range (the mapper draws nothing there)
  vtkDataArray* mask = image->GetPointData()->GetArray(mapper->GetValidMaskArrayName());
  auto table = coloring.Table(array, rangeComponent, mask);
  if (mask && mask->GetNumberOfComponents() == 1)
  {
    vtkIdType valid = 0;
    for (vtkIdType i = 0; i < mask->GetNumberOfTuples(); ++i)
    {
      valid += mask->GetComponent(i, 0) != 0.0 ? 1 : 0;
    }
    if (valid * 100 < mask->GetNumberOfTuples())
    {
      // e.g. a surface mesh: resampling finds almost no point inside its cells
      std::cerr << "plume: warning: " << p.Where() << ": only " << valid << " of " << mask->GetNumberOfTuples()
                << " resampled points of dataset '" << dataset
                << "' lie inside its cells (a surface or very thin data has no volume); little will show\n";
    }
  }
  const double* range = table->GetRange();
  if (!solid)
  {
    const std::string name = array->GetName() ? array->GetName() : "";
    coloring.AddLegend(renderer, table,
      rangeComponent >= 0 || array->GetNumberOfComponents() == 1 ? name : "|" + name + "|");
  }

  vtkNew<vtkColorTransferFunction> color;
  for (int i = 0; i < 64; ++i)
  {
    const double v = range[0] + (range[1] - range[0]) * i / 63.0;
    double rgb[3] = { coloring.Color[0], coloring.Color[1], coloring.Color[2] };
    if (!solid)
    {
      table->GetColor(v, rgb);
    }
    color->AddRGBPoint(v, rgb[0], rgb[1], rgb[2]);
  }
  vtkNew<vtkPiecewiseFunction> opacity;
  if (opacityPoints)
  {
    if (!opacityPoints->is_array() || opacityPoints->empty())
    {
      throw SceneError(p.Where() + ": 'opacity' must be a non-empty list of [value, opacity] pairs");
    }
    for (const auto& point : *opacityPoints)
    {
      if (!point.is_array() || point.size() != 2 || !point[0].is_number() || !point[1].is_number() ||
        !std::isfinite(point[0].get<double>()) || !(point[1].get<double>() >= 0 && point[1].get<double>() <= 1))
      {
        throw SceneError(p.Where() + ": 'opacity' entries must be [finite value, opacity in 0..1], got " +
          point.dump());
      }
      opacity->AddPoint(point[0].get<double>(), point[1].get<double>());
    }
  }
  else
  {
    opacity->AddPoint(range[0], 0.0);
    opacity->AddPoint(range[1], 1.0);
  }
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetInterpolationTypeToLinear();

  mapper->SetInputData(image);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectScalarArray(array->GetName());
  volume->SetMapper(mapper);
  renderer->AddVolume(volume);
}
}

void RegisterVolumeRepresentations(std::map<std::string, RepresentationBuilder>& builders)
{
  builders["volume"] = BuildVolume;
}
}
