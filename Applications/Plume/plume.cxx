// plume: the command line of Plume — render a JSON scene, describe a dataset,
// run a benchmark. Errors print one line naming the problem and exit non-zero.
#include "plumeBenchmarks.h"
#include "plumeImageOutput.h"
#include "plumeInfo.h"
#include "plumeOutputWindow.h"
#include "plumeProgress.h"
#include "plumeRenderWindowFactory.h"
#include "plumeScene.h"
#include "plumeSceneError.h"
#include "plumeTestSupport.h"

#include "vtkPlumeDatasetReader.h"
#include "vtkPlumeInputValidation.h"

#include "vtkCamera.h"
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

vtkSmartPointer<vtkRenderWindow> MakeWindow(plume::Backend backend, int w, int h)
{
  plume::Backend used;
  std::string error;
  auto window = plume::CreateRenderWindow(backend, w, h, &used, &error);
  if (!window)
  {
    throw plume::SceneError("cannot create a render window (backend " +
      std::string(plume::BackendName(backend)) + "): " + error);
  }
  return window;
}

int Render(const std::string& scenePath, const std::string& output, const std::string& size, plume::Backend backend)
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
  {
    // checked before any (possibly long) rendering
    std::string folder = vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::CollapseFullPath(output));
    if (!vtksys::SystemTools::FileIsDirectory(folder) || access(folder.c_str(), W_OK) != 0)
    {
      throw plume::SceneError("output '" + output + "': folder '" + folder + "' does not exist or is not writable");
    }
  }
  const nlohmann::json scene = plume::Scene::ReadFile(scenePath);
  std::string directory = vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::CollapseFullPath(scenePath));
  vtkNew<vtkRenderer> renderer;
  plume::Scene::Build(scene, directory, renderer, options);

  {
    // window (RGBA8 + depth, twice for multisampling) and the float read-back (RGBA32F + depth, plus a copy)
    const double pixels = double(options.Width) * double(options.Height);
    const std::string tooBig = vtkPlumeInputValidation::CheckMemory(pixels * (2 * 8.0 + 2 * 20.0),
      "a " + std::to_string(options.Width) + "x" + std::to_string(options.Height) + " image");
    if (!tooBig.empty())
    {
      throw plume::SceneError(tooBig + "; choose a smaller --size or scene 'size'");
    }
  }
  auto window = MakeWindow(backend, options.Width, options.Height);
  window->AddRenderer(renderer);
  renderer->ResetCameraClippingRange();
  if (options.Progress)
  {
    plume::DrawProgress("rendering", 0);
  }
  // EXR: the frame from a float framebuffer (the window's is 8 bits per channel)
  const plume::test::FloatImage image =
    ext == ".exr" ? plume::RenderFloat(window, renderer) : plume::test::ReadBack(window);
  if (options.Progress)
  {
    plume::DrawProgress("rendering", 1);
  }
  const std::string glErrors = plume::test::GLErrors(window);
  if (!glErrors.empty())
  {
    throw plume::SceneError("OpenGL reported errors while rendering: " + glErrors);
  }
  plume::WriteImage(output, image, renderer->GetActiveCamera());
  std::cout << "wrote " << output << " (" << options.Width << "x" << options.Height << ")\n";
  return 0;
}

