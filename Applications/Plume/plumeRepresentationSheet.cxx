// The `sheet` representation: a triangle mesh drawn as volumetric Gaussian
// smoke by vtkPlumeSheetMapper (seed 000), with every parameter of
// Documentation/SceneFormat.md. Put it after the opaque representations it
// overlaps: it integrates up to the depth they leave.
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

namespace plume
{
namespace
{
void BuildSheet(Parameters& p, SceneDatasets& datasets, vtkRenderer* renderer)
{
  const std::string dataset = p.String("dataset", "");
  const std::string densityArray = p.String("density_array", "");
  const double density = p.Number("density", 1.0, 0.0, 1e30);
  const double densityScale = p.Number("density_scale", 1.0, 0.0, 1e30);
  const std::string blurArray = p.String("blur_array", "");
  const double blur = p.Number("blur", 0.05, 0.0, vtkPlumeSheetMapper::MaximumSigma);
  const std::string thicknessArray = p.String("thickness_array", "");
  const double thickness = p.Number("thickness", 0.05, 0.0, vtkPlumeSheetMapper::MaximumSigma);
  const std::string absorptionArray = p.String("absorption_array", "");
  const auto smokeColor = p.Vector<3>("smoke_color", { 0, 0, 0 });
  const bool thin = p.Boolean("thin", false);
  const bool bounded = p.Boolean("opaque_depth", true);
  const double cutoff = p.Number("cutoff", 3.5, 1.0, 10.0);
  const double minSigma = p.Number("min_sigma_pixels", 1.0 / 3.0, 0.0, 100.0);
  const std::string quadrature = p.Choice("quadrature", "analytic", { "analytic", "grid" });
  const auto grid = p.Vector<2>("grid", { 8, 5 });
  p.RejectUnknown();
  if (dataset.empty())
  {
    throw SceneError(p.Where() + ": 'dataset' is required");
  }
  for (int i = 0; i < 2; ++i)
  {
    if (!(grid[i] >= 1 && grid[i] <= 32) || grid[i] != static_cast<int>(grid[i]))
    {
      throw SceneError(p.Where() + ": 'grid' entries must be whole numbers in 1..32");
    }
  }
  for (double c : smokeColor)
  {
    if (!(c >= 0 && c <= 1))
    {
      throw SceneError(p.Where() + ": 'smoke_color' entries must be in 0..1");
    }
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
    throw SceneError(p.Where() + ": dataset '" + dataset + "' has no polygons or triangle strips");
  }
  const std::pair<const std::string*, int> arrays[4] = { { &densityArray, 1 }, { &blurArray, 1 },
    { &thicknessArray, 1 }, { &absorptionArray, 3 } };
  for (const auto& a : arrays)
  {
    if (!a.first->empty())
    {
      RequirePointArray(mesh, *a.first, a.second, p.Where(), dataset);
    }
  }

  vtkNew<vtkPlumeSheetMapper> mapper;
  mapper->SetInputData(mesh);
  mapper->SetDensityArrayName(densityArray.c_str());
  mapper->SetDensity(density);
  mapper->SetDensityScale(densityScale);
  mapper->SetBlurArrayName(blurArray.c_str());
  mapper->SetBlurRadius(blur);
  mapper->SetThicknessArrayName(thicknessArray.c_str());
  mapper->SetThickness(thickness);
  mapper->SetAbsorptionArrayName(absorptionArray.c_str());
  mapper->SetSmokeColor(smokeColor[0], smokeColor[1], smokeColor[2]);
  mapper->SetThinSheet(thin);
  mapper->SetBoundedByDepth(bounded);
  mapper->SetCutoff(cutoff);
  mapper->SetMinimumSigmaPixels(minSigma);
  mapper->SetQuadrature(quadrature == "grid" ? vtkPlumeSheetMapper::QUADRATURE_GRID
                                             : vtkPlumeSheetMapper::QUADRATURE_ANALYTIC);
  mapper->SetGridA(static_cast<int>(grid[0]));
  mapper->SetGridB(static_cast<int>(grid[1]));
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
