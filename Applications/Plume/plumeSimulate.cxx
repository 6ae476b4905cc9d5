// `plume simulate SCENE.json -o OUT.pvd`: runs a scene's `"source": "smoke"`
// dataset (vtkPlumeSmokeSolver) and writes every K-th step as a .vti file of
// a ParaView collection (.pvd) that `plume render`, `plume info` and
// ParaView read as a time series; optionally restarts from and writes a
// solver checkpoint. Documented in Documentation/SceneFormat.md ("Smoke
// simulation") and the README.
#include "plumeSimulate.h"

#include "plumeParameters.h"
#include "plumeProgress.h"
#include "plumeScene.h"
#include "plumeSceneError.h"

#include "vtkPlumeSmokeSolver.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkXMLImageDataWriter.h"
#include "vtkXMLUtilities.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

namespace plume
{
namespace
{
std::string Stem(const std::string& path)
{
  const std::string ext = vtksys::SystemTools::GetFilenameLastExtension(path);
  return path.substr(0, path.size() - ext.size());
}

// XML text and attribute values (file names and documentation may hold &, <,
// ", ...): VTK's own entity encoder, bytes otherwise passed through
std::string Escape(const std::string& text)
{
  std::ostringstream out;
  vtkXMLUtilities::EncodeString(text.c_str(), VTK_ENCODING_NONE, out, VTK_ENCODING_NONE, 1);
  return out.str();
}
}

int Simulate(const SimulateOptions& options, std::ostream& out)
{
  if (vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(options.Output)) != ".pvd")
  {
    throw SceneError("output '" + options.Output + "': plume simulate writes a .pvd collection (e.g. -o smoke.pvd)");
  }
  if (options.Every < 1)
  {
    throw SceneError("--every " + std::to_string(options.Every) + ": must be 1 or more");
  }
  const nlohmann::json scene = Scene::ReadFile(options.Scene);
  const std::string sceneDir = vtksys::SystemTools::GetFilenamePath(
    vtksys::SystemTools::CollapseFullPath(options.Scene));
  const nlohmann::json* specs = scene.is_object() && scene.contains("datasets") ? &scene["datasets"] : nullptr;
  std::vector<std::string> smoke;
  if (specs && specs->is_object())
  {
    for (const auto& item : specs->items())
    {
      if (item.value().is_object() && item.value().contains("source") && item.value()["source"] == "smoke")
      {
        smoke.push_back(item.key());
      }
    }
  }
  std::string name = options.Dataset;
  if (name.empty())
  {
    if (smoke.size() != 1)
    {
      std::string list;
      for (const auto& s : smoke)
      {
        list += (list.empty() ? "" : ", ") + s;
      }
      throw SceneError(options.Scene + ": " +
        (smoke.empty() ? std::string("no dataset has \"source\": \"smoke\"; nothing to simulate")
                       : "several smoke datasets (" + list + "); choose one with --dataset"));
    }
    name = smoke.front();
  }
  else if (std::find(smoke.begin(), smoke.end(), name) == smoke.end())
  {
    throw SceneError("--dataset '" + name + "': the scene has no smoke dataset of that name");
  }

  SceneDatasets datasets(specs, sceneDir, ProgressEnabled());
  Parameters p((*specs)[name], "datasets." + name);
  p.Choice("source", "smoke", { "smoke" });
  int sceneSteps = 0;
  vtkSmartPointer<vtkPlumeSmokeSolver> solver = ConfigureSmokeSolver(p, datasets, name, sceneSteps);
  const int steps = options.Steps >= 0 ? options.Steps : sceneSteps;
  if (steps > solver->GetNumberOfTimeSteps())
  {
    solver->SetNumberOfTimeSteps(steps);
  }
  const double dt = solver->GetTimeStep();
  auto advance = [&](vtkIdType step) {
    solver->UpdateTimeStep(double(step) * dt);
    if (*solver->GetLastError())
    {
      throw SceneError("datasets." + name + ": " + solver->GetLastError());
    }
  };
  advance(0); // the state from the pipeline's inputs (obstacles, the flow of a virtual smoke)
  if (!options.Restart.empty())
  {
    if (!solver->ReadCheckpoint(options.Restart.c_str()))
    {
      throw SceneError("--restart: " + std::string(solver->GetLastError()));
    }
  }
  const vtkIdType first = solver->GetCurrentStep();
  if (steps == first)
  {
    throw SceneError("nothing to simulate: the last step (" + std::to_string(steps) +
      ", --steps or the dataset's \"step\") is where the simulation starts");
  }
  if (steps < first)
  {
    throw SceneError("the checkpoint is at step " + std::to_string(first) + ", beyond the " +
      std::to_string(steps) + " steps asked for (--steps)");
  }

  // OUT.pvd + OUT/<dataset>_<step>.vti (ParaView's layout)
  const std::string folder = Stem(options.Output);
  const std::string folderName = vtksys::SystemTools::GetFilenameName(folder);
  if (!vtksys::SystemTools::MakeDirectory(folder))
  {
    throw SceneError("cannot create the folder '" + folder + "' for the time steps");
  }
  std::ostringstream collection;
  collection.precision(15); // times as the solver has them
  collection << "<?xml version=\"1.0\"?>\n"
             << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
             << "  <Collection>\n";
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  int written = 0;
  const bool progress = ProgressEnabled();
  for (vtkIdType step = first; step <= steps; ++step)
  {
    const bool output = step > first && ((step - first) % options.Every == 0 || step == steps);
    if (!output && step != steps)
    {
      continue;
    }
    advance(step);
    if (!output)
    {
      continue;
    }
    char file[64];
    std::snprintf(file, sizeof(file), "_%06lld.vti", static_cast<long long>(step));
    const std::string relative = folderName + "/" + name + file;
    const std::string path = folder + "/" + name + file;
    vtkNew<vtkImageData> copy;
    copy->ShallowCopy(solver->GetOutput());
    writer->SetInputData(copy);
    writer->SetFileName(path.c_str());
    if (writer->Write() != 1 || writer->GetErrorCode() != 0)
    {
      throw SceneError("cannot write the time step '" + path + "'");
    }
    collection << "    <DataSet timestep=\"" << solver->GetSimulationTime() << "\" group=\"\" part=\"0\" file=\""
               << Escape(relative) << "\"/>\n";
    ++written;
    if (progress)
    {
      DrawProgress("simulating " + name, double(step - first) / double(std::max<vtkIdType>(1, steps - first)));
    }
  }
  collection << "  </Collection>\n</VTKFile>\n";
  {
    std::ofstream pvd(options.Output);
    pvd << collection.str();
    if (!pvd.good())
    {
      throw SceneError("cannot write '" + options.Output + "'");
    }
  }
  if (!options.Checkpoint.empty() && !solver->WriteCheckpoint(options.Checkpoint.c_str()))
  {
    throw SceneError("--checkpoint: " + std::string(solver->GetLastError()));
  }
  out << "plume: wrote " << options.Output << " (" << written << " time steps of dataset '" << name
      << "', steps " << first << ".." << steps << ", t = " << solver->GetSimulationTime() << ")";
  if (!options.Checkpoint.empty())
  {
    out << " and checkpoint " << options.Checkpoint;
  }
  out << "\n";
  if (solver->IsVelocityTimeSeries())
  {
    const std::vector<double>& times = solver->GetVelocityTimes();
    out << "plume: the flow is a time series of " << times.size() << " written times (t = " << times.front()
        << " to " << times.back() << ", offset " << solver->GetVelocityTimeOffset() << "); "
        << solver->GetNumberOfVelocityFramesRead() << " read\n";
  }
  return 0;
}
}
