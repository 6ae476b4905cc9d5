// plume: the command line of Plume — render a JSON scene, describe a dataset,
// run a benchmark. Errors print one line naming the problem and exit non-zero.
#include "plumeImageOutput.h"
#include "plumeInfo.h"
#include "plumeOutputWindow.h"
#include "plumeParameterTables.h"
#include "plumeProgress.h"
#include "plumeRenderWindowFactory.h"
#include "plumeScene.h"
#include "plumeSceneError.h"
#include "plumeSimulate.h"
#include "plumeView.h"

#include "vtkPlumeDatasetReader.h"
#include "vtkPlumeParameterTable.h"
#include "vtkPlumeInputValidation.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkGenericCell.h"
#include "vtkCellTypes.h"
#include "vtkPolyData.h"
#include "vtkCellData.h"
#include "vtkPointData.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtksys/SystemTools.hxx"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
/** Parses "WxH" with overflow checks (sscanf's %d wraps 4294967297 to 1). */
bool ParseSize(const std::string& text, int& w, int& h)
{
  return vtkPlumeInputValidation::ParseSize(text, 16384, w, h);
}


/**
 * --time-steps: "all", "A:B" (inclusive) or "A,B,C". `count` is the number of
 * steps ("all" and checks; 0 while unknown). Throws SceneError naming the text.
 */
std::vector<int> ParseTimeSteps(const std::string& text, int count)
{
  const std::string usage = "--time-steps must be 'all', 'A:B' (first and last step) or a list 'A,B,C' of step "
                            "indices 0 or more, got '" + text + "'";
  std::vector<int> steps;
  if (text == "all")
  {
    for (int k = 0; k < count; ++k)
    {
      steps.push_back(k);
    }
    return steps;
  }
  auto number = [&](const std::string& part) {
    if (part.empty() || part.size() > 9 || part.find_first_not_of("0123456789") != std::string::npos)
    {
      throw plume::SceneError(usage);
    }
    return std::stoi(part);
  };
  const size_t colon = text.find(':');
  if (colon != std::string::npos)
  {
    const int first = number(text.substr(0, colon));
    const int last = number(text.substr(colon + 1));
    if (last < first)
    {
      throw plume::SceneError("--time-steps '" + text + "': the last step is before the first");
    }
    for (int k = first; k <= last; ++k)
    {
      steps.push_back(k);
    }
    return steps;
  }
  size_t at = 0;
  while (at <= text.size())
  {
    const size_t comma = text.find(',', at);
    steps.push_back(number(text.substr(at, comma == std::string::npos ? std::string::npos : comma - at)));
    if (comma == std::string::npos)
    {
      break;
    }
    at = comma + 1;
  }
  return steps;
}

/** OUT.png -> OUT_0003.png: frame files of a series, in step order for video tools. */
std::string FramePath(const std::string& output, int step)
{
  const std::string ext = vtksys::SystemTools::GetFilenameLastExtension(output);
  char number[16];
  std::snprintf(number, sizeof(number), "_%04d", step);
  return output.substr(0, output.size() - ext.size()) + number + ext;
}

/**
 * Quick look (`plume render FILE`): a scene chosen from what the dataset holds.
 * Vectors -> glyph lines coloured by speed; an image, or a mesh of 3D cells (a
 * CFD case), with a scalar array and no vectors -> a composite volume (meshes
 * resampled onto an image); polygons only -> the surface (coloured by its
 * first scalar array); anything else -> the outer surface. Always the outline.
 */
// Whether the dataset has cells of dimension 3 (hexahedra, tetrahedra, ...).
static bool HasVolumeCells(vtkDataSet* data)
{
  vtkNew<vtkCellTypes> types;
  data->GetCellTypes(types);
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType i = 0; i < types->GetNumberOfTypes(); ++i)
  {
    cell->SetCellType(types->GetCellType(i));
    if (cell->GetCellDimension() == 3)
    {
      return true;
    }
  }
  return false;
}

