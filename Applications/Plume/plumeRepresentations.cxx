// The representation types of a scene: each reads and checks all its
// parameters first (so typos fail before slow work), then builds its props.
#include "plumeColorMaps.h"
#include "plumeRepresentationHelpers.h"
#include "plumeParameters.h"
#include "plumeScene.h"
#include "plumeSceneError.h"

#include "vtkPlumeDerivedGeometry.h"
#include "vtkPlumeInputValidation.h"
#include "vtkPlumeParameterTable.h"
#include "vtkPlumeVelocityGlyphMapper.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkContourFilter.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkImageData.h"
#include "vtkOutlineFilter.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace plume
{
namespace
{

void BuildGlyphs(Parameters& p, SceneDatasets& datasets, vtkRenderer* renderer)
{
  const std::string dataset = p.String("dataset", "");
  const nlohmann::json* seedPlane = p.Object("seed_plane");
  const std::string seedDataset = p.String("seed_dataset", "");
  // the mapper's own parameters (roots, scale, integrator, ...) come from its table
  vtkNew<vtkPlumeVelocityGlyphMapper> mapper;
  p.Apply(vtkPlumeVelocityGlyphMapper::GetParameterTable(), mapper);
  if (p.Has("scale") && !p.Has("scale_mode"))
  {
    // a scene that gives a scale means it (the table's default mode is auto)
    mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
  }
  const int roots = mapper->GetRootMode();
  const std::string rootsName = mapper->GetParameterTable().Find("roots")->FindOption(roots)->Key;
  const std::string colorBy = p.Choice("color_by", "magnitude", { "magnitude", "solid" });
  Coloring coloring;
  coloring.Read(p, { 1, 1, 1 });
  coloring.ReadLegend(p);
  p.RejectUnknown();
  if (dataset.empty())
  {
    throw SceneError(p.Where() + ": 'dataset' is required");
  }
  if (roots == vtkPlumeVelocityGlyphMapper::ROOTS_SEEDS && !seedPlane && seedDataset.empty())
  {
    throw SceneError(p.Where() + ": roots \"seeds\" needs 'seed_plane' or 'seed_dataset'");
  }
  if (seedPlane && !seedDataset.empty())
  {
    throw SceneError(p.Where() + ": give 'seed_plane' or 'seed_dataset', not both");
  }
  if ((seedPlane || !seedDataset.empty()) && roots != vtkPlumeVelocityGlyphMapper::ROOTS_SEEDS)
  {
    throw SceneError(p.Where() + ": '" + std::string(seedPlane ? "seed_plane" : "seed_dataset") +
      "' is used only with roots \"seeds\" (roots is \"" + rootsName + "\")");
  }

  vtkImageData* image = datasets.GetImage(dataset, p.Where());
  vtkDataArray* array = RequirePointArray(image, mapper->GetVectorArrayName(), 3, p.Where(), dataset);

  mapper->SetInputData(image);
  mapper->SetVectorArrayName(array->GetName() ? array->GetName() : "");
  if (roots == vtkPlumeVelocityGlyphMapper::ROOTS_SEEDS)
  {
    if (seedPlane)
    {
      Parameters sp(*seedPlane, p.Where() + ".seed_plane");
      vtkNew<vtkPlaneSource> plane;
      plane->SetOrigin(sp.Vector<3>("origin", { 0, 0, 0 }).data());
      plane->SetPoint1(sp.Vector<3>("point1", { 1, 0, 0 }).data());
      plane->SetPoint2(sp.Vector<3>("point2", { 0, 1, 0 }).data());
      const auto res = sp.Vector<2>("resolution", { 20, 20 });
      sp.RejectUnknown();
      for (double r : res)
      {
        if (r < 1 || r > 4096 || r != std::floor(r))
        {
          throw SceneError(sp.Where() + ": 'resolution' must be two integers in [1, 4096], got " +
            std::to_string(r));
        }
      }
      plane->SetResolution(int(res[0]), int(res[1]));
      plane->Update();
      mapper->SetSeedData(plane->GetOutput());
    }
    else
    {
      mapper->SetSeedData(RequireDataSet(datasets.Get(seedDataset, p.Where()), p.Where(), seedDataset));
    }
  }
  if (mapper->GetScaleMode() == vtkPlumeVelocityGlyphMapper::SCALE_AUTO)
  {
    std::ostringstream line;
    // screen roots: the stride, and so the scale, is the frame's (known at render)
    const bool screen = mapper->GetRootMode() == vtkPlumeVelocityGlyphMapper::ROOTS_SCREEN_ADAPTIVE;
    line << p.Where() << ": scale "
         << (screen ? mapper->GetAutomaticScale(1) : mapper->GetEffectiveScale())
         << (screen ? " x the screen-adaptive root stride" : "")
         << " (auto: a glyph at the robust maximum speed " << mapper->GetRobustMaximumSpeed()
         << " spans about two root spacings; set 'scale' to choose)";
    Note(line.str());
  }
  mapper->SetColorByMagnitude(colorBy == "magnitude");
  if (colorBy == "magnitude")
  {
    // nodes outside resampled data are not part of the default range
    auto table = coloring.Table(array, -1, image->GetPointData()->GetArray(mapper->GetValidMaskArrayName()));
    mapper->SetLookupTable(table);
    mapper->SetUseDataRange(false);
    mapper->SetScalarRange(table->GetRange());
    coloring.AddLegend(renderer, table, "|" + std::string(array->GetName() ? array->GetName() : "") + "|");
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(coloring.Color[0], coloring.Color[1], coloring.Color[2]);
  renderer->AddActor(actor);
}

void AddPolyActor(vtkAlgorithmOutput* port, vtkDataSet* sample, const std::string& arrayName, const Coloring& coloring,
  double opacity, const std::string& where, const std::string& dataset, vtkRenderer* renderer, bool wireframe = false)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(port);
  if (!arrayName.empty())
  {
    vtkDataArray* array = RequirePointArray(sample, arrayName, 0, where, dataset);
    const int component = array->GetNumberOfComponents() == 1 ? 0 : -1;
    auto table = coloring.Table(array, component);
    mapper->SetLookupTable(table);
    mapper->SetScalarModeToUsePointFieldData();
    mapper->SelectColorArray(arrayName.c_str());
    mapper->SetScalarRange(table->GetRange());
    mapper->ScalarVisibilityOn();
    coloring.AddLegend(renderer, table, component < 0 ? "|" + arrayName + "|" : arrayName);
  }
  else
  {
    mapper->ScalarVisibilityOff();
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(coloring.Color[0], coloring.Color[1], coloring.Color[2]);
  actor->GetProperty()->SetOpacity(opacity);
  if (wireframe)
  {
    actor->GetProperty()->SetRepresentationToWireframe();
  }
  renderer->AddActor(actor);
}

// A surface's or contour's own size against the memory budget, before
// anything is drawn: the check when a dataset is read bounds it only loosely
// (up to 6 faces per cell; a contour up to 5 triangles per cell and value).
// Counted as the filter's output plus what the mapper uploads (point, normal
// and colour per point: 28 bytes; three 4-byte indices per triangle).
void CheckPolyBudget(vtkPolyDataAlgorithm* filter, const std::string& where, const std::string& dataset,
  const char* noun)
{
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  double triangles = 0;
  for (vtkCellArray* cells : { out->GetPolys(), out->GetStrips() })
  {
    for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
    {
      triangles += std::max<vtkIdType>(cells->GetCellSize(c) - 2, 0);
    }
  }
  const double points = static_cast<double>(out->GetNumberOfPoints());
  const double bytes = 1024.0 * static_cast<double>(out->GetActualMemorySize()) + 28.0 * points + 12.0 * triangles;
  std::ostringstream what;
  what << "dataset '" << dataset << "': the " << noun << "'s " << static_cast<long long>(triangles) << " triangles and "
       << static_cast<long long>(points) << " points";
  const std::string tooBig = vtkPlumeInputValidation::CheckMemory(bytes, what.str());
  if (!tooBig.empty())
  {
    throw SceneError(where + ": " + tooBig);
  }
}

void BuildSurface(Parameters& p, SceneDatasets& datasets, vtkRenderer* renderer)
{
  const std::string dataset = p.String("dataset", "");
  const std::string colorArray = p.String("color_array", "");
  const double opacity = p.Number("opacity", 1.0, 0.0, 1.0);
  const bool wireframe = p.Boolean("wireframe", false);
  // "cell": colour each cell by its own value (finite-volume data), no interpolation
  const std::string association = p.Choice("association", "point", { "point", "cell" });
  Coloring coloring;
  coloring.Read(p, { 0.8, 0.8, 0.8 });
  coloring.ReadLegend(p);
  p.RejectUnknown();
  if (association == "cell")
  {
    vtkDataSet* cells = RequireDataSet(datasets.Get(dataset, p.Where()), p.Where(), dataset);
    if (colorArray.empty())
    {
      throw SceneError(p.Where() + ": 'association' \"cell\" needs a 'color_array' (a cell array)");
    }
    vtkDataArray* array = cells->GetCellData()->GetArray(colorArray.c_str());
    if (!array)
    {
      std::string names;
      for (int i = 0; i < cells->GetCellData()->GetNumberOfArrays(); ++i)
      {
        const char* n = cells->GetCellData()->GetArrayName(i);
        names += (names.empty() ? "" : ", ") + std::string(n ? n : "");
      }
      throw SceneError(p.Where() + ": dataset '" + dataset + "' has no cell array '" + colorArray +
        "' (cell arrays: " + (names.empty() ? "none" : names) + ")");
    }
    vtkNew<vtkDataSetSurfaceFilter> surface;
    surface->SetInputData(cells);
    CheckPolyBudget(surface, p.Where(), dataset, "surface");
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(surface->GetOutputPort());
    const int component = array->GetNumberOfComponents() == 1 ? 0 : -1;
    auto table = coloring.Table(array, component);
    mapper->SetLookupTable(table);
    mapper->SetScalarModeToUseCellFieldData();
    mapper->SelectColorArray(colorArray.c_str());
    mapper->SetScalarRange(table->GetRange());
    mapper->ScalarVisibilityOn();
    coloring.AddLegend(renderer, table, component < 0 ? "|" + colorArray + "|" : colorArray);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetOpacity(opacity);
    if (wireframe)
    {
      actor->GetProperty()->SetRepresentationToWireframe();
    }
    renderer->AddActor(actor);
    return;
  }
  vtkSmartPointer<vtkDataSet> data =
    WithPointArrays(RequireDataSet(datasets.Get(dataset, p.Where()), p.Where(), dataset), { colorArray });
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(data);
  CheckPolyBudget(surface, p.Where(), dataset, "surface");
  AddPolyActor(surface->GetOutputPort(), data, colorArray, coloring, opacity, p.Where(), dataset, renderer, wireframe);
}

void BuildContour(Parameters& p, SceneDatasets& datasets, vtkRenderer* renderer)
{
  const std::string dataset = p.String("dataset", "");
  const std::string arrayName = p.String("array", "");
  const nlohmann::json* values = p.Raw("values");
  const std::string colorArray = p.String("color_array", "");
  const double opacity = p.Number("opacity", 1.0, 0.0, 1.0);
  Coloring coloring;
  coloring.Read(p, { 0.9, 0.85, 0.7 });
  coloring.ReadLegend(p);
  p.RejectUnknown();
  if (!values || !values->is_array() || values->empty())
  {
    throw SceneError(p.Where() + ": 'values' must be a non-empty list of iso values");
  }
  vtkSmartPointer<vtkDataSet> data = WithPointArrays(
    RequireDataSet(datasets.Get(dataset, p.Where()), p.Where(), dataset), { arrayName, colorArray });
  vtkDataArray* array = RequirePointArray(data, arrayName, 1, p.Where(), dataset);
  const std::string tooMuch = vtkPlumeDerivedGeometry::CheckContourWork(data->GetNumberOfCells(), values->size());
  if (!tooMuch.empty())
  {
    throw SceneError(p.Where() + ": dataset '" + dataset + "': " + tooMuch);
  }
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(data);
  contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, array->GetName());
  int i = 0;
  for (const auto& v : *values)
  {
    if (!v.is_number() || !std::isfinite(v.get<double>()))
    {
      throw SceneError(p.Where() + ": 'values' must hold finite numbers, got " + v.dump());
    }
    contour->SetValue(i++, v.get<double>());
  }
  contour->SetComputeScalars(!colorArray.empty());
  CheckPolyBudget(contour, p.Where(), dataset, "contour");
  AddPolyActor(contour->GetOutputPort(), data, colorArray, coloring, opacity, p.Where(), dataset, renderer);
}

void BuildOutline(Parameters& p, SceneDatasets& datasets, vtkRenderer* renderer)
{
  const std::string dataset = p.String("dataset", "");
  const double lineWidth = p.Number("line_width", 1.0, 0.5, 64.0);
  Coloring coloring;
  coloring.Read(p, { 1, 1, 1 });
  p.RejectUnknown();
  vtkDataSet* data = RequireDataSet(datasets.Get(dataset, p.Where()), p.Where(), dataset);
  vtkNew<vtkOutlineFilter> outline;
  outline->SetInputData(data);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(outline->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(coloring.Color[0], coloring.Color[1], coloring.Color[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(lineWidth));
  actor->GetProperty()->LightingOff();
  renderer->AddActor(actor);
}

void BuildSphere(Parameters& p, SceneDatasets&, vtkRenderer* renderer)
{
  const auto center = p.Vector<3>("center", { 0, 0, 0 });
  const double radius = p.Number("radius", 1.0, 0.0);
  const int resolution = p.Integer("resolution", 48, 3, 1024);
  const double opacity = p.Number("opacity", 1.0, 0.0, 1.0);
  Coloring coloring;
  coloring.Read(p, { 0.85, 0.3, 0.2 });
  p.RejectUnknown();
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(center.data());
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution / 2 + 2);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(coloring.Color[0], coloring.Color[1], coloring.Color[2]);
  actor->GetProperty()->SetOpacity(opacity);
  renderer->AddActor(actor);
}

}

void RegisterCoreRepresentations(std::map<std::string, RepresentationBuilder>& builders)
{
  builders["glyphs"] = BuildGlyphs;
  builders["surface"] = BuildSurface;
  builders["contour"] = BuildContour;
  builders["outline"] = BuildOutline;
  builders["sphere"] = BuildSphere;
}

}
