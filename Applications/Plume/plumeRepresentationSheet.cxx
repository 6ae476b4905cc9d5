// The `sheet` representation: a triangle mesh drawn as volumetric Gaussian
// smoke by vtkPlumeSheetMapper (seed 000), with every parameter of
// Documentation/SceneFormat.md (declared once, in the mapper's parameter
// table).
#include "plumeParameters.h"
#include "plumeRepresentationHelpers.h"
#include "plumeScene.h"
#include "plumeSceneError.h"

#include "vtkPlumeSheetMapper.h"

#include "vtkActor.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"

#include <array>

namespace plume
{
namespace
{
void BuildSheet(Parameters& p, SceneDatasets& datasets, vtkRenderer* renderer)
{
  const std::string dataset = p.String("dataset", "");
  // every mapper parameter comes from the mapper's own table
  vtkNew<vtkPlumeSheetMapper> mapper;
  const bool colorGiven = p.Has("smoke_color");
  p.Apply(vtkPlumeSheetMapper::GetParameterTable(), mapper);
  p.RejectUnknown();
  if (!colorGiven)
  {
    // The mapper's default smoke only absorbs (black): on the scene's default
    // dark background it drew nothing visible. Light smoke there, absorbing
    // smoke on a light background (where the overlay text is dark too).
    const std::array<double, 3> behind = BackgroundAt(renderer, 0.5);
    if (TextColorOn(behind.data())[0] > 0.5)
    {
      const double light[3] = { 0.85, 0.85, 0.88 };
      mapper->SetSmokeColor(light);
      Note(p.Where() + ": smoke_color [0.85, 0.85, 0.88] (light smoke on the dark background; set 'smoke_color' "
                       "to choose)");
    }
  }
  if (dataset.empty())
  {
    throw SceneError(p.Where() + ": 'dataset' is required");
  }
  vtkDataSet* data = RequireDataSet(datasets.Get(dataset, p.Where()), p.Where(), dataset);
  vtkSmartPointer<vtkPolyData> mesh = vtkPolyData::SafeDownCast(data);
  if (!mesh)
  {
    vtkNew<vtkDataSetSurfaceFilter> surface; // e.g. an unstructured grid of triangles
    surface->SetInputData(data);
    surface->Update();
    mesh = surface->GetOutput();
  }
  if (mesh->GetNumberOfPolys() + mesh->GetNumberOfStrips() < 1)
  {
    throw SceneError(p.Where() + ": dataset '" + dataset + "' has no polygons or triangle strips" +
      (mesh->GetNumberOfLines() > 0 ? " (it holds " + std::to_string(mesh->GetNumberOfLines()) +
            " lines; a sheet needs a surface: derive a 'stream_surface' or 'ribbon')"
                                    : std::string()));
  }
  const std::pair<std::string, int> arrays[4] = { { mapper->GetDensityArrayName(), 1 },
    { mapper->GetBlurArrayName(), 1 }, { mapper->GetThicknessArrayName(), 1 }, { mapper->GetAbsorptionArrayName(), 3 } };
  for (const auto& a : arrays)
  {
    if (!a.first.empty())
    {
      RequirePointArray(mesh, a.first, a.second, p.Where(), dataset);
    }
  }

  const std::string overBudget = mapper->CheckBudget(mesh);
  if (!overBudget.empty())
  {
    throw SceneError(p.Where() + ": dataset '" + dataset + "': " + overBudget);
  }
  mapper->SetInputData(mesh);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
}
}

void RegisterSheetRepresentations(std::map<std::string, RepresentationBuilder>& builders)
{
  builders["sheet"] = BuildSheet;
}
}