nlohmann::json QuickLookScene(const std::string& file)
{
  std::string path = file;
  if (!vtksys::SystemTools::FileIsFullPath(path) && !vtksys::SystemTools::FileExists(path) &&
    vtksys::SystemTools::FileExists(plume::DataFolder() + "/" + path))
  {
    path = plume::DataFolder() + "/" + path;
  }
  path = vtksys::SystemTools::CollapseFullPath(path);
  vtkNew<vtkPlumeDatasetReader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  if (reader->GetNumberOfTimeValues() > 1)
  {
    reader->SetTimeStep(reader->GetNumberOfTimeValues() - 1); // as scenes: the last step
  }
  reader->Update();
  if (!reader->GetLastError().empty())
  {
    throw plume::SceneError(reader->GetLastError());
  }
  auto* data = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (!data)
  {
    throw plume::SceneError("quick look: '" + file + "' holds no single dataset (try plume info)");
  }
  auto firstArray = [&](int components) -> std::string {
    for (vtkDataSetAttributes* a : { static_cast<vtkDataSetAttributes*>(data->GetPointData()),
           static_cast<vtkDataSetAttributes*>(data->GetCellData()) })
    {
      vtkDataArray* active = components == 3 ? a->GetVectors() : a->GetScalars();
      if (active && active->GetName() && active->GetNumberOfComponents() == components)
      {
        return active->GetName();
      }
      for (int i = 0; i < a->GetNumberOfArrays(); ++i)
      {
        vtkDataArray* array = a->GetArray(i);
        const std::string name = array && array->GetName() ? array->GetName() : "";
        if (!name.empty() && name != "vtkValidPointMask" && name != "vtkGhostType" &&
          array->GetNumberOfComponents() == components)
        {
          return name;
        }
      }
    }
    return "";
  };
  const std::string vectors = firstArray(3);
  const std::string scalars = firstArray(1);
  auto* poly = vtkPolyData::SafeDownCast(data);
  nlohmann::json scene;
  scene["datasets"]["data"]["path"] = path;
  nlohmann::json reps = nlohmann::json::array();
  reps.push_back({ { "type", "outline" }, { "dataset", "data" }, { "color", { 0.6, 0.6, 0.65 } } });
  if (poly && poly->GetNumberOfPolys() + poly->GetNumberOfStrips() > 0)
  {
    nlohmann::json surface = { { "type", "surface" }, { "dataset", "data" } };
    if (!scalars.empty())
    {
      surface["color_array"] = scalars;
    }
    reps.push_back(surface);
  }
  else if (!vectors.empty())
  {
    // a lattice of about 24 roots along the longest axis (images; others are resampled to 64 points)
    int stride = 3;
    if (auto* image = vtkImageData::SafeDownCast(data))
    {
      int dims[3];
      image->GetDimensions(dims);
      stride = std::max(1, std::max(dims[0], std::max(dims[1], dims[2])) / 24);
    }
    reps.push_back({ { "type", "glyphs" }, { "dataset", "data" }, { "vectors", vectors }, { "roots", "lattice" },
      { "stride", stride } });
  }
  else if (!scalars.empty() && (vtkImageData::SafeDownCast(data) || HasVolumeCells(data)))
  {
    reps.push_back({ { "type", "volume" }, { "dataset", "data" }, { "array", scalars } });
  }
  else
  {
    reps.push_back({ { "type", "surface" }, { "dataset", "data" } });
  }
  scene["representations"] = reps;
  scene["camera"] = { { "view_up", "auto" }, { "azimuth", 30 }, { "elevation", 20 } };
  return scene;
}

std::string QuickLookSummary(const nlohmann::json& scene)
{
  const auto& rep = scene["representations"].back();
  std::string what = rep["type"].get<std::string>();
  for (const char* key : { "vectors", "array", "color_array" })
  {
    if (rep.contains(key))
    {
      what += " of '" + rep[key].get<std::string>() + "'";
    }
  }
  return what + " and the outline";
}

/**
 * --camera FILE: a camera saved by plume view (key c), {"camera": {...}}, or a
 * bare camera object; it replaces the scene's camera.
 */
nlohmann::json ReadCamera(const std::string& path)
{
  const std::string notRegular = vtkPlumeInputValidation::CheckRegularFile(path);
  if (!notRegular.empty())
  {
    throw plume::SceneError("--camera: " + notRegular);
  }
  std::ifstream in(path);
  if (!in)
  {
    throw plume::SceneError("--camera: cannot open '" + path + "'");
  }
  const nlohmann::json file = plume::Scene::Parse(in, "--camera file '" + path + "'");
  const nlohmann::json camera = file.is_object() && file.contains("camera") ? file["camera"] : file;
  if (!camera.is_object())
  {
    throw plume::SceneError("--camera file '" + path + "' must hold a camera object (as plume view's key c saves), "
                            "got " + camera.dump().substr(0, 80));
  }
  return camera;
}