/** Runs one benchmark job in a child process (fresh peak memory) and returns its JSON. */
nlohmann::json RunJobInChild(
  const std::string& name, const std::string& job, bool quick, const std::string& backend)
{
  int fds[2];
  if (pipe(fds) != 0)
  {
    throw plume::SceneError("bench: cannot create a pipe");
  }
  const pid_t pid = fork();
  if (pid == 0)
  {
    dup2(fds[1], STDOUT_FILENO);
    close(fds[0]);
    close(fds[1]);
    std::vector<std::string> args = { "plume", "--backend", backend, "bench", name, "--job", job };
    if (quick)
    {
      args.push_back("--quick");
    }
    std::vector<char*> argv;
    for (auto& a : args)
    {
      argv.push_back(a.data());
    }
    argv.push_back(nullptr);
    execv("/proc/self/exe", argv.data());
    _exit(127);
  }
  close(fds[1]);
  std::string text;
  char buffer[4096];
  ssize_t got;
  while ((got = read(fds[0], buffer, sizeof(buffer))) > 0)
  {
    text.append(buffer, static_cast<size_t>(got));
  }
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
  {
    throw plume::SceneError("bench " + name + ": job '" + job + "' failed (exit status " +
      std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
  }
  try
  {
    return nlohmann::json::parse(text.substr(text.rfind('{', text.rfind("{\"") + 1) == std::string::npos ? 0 : text.rfind("{\"")));
  }
  catch (const std::exception&)
  {
    throw plume::SceneError("bench " + name + ": job '" + job + "' printed no result: " + text);
  }
}

int Bench(const std::string& name, bool quick, const std::string& job, plume::Backend backend, bool list)
{
  const auto& registry = plume::bench::Registry();
  if (list)
  {
    for (const auto& b : registry)
    {
      std::cout << b.first << "\t" << b.second.Description << "\n";
    }
    return 0;
  }
  auto it = registry.find(name);
  if (it == registry.end())
  {
    std::string known;
    for (const auto& b : registry)
    {
      known += (known.empty() ? "" : ", ") + b.first;
    }
    throw plume::SceneError("unknown benchmark '" + name + "' (known: " + known + ")");
  }
  const plume::bench::Benchmark& benchmark = it->second;
  if (!job.empty())
  {
    // jobs are parsed by each benchmark without checks: only run the ones it lists
    const auto known = benchmark.Jobs(quick);
    if (std::find(known.begin(), known.end(), job) == known.end())
    {
      std::string names;
      for (const auto& k : known)
      {
        names += (names.empty() ? "" : ", ") + k;
      }
      throw plume::SceneError("bench " + name + ": unknown job '" + job + "'" + (quick ? " (with --quick)" : "") +
        " (known: " + names + ")");
    }
    plume::bench::Context context;
    context.Quick = quick;
    context.MakeWindow = [backend](int w, int h) { return MakeWindow(backend, w, h); };
    std::cout << benchmark.Run(context, job).dump() << std::endl;
    return 0;
  }
  const auto jobs = benchmark.Jobs(quick);
  std::map<std::string, nlohmann::json> results;
  for (size_t i = 0; i < jobs.size(); ++i)
  {
    plume::DrawProgress("bench " + name, double(i) / jobs.size());
    results[jobs[i]] = RunJobInChild(name, jobs[i], quick, plume::BackendName(backend));
  }
  plume::DrawProgress("bench " + name, 1);
  for (const auto& line : benchmark.Report(results, quick))
  {
    std::cout << line.dump() << std::endl;
  }
  return 0;
}
}

int main(int argc, char* argv[])
{
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
  render->add_option("scene", scene, "scene file (JSON; see Documentation/SceneFormat.md)")->required();
  render->add_option("-o,--output", output, "output image: .png (8-bit) or .exr (float RGBA + Z)")->required();
  render->add_option("--size", size, "image size WxH (default: the scene's size, else 800x600)");

  auto* info = app.add_subcommand("info", "describe what a dataset holds");
  std::string file, readerName, qFile;
  int timeStep = 0;
  bool json = false, noMerge = false;
  std::vector<std::string> blocks;
  info->add_option("file", file, "dataset file (any format VTK reads)")->required();
  info->add_option("--reader", readerName, "reader: legacy, xml, pvd, plot3d, exodus, ensight, openfoam, cgns, vrml");
  info->add_option("--q", qFile, "PLOT3D solution file (default: guessed from the grid file)");
  info->add_option("--time-step", timeStep, "time step index (default 0)")->check(CLI::NonNegativeNumber);
  info->add_option("--block", blocks, "only these blocks (repeatable)");
  info->add_flag("--no-merge", noMerge, "keep multiblock data as blocks");
  info->add_flag("--json", json, "print JSON");

  auto* bench = app.add_subcommand("bench", "run a named benchmark (JSON lines on stdout)");
  std::string benchName, job;
  bool quick = false, list = false;
  bench->add_option("name", benchName, "benchmark name (--list shows them)");
  bench->add_flag("--quick", quick, "small sizes and few frames (smoke test)");
  bench->add_flag("--list", list, "list the benchmarks");
  bench->add_option("--job", job, "run one job in this process (used internally)")->group("");

  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& e)
  {
    // --help/--version exit 0; every usage error exits 2 like other bad input.
    return app.exit(e) == 0 ? 0 : 2;
  }

  plume::Backend backend = plume::Backend::Auto;
  plume::ParseBackend(backendName, backend);
  int status = 0;
  std::string error;
  try
  {
    if (*render)
    {
      status = Render(scene, output, size, backend);
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
      reader->SetTimeStep(timeStep);
      reader->SetMergeBlocks(!noMerge);
      for (const auto& b : blocks)
      {
        reader->AddBlockName(b.c_str());
      }
      status = plume::RunInfo(reader, json, std::cout, std::cerr);
    }
    else if (*bench)
    {
      if (benchName.empty() && !list)
      {
        throw plume::SceneError("bench: name a benchmark (plume bench --list shows them)");
      }
      status = Bench(benchName, quick, job, backend, list);
    }
  }
  catch (const std::exception& e)
  {
    error = e.what();
    status = 2;
  }
  // On failure the one message below says what went wrong (VTK's own
  // messages are its details, available with PLUME_VERBOSE=1); on success
  // anything VTK reported is shown, so no warning is lost.
  const std::string messages = vtkMessages->TakeMessages();
  if (!error.empty())
  {
    std::cerr << "plume: error: " << plume::OneLine(error) << "\n";
  }
  if (!messages.empty() && (status == 0 || std::getenv("PLUME_VERBOSE")))
  {
    std::cerr << messages;
  }
  return status;
}
