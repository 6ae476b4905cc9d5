// The scene dataset `"source": "smoke"`: vtkPlumeSmokeSolver (seed 004's
// smoke simulation) run to the time step `step` through the pipeline's time
// request, as an image with velocity, density, temperature, pressure,
// divergence and obstacle. Every solver parameter comes from the solver's
// vtkPlumeParameterTable (same keys, types and ranges as the class); the
// lists `sources` and `obstacles` and `step` are read here. Documented in
// Documentation/SceneFormat.md.
#include "plumeParameters.h"
#include "plumeProgress.h"
#include "plumeScene.h"
#include "plumeSceneError.h"

#include "vtkPlumeDatasetReader.h"
#include "vtkPlumeParameterTable.h"
#include "vtkPlumeResampleToImage.h"
#include "vtkPlumeSmokeSolver.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkInformation.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtksys/SystemTools.hxx"

#include <cmath>

namespace plume
{
vtkSmartPointer<vtkPlumeSmokeSolver> ConfigureSmokeSolver(
  Parameters& p, SceneDatasets& datasets, const std::string& name, int& step)
{
  const std::string where = "datasets." + name;
  auto solver = vtkSmartPointer<vtkPlumeSmokeSolver>::New();
  p.Apply(vtkPlumeSmokeSolver::GetParameterTable(), solver);
  if (const nlohmann::json* dims = p.Has("dimensions") ? p.Raw("dimensions") : nullptr)
  {
    // the table takes a 3-vector; grid dimensions are whole numbers too
    for (const auto& d : *dims)
    {
      if (d.is_number() && d.get<double>() != std::floor(d.get<double>()))
      {
        throw SceneError(where + ": parameter 'dimensions' must be 3 integers in [1, 4096], got " + dims->dump());
      }
    }
  }

  // Virtual smoke in another dataset's flow: its velocity (resampled onto an
  // image if it is not one) drives passive smoke; the grid defaults to its grid.
  if (p.Has("velocity_dataset"))
  {
    const std::string flow = p.String("velocity_dataset", "");
    vtkImageData* image = datasets.GetImage(flow, where + ".velocity_dataset");
    if (!p.Has("dimensions") && !p.Has("origin") && !p.Has("spacing"))
    {
      int dims[3];
      image->GetDimensions(dims);
      solver->SetDimensions(dims);
      solver->SetOrigin(image->GetOrigin());
      solver->SetSpacing(image->GetSpacing());
    }
    solver->SetVelocityData(image);
  }

  // Virtual smoke in a time-varying flow: a series file read at the times
  // the steps need (its image grid by default), linear between written times.
  if (p.Has("velocity_series"))
  {
    if (p.Has("velocity_dataset"))
    {
      throw SceneError(where + ": give 'velocity_dataset' (a static flow) or 'velocity_series' (a time series), not both");
    }
    const std::string path = p.String("velocity_series", "");
    const std::string resolved = datasets.Resolve(path);
    if (!vtksys::SystemTools::FileExists(resolved))
    {
      throw SceneError(where + ": velocity_series: file not found: '" + path + "'");
    }
    auto reader = vtkSmartPointer<vtkPlumeDatasetReader>::New();
    reader->SetFileName(resolved.c_str());
    auto resample = vtkSmartPointer<vtkPlumeResampleToImage>::New();
    resample->SetInputConnection(reader->GetOutputPort());
    resample->SetMaximumDimension(p.Integer("velocity_series_dimension", 64, 2, 1024));
    resample->UpdateInformation();
    if (!reader->GetLastError().empty() || !resample->GetLastError().empty())
    {
      throw SceneError(where + ": velocity_series '" + path + "': " +
        (!reader->GetLastError().empty() ? reader->GetLastError() : resample->GetLastError()));
    }
    vtkInformation* info = resample->GetOutputInformation(0);
    if (!info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) ||
      info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) < 2)
    {
      throw SceneError(where + ": velocity_series '" + path +
        "' has fewer than 2 written times; give a static flow with 'velocity_dataset'");
    }
    if (!p.Has("dimensions") && !p.Has("origin") && !p.Has("spacing"))
    {
      int extent[6];
      info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
      solver->SetDimensions(extent[1] - extent[0] + 1, extent[3] - extent[2] + 1, extent[5] - extent[4] + 1);
      solver->SetOrigin(info->Get(vtkDataObject::ORIGIN()));
      solver->SetSpacing(info->Get(vtkDataObject::SPACING()));
    }
    solver->SetVelocityConnection(resample->GetOutputPort());
  }

  // Sources: default one at the bottom centre of the grid.
  const int* dims = solver->GetDimensions();
  const double* origin = solver->GetOrigin();
  const double* spacing = solver->GetSpacing();
  if (const nlohmann::json* sources = p.Raw("sources"))
  {
    if (!sources->is_array())
    {
      throw SceneError(where + ": 'sources' must be a list of objects, got " + sources->dump());
    }
    for (size_t s = 0; s < sources->size(); ++s)
    {
      const std::string at = where + ".sources[" + std::to_string(s) + "]";
      if (!(*sources)[s].is_object())
      {
        throw SceneError(at + ": a source must be an object, got " + (*sources)[s].dump());
      }
      Parameters sp((*sources)[s], at);
      const auto center = sp.Vector<3>("center", { 0, 0, 0 });
      if (!sp.Has("center"))
      {
        throw SceneError(sp.Where() + ": 'center' is required");
      }
      const double radius = sp.Number("radius", 0.1, 0.0, 1e30);
      const double density = sp.Number("density", 1.0, -1e30, 1e30);
      const double temperature = sp.Number("temperature", 1.0, -1e30, 1e30);
      const auto velocity = sp.Vector<3>("velocity", { 0, 0, 0 });
      sp.RejectUnknown();
      solver->AddSource(center.data(), radius, density, temperature, velocity.data());
    }
  }
  else if (!p.Has("source_points"))
  {
    const double center[3] = { origin[0] + 0.5 * (dims[0] - 1) * spacing[0],
      origin[1] + 0.5 * (dims[1] - 1) * spacing[1], origin[2] + 0.1 * (dims[2] - 1) * spacing[2] };
    const double velocity[3] = { 0, 0, 0 };
    solver->AddSource(center, 0.1 * (dims[0] - 1) * spacing[0], 1.0, 1.0, velocity);
  }
  // Sources given as points: another dataset's points (a .vtp of marked
  // inlets, a threshold of the data ...) with their rate/temperature/radius/velocity arrays.
  if (p.Has("source_points"))
  {
    const std::string pointsName = p.String("source_points", "");
    vtkDataObject* data = datasets.Get(pointsName, where + ".source_points");
    auto* points = vtkPointSet::SafeDownCast(data);
    if (!points)
    {
      throw SceneError(where + ": source_points: dataset '" + pointsName + "' is a " +
        (data ? data->GetClassName() : "nothing") + ", not a point set (a .vtp, .vtu, a threshold ...)");
    }
    if (points->GetNumberOfPoints() == 0)
    {
      throw SceneError(where + ": source_points: dataset '" + pointsName + "' has no points");
    }
    solver->SetSourcePointsData(points);
  }
  if (const nlohmann::json* obstacles = p.Raw("obstacles"))
  {
    if (!obstacles->is_array())
    {
      throw SceneError(where + ": 'obstacles' must be a list of objects, got " + obstacles->dump());
    }
    for (size_t o = 0; o < obstacles->size(); ++o)
    {
      const std::string at = where + ".obstacles[" + std::to_string(o) + "]";
      if (!(*obstacles)[o].is_object())
      {
        throw SceneError(at + ": an obstacle must be an object, got " + (*obstacles)[o].dump());
      }
      Parameters op((*obstacles)[o], at);
      const std::string type = op.Choice("type", "sphere", { "sphere", "box", "surface" });
      // a moving obstacle: its velocity (model units / s), imposed on the fluid at its faces
      const auto velocity = op.Vector<3>("velocity", { 0, 0, 0 });
      if (type == "sphere")
      {
        if (!op.Has("center"))
        {
          throw SceneError(op.Where() + ": 'center' is required");
        }
        const auto center = op.Vector<3>("center", { 0, 0, 0 });
        const double radius = op.Number("radius", 0.1, 0.0, 1e30);
        op.RejectUnknown();
        solver->AddObstacleSphere(center.data(), radius, velocity.data());
      }
      else if (type == "box")
      {
        if (!op.Has("bounds"))
        {
          throw SceneError(op.Where() + ": 'bounds' is required");
        }
        const auto bounds = op.Vector<6>("bounds", { 0, 0, 0, 0, 0, 0 });
        op.RejectUnknown();
        solver->AddObstacleBox(bounds.data(), velocity.data());
      }
      else
      {
        // a closed surface read from a file (.vtp, .stl, .obj, .ply, legacy .vtk ...), voxelised
        const std::string path = op.String("path", "");
        if (path.empty())
        {
          throw SceneError(op.Where() + ": 'path' is required (a closed polygonal surface)");
        }
        op.RejectUnknown();
        const std::string resolved = datasets.Resolve(path);
        if (!vtksys::SystemTools::FileExists(resolved))
        {
          throw SceneError(op.Where() + ": file not found: '" + path + "'");
        }
        vtkNew<vtkPlumeDatasetReader> reader;
        reader->SetFileName(resolved.c_str());
        reader->Update();
        auto* surface = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
        if (!reader->GetLastError().empty() || !surface)
        {
          throw SceneError(op.Where() + ": '" + path + "' is not a polygonal surface" +
            (reader->GetLastError().empty() ? std::string() : ": " + reader->GetLastError()));
        }
        solver->AddObstacleSurface(surface, velocity.data());
      }
    }
  }
  step = p.Integer("step", 100, 0, 10000000);
  p.RejectUnknown();
  return solver;
}

vtkSmartPointer<vtkDataObject> BuildSmokeDataset(Parameters& p, SceneDatasets& datasets, const std::string& name)
{
  const std::string where = "datasets." + name;
  int step = 0;
  vtkSmartPointer<vtkPlumeSmokeSolver> solver = ConfigureSmokeSolver(p, datasets, name, step);

  // The pipeline's time request drives the simulation, as ParaView's animation would.
  if (ProgressEnabled())
  {
    AttachProgress(solver, "simulating " + name);
  }
  if (step > solver->GetNumberOfTimeSteps())
  {
    solver->SetNumberOfTimeSteps(step);
  }
  solver->UpdateTimeStep(step * solver->GetTimeStep());
  if (*solver->GetLastError())
  {
    throw SceneError(where + ": " + solver->GetLastError());
  }
  vtkSmartPointer<vtkDataObject> result = solver->GetOutputDataObject(0);
  return result;
}
}