/** A scene file, or a quick look's scene for a dataset file (stated; printed with --print-scene). */
nlohmann::json LoadScene(const std::string& scenePath, bool printScene, const std::string& cameraFile = "")
{
  // a folder is not a quick look: the scene reader says it is a directory
  const bool quickLook = !vtksys::SystemTools::FileIsDirectory(scenePath) &&
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(scenePath)) != ".json";
  nlohmann::json scene = quickLook ? QuickLookScene(scenePath) : plume::Scene::ReadFile(scenePath);
  if (!cameraFile.empty())
  {
    scene["camera"] = ReadCamera(cameraFile); // checked like any scene camera when the scene is built
  }
  if (printScene)
  {
    // the scene chosen, for the user to edit (stderr keeps stdout for --print-scene)
    std::cout << scene.dump(2) << "\n";
  }
  if (quickLook)
  {
    plume::Note("quick look at " + scenePath + ": " + QuickLookSummary(scene) +
      " (--print-scene prints the scene to edit)");
  }
  return scene;
}

/** `plume view`: the scene plume render would render, in an interactive window. */
int View(const std::string& scenePath, const std::string& size, plume::ViewOptions options, bool printScene,
  const std::string& cameraFile)
{
  if (!size.empty() && !ParseSize(size, options.Width, options.Height))
  {
    throw plume::SceneError("--size must be WxH with positive integers up to 16384, got '" + size + "'");
  }
  const nlohmann::json scene = LoadScene(scenePath, printScene, cameraFile);
  const std::string directory =
    vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::CollapseFullPath(scenePath));
  return plume::View(scene, directory, options, std::cout);
}

int Render(const std::string& scenePath, const std::string& output, const std::string& size, plume::Backend backend,
  const std::string& timeSteps, const std::string& video, bool printScene, const std::string& cameraFile)
{
  plume::SceneOptions options;
  if (!size.empty() && !ParseSize(size, options.Width, options.Height))
  {
    throw plume::SceneError("--size must be WxH with positive integers up to 16384, got '" + size + "'");
  }
  options.Progress = plume::ProgressEnabled();
  const std::string ext =
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(output));
  if (ext != ".png" && ext != ".exr")
  {
    throw plume::SceneError("output '" + output + "': unknown image format '" + ext + "' (use .png or .exr)");
  }
  for (const std::string& file : { output, video })
  {
    if (file.empty())
    {
      continue;
    }
    // checked before any (possibly long) rendering
    std::string folder = vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::CollapseFullPath(file));
    if (!vtksys::SystemTools::FileIsDirectory(folder) || access(folder.c_str(), W_OK) != 0)
    {
      throw plume::SceneError("output '" + file + "': folder '" + folder + "' does not exist or is not writable");
    }
  }
  std::string ffmpeg;
  if (!video.empty())
  {
    if (timeSteps.empty())
    {
      throw plume::SceneError("--video needs --time-steps (the frames of the video)");
    }
    if (ext != ".png")
    {
      throw plume::SceneError("--video assembles PNG frames: give -o FRAME.png, got '" + output + "'");
    }
    ffmpeg = vtksys::SystemTools::FindProgram("ffmpeg");
    if (ffmpeg.empty())
    {
      throw plume::SceneError("--video needs ffmpeg, which is not on PATH (Debian: apt-get install ffmpeg; "
                              "scripts/install-deps.sh installs it)");
    }
  }
  std::vector<int> steps;
  const bool all = timeSteps == "all";
  if (!timeSteps.empty() && !all)
  {
    steps = ParseTimeSteps(timeSteps, 0);
  }
  const nlohmann::json scene = LoadScene(scenePath, printScene, cameraFile);
  std::string directory = vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::CollapseFullPath(scenePath));
  vtkSmartPointer<vtkRenderWindow> window;
  // One frame per step: the scene is built again for each (every series read at that step).
  auto renderFrame = [&](int step, const std::string& file) {
    plume::SceneOptions frame = options;
    frame.TimeStep = step;
    vtkNew<vtkRenderer> renderer;
    plume::Scene::Build(scene, directory, renderer, frame);
    options.Width = frame.Width;
    options.Height = frame.Height;
    options.NumberOfTimeSteps = frame.NumberOfTimeSteps;
    if (!window)
    {
      window = plume::RequireRenderWindow(backend, frame.Width, frame.Height);
    }
    window->AddRenderer(renderer);
    renderer->ResetCameraClippingRange();
    // EXR: the frame from a float framebuffer (the window's is 8 bits per channel)
    const plume::FloatImage image =
      ext == ".exr" ? plume::RenderFloat(window, renderer) : plume::ReadBack(window);
    const std::string glErrors = plume::GLErrors(window);
    if (!glErrors.empty())
    {
      throw plume::SceneError("OpenGL reported errors while rendering: " + glErrors);
    }
    plume::WriteImage(file, image, renderer->GetActiveCamera());
    window->RemoveRenderer(renderer);
  };
  if (timeSteps.empty())
  {
    if (options.Progress)
    {
      plume::DrawProgress("rendering", 0);
    }
    renderFrame(-1, output);
    if (options.Progress)
    {
      plume::DrawProgress("rendering", 1);
    }
    std::cout << "wrote " << output << " (" << options.Width << "x" << options.Height << ")\n";
    return 0;
  }
  // the first frame tells how many steps the series has ("all", and range checks)
  const int first = all ? 0 : steps.front();
  renderFrame(first, FramePath(output, first));
  if (options.NumberOfTimeSteps < 2)
  {
    throw plume::SceneError("--time-steps: no dataset of the scene is a time series (each holds one step)");
  }
  if (all)
  {
    steps = ParseTimeSteps("all", options.NumberOfTimeSteps);
  }
  for (int step : steps)
  {
    if (step >= options.NumberOfTimeSteps)
    {
      throw plume::SceneError("--time-steps: step " + std::to_string(step) + " is past the last step " +
        std::to_string(options.NumberOfTimeSteps - 1));
    }
  }
  for (size_t i = 1; i < steps.size(); ++i)
  {
    if (options.Progress)
    {
      plume::DrawProgress("rendering frames", double(i) / double(steps.size()));
    }
    renderFrame(steps[i], FramePath(output, steps[i]));
  }
  if (options.Progress)
  {
    plume::DrawProgress("rendering frames", 1);
  }
  std::cout << "wrote " << steps.size() << " frames " << FramePath(output, steps.front()) << " .. "
            << FramePath(output, steps.back()) << " (" << options.Width << "x" << options.Height << ")\n";
  if (!video.empty())
  {
    // ffmpeg reads numbered frames from a list (the steps need not be consecutive)
    const std::string list = video + ".frames.txt";
    {
      std::ofstream out(list);
      for (int step : steps)
      {
        out << "file '" << vtksys::SystemTools::CollapseFullPath(FramePath(output, step)) << "'\nduration 0.2\n";
      }
    }
    const std::string command = "'" + ffmpeg + "' -loglevel error -y -f concat -safe 0 -i '" + list +
      "' -vf 'scale=trunc(iw/2)*2:trunc(ih/2)*2,format=yuv420p' -r 5 '" + video + "' < /dev/null";
    const int rc = std::system(command.c_str());
    std::remove(list.c_str());
    if (rc != 0)
    {
      throw plume::SceneError("--video: ffmpeg failed (exit " + std::to_string(WEXITSTATUS(rc)) + ") making '" +
        video + "'");
    }
    std::cout << "wrote " << video << " (" << steps.size() << " frames, 5 per second)\n";
  }
  return 0;
}
}

// `plume params [TYPE]`: the Markdown tables of Documentation/SceneFormat.md,
// made from the renderers' own parameter tables
static int Params(const std::string& type)
{
  bool found = false;
  for (const vtkPlumeParameterTable* table : plume::ParameterTables())
  {
    if (type.empty() || table->GetSceneType() == type)
    {
      std::cout << "### `" << table->GetSceneType() << "` (" << table->GetClassName() << ")\n\n";
      table->WriteMarkdown(std::cout);
      std::cout << "\n";
      found = true;
    }
  }
  if (!found)
  {
    std::string known;
    for (const vtkPlumeParameterTable* table : plume::ParameterTables())
    {
      known += (known.empty() ? "" : ", ") + table->GetSceneType();
    }
    throw plume::SceneError("params: no parameter table for '" + type + "' (known: " + known + ")");
  }
  return 0;
}

// `plume bench ...` runs plume-bench, built beside plume with the tests: the
// benchmarks measure against the test references, which the shipped product
// does not link. Returns only if plume-bench cannot be started.
int ExecBench(int argc, char* argv[], int benchIndex)
{
  const std::string self = vtksys::SystemTools::GetRealPath("/proc/self/exe");
  const std::string tool = vtksys::SystemTools::GetFilenamePath(self) + "/plume-bench";
  std::vector<std::string> args = { tool };
  for (int i = 1; i < argc; ++i)
  {
    if (i != benchIndex)
    {
      args.emplace_back(argv[i]);
    }
  }
  std::vector<char*> pointers;
  for (auto& a : args)
  {
    pointers.push_back(a.data());
  }
  pointers.push_back(nullptr);
  execv(tool.c_str(), pointers.data());
  std::cerr << "plume: error: bench: cannot run '" << tool
            << "' (benchmarks are built with the tests in the build tree and are not installed)\n";
  return 2;
}

int main(int argc, char* argv[])
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--backend")
    {
      ++i; // its value
      continue;
    }
    if (a == "bench")
    {
      return ExecBench(argc, argv, i);
    }
    if (a.empty() || a[0] != '-')
    {
      break; // another subcommand
    }
  }

  // Debian's VTK defaults to the sequential SMP backend; use real threads
  // unless the user chose a backend through the environment.
  if (!std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    vtkSMPTools::SetBackend("STDThread");
  }
  plumeOutputWindow* vtkMessages = plumeOutputWindow::Install();

  CLI::App app{ "plume: volumetric flow visualization with VTK" };
  app.require_subcommand(1);
  app.fallthrough(); // --backend may also follow the subcommand
  std::string backendName = "auto";
  app.add_option("--backend", backendName, "OpenGL backend: auto (OSMesa, else X), osmesa, x")
    ->check(CLI::IsMember({ "auto", "osmesa", "x" }));
  app.set_version_flag("--version", "plume 0.1.0");

  auto* render = app.add_subcommand("render", "render a JSON scene to an image");
  std::string scene, output, size;
  render->add_option("scene", scene,
    "scene file (JSON; see Documentation/SceneFormat.md), or a dataset for a quick look (a scene chosen from its arrays)")
    ->required();
  bool printScene = false;
  render->add_flag("--print-scene", printScene, "print the scene rendered (JSON) on stdout, e.g. a quick look's to edit");
  render->add_option("-o,--output", output, "output image: .png (8-bit) or .exr (float RGBA + Z)")->required();
  render->add_option("--size", size, "image size WxH (default: the scene's size, else 800x600)");
  std::string timeSteps, video;
  render->add_option("--time-steps", timeSteps,
    "render these time steps to numbered images OUT_0000.png ...: all, A:B or A,B,C");
  render->add_option("--video", video, "with --time-steps: also assemble the frames into this video (ffmpeg)");
  std::string cameraFile;
  render->add_option("--camera", cameraFile,
    "use this camera instead of the scene's: a JSON camera object, e.g. one plume view saved with key c");

  auto* view = app.add_subcommand("view", "show a scene (or a dataset's quick look) in an interactive window (X display)");
  std::string viewScene, viewSize;
  plume::ViewOptions viewOptions;
  bool viewPrint = false;
  view->add_option("scene", viewScene, "scene file (JSON) or a dataset for a quick look, as plume render")->required();
  view->add_option("--size", viewSize, "window size WxH (default: the scene's size, else 800x600)");
  view->add_option("--screenshot-prefix", viewOptions.ScreenshotPrefix,
    "key s writes PREFIX_0000.png, PREFIX_0001.png, ... (default plume_view)");
  view->add_option("--update-rate", viewOptions.DesiredUpdateRate,
      "frames per second asked for while the camera moves: VTK's DesiredUpdateRate, under which the volume "
      "uses its interactive ray lattice (default 15)")
    ->check(CLI::Range(0.001, 1000.0));
  view->add_option("--scripted-moves", viewOptions.ScriptedMoves,
      "no event loop: N scripted mouse drags with a screenshot after each, release, s, r, s, q (for tests)")
    ->check(CLI::Range(1, 1000));
  view->add_option("--scripted-keys", viewOptions.ScriptedKeys,
    "with --scripted-moves: keys pressed after its r and screenshot, before q (e.g. ps1s)");
  view->add_flag("--print-scene", viewPrint, "print the scene shown (JSON) on stdout");
  std::string viewCamera;
  view->add_option("--camera", viewCamera, "start from this camera (a JSON camera object, as key c saves)");
  view->footer(plume::ViewKeys());

  auto* info = app.add_subcommand("info", "describe what a dataset holds");
  std::string file, readerName, qFile;
  int timeStep = 0;
  bool json = false, noMerge = false;
  std::vector<std::string> blocks;
  info->add_option("file", file, "dataset file (any format VTK reads)")->required();
  info->add_option("--reader", readerName, "reader: legacy, xml, pvd, plot3d, exodus, ensight, openfoam, cgns, vrml");
  info->add_option("--q", qFile, "PLOT3D solution file (default: guessed from the grid file)");
  // Without --time-step, the last step, as scenes read: a transient run's
  // step 0 is often its uniform initial condition.
  auto* infoTimeStep = info->add_option("--time-step", timeStep, "time step index (default: the last, as scenes)")
    ->check(CLI::Range(0, 1 << 30).description("a time step index: 0 or more"));
  info->add_option("--block", blocks, "only these blocks (repeatable)");
  info->add_flag("--no-merge", noMerge, "keep multiblock data as blocks");
  info->add_flag("--json", json, "print JSON");

  auto* simulate = app.add_subcommand("simulate", "run a scene's smoke dataset and write its time steps (.pvd)");
  plume::SimulateOptions simulation;
  simulate->add_option("scene", simulation.Scene, "scene file with a \"source\": \"smoke\" dataset")->required();
  simulate->add_option("-o,--output", simulation.Output, "output collection (.pvd); steps go to the folder of its stem")
    ->required();
  simulate->add_option("--dataset", simulation.Dataset, "which smoke dataset (default: the only one)");
  simulate->add_option("--steps", simulation.Steps, "last step (default: the dataset's \"step\")")
    ->check(CLI::Range(1, 10000000).description("a step count: 1 or more"));
  simulate->add_option("--every", simulation.Every, "write every K-th step, and the last (default 10)")
    ->check(CLI::Range(1, 10000000).description("1 or more"));
  simulate->add_option("--restart", simulation.Restart, "continue from this checkpoint (plume simulate --checkpoint)");
  simulate->add_option("--checkpoint", simulation.Checkpoint, "write the final state here, to continue later");

  // listed for --help; main() hands `plume bench ...` to plume-bench before parsing
  app.add_subcommand("bench", "run a named benchmark (JSON lines on stdout; plume bench --list)")
    ->allow_extras()
    ->prefix_command();

  auto* params = app.add_subcommand("params", "the parameters of each representation (Markdown tables)");
  std::string paramsType;
  params->add_option("type", paramsType, "only this representation type (e.g. sheet)");

  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& e)
  {
    // --help/--version print and exit 0; a usage error is one line and exit 2, like other bad input
    if (e.get_exit_code() == 0)
    {
      return app.exit(e);
    }
    std::cerr << "plume: error: " << e.what() << " (plume --help)\n";
    return 2;
  }

  plume::Backend backend = plume::Backend::Auto;
  plume::ParseBackend(backendName, backend);
  int status = 0;
  std::string error;
  try
  {
    if (*render)
    {
      status = Render(scene, output, size, backend, timeSteps, video, printScene, cameraFile);
    }
    else if (*view)
    {
      status = View(viewScene, viewSize, viewOptions, viewPrint, viewCamera);
    }
    else if (*info)
    {
      vtkNew<vtkPlumeDatasetReader> reader;
      // a relative path not found here is looked up in the data folder, as in scenes
      std::string path = file;
      if (!vtksys::SystemTools::FileIsFullPath(path) && !vtksys::SystemTools::FileExists(path) &&
        vtksys::SystemTools::FileExists(plume::DataFolder() + "/" + path))
      {
        path = plume::DataFolder() + "/" + path;
      }
      reader->SetFileName(path.c_str());
      reader->SetReaderName(readerName.c_str());
      if (!qFile.empty())
      {
        reader->SetQFileName(qFile.c_str());
      }
      reader->SetMergeBlocks(!noMerge);
      for (const auto& b : blocks)
      {
        reader->AddBlockName(b.c_str());
      }
      if (infoTimeStep->count() > 0)
      {
        reader->SetTimeStep(timeStep);
      }
      else
      {
        reader->UpdateInformation();
        reader->SetTimeStep(std::max(reader->GetNumberOfTimeValues() - 1, 0));
      }
      status = plume::RunInfo(reader, json, std::cout, std::cerr);
    }
    else if (*simulate)
    {
      status = plume::Simulate(simulation, std::cout);
    }
    else if (*params)
    {
      status = Params(paramsType);
    }
  }
  catch (const std::exception& e)
  {
    error = e.what();
    status = 2;
  }
  return vtkMessages->Finish(status, error);
}
