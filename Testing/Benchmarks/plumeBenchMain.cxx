// plume-bench: the benchmarks behind `plume bench NAME` (plume hands that
// command to this tool). Each job runs in a child process of its own (fresh
// peak memory); the report prints JSON lines. Built with the tests: the
// benchmarks compare with the test references, which the shipped plume does
// not link.
#include "plumeBenchmarks.h"
#include "plumeOutputWindow.h"
#include "plumeProgress.h"
#include "plumeRenderWindowFactory.h"
#include "plumeSceneError.h"

#include "vtkRenderWindow.h"
#include "vtkSMPTools.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>
#include <sys/wait.h>
#include <unistd.h>

namespace
{

/**
 * Runs one benchmark job in a child process (fresh peak memory) and returns
 * its JSON. The child runs this program again with --job, or, when `here` is
 * given, calls it after the fork instead (no exec: skips loading the ~160
 * shared libraries again, ~0.2 s of CPU a job) and exits with its status.
 */
nlohmann::json RunJobInChild(const std::string& name, const std::string& job, bool quick,
  const std::string& backend, const std::function<int()>& here = nullptr)
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
    if (here)
    {
      const int status = here();
      std::cout.flush();
      std::cerr.flush();
      _exit(status);
    }
    std::vector<std::string> args = { "plume-bench", "--backend", backend, name, "--job", job };
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

// VTK's messages, collected (main installs it; a forked job reports through it too)
plumeOutputWindow* Messages = nullptr;

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
    context.MakeWindow = [backend](int w, int h)
    {
      auto window = plume::RequireRenderWindow(backend, w, h);
      // bench only: PLUME_BENCH_MULTISAMPLES=N draws in an N-sample window
      // (0: none) instead of VTK's default; VTK remakes its render
      // framebuffer at the next frame when the count changed
      if (const char* samples = std::getenv("PLUME_BENCH_MULTISAMPLES"))
      {
        window->SetMultiSamples(std::atoi(samples));
      }
      return window;
    };
    std::cout << benchmark.Run(context, job).dump() << std::endl;
    return 0;
  }
  const auto jobs = benchmark.Jobs(quick);
  std::map<std::string, nlohmann::json> results;
  for (size_t i = 0; i < jobs.size(); ++i)
  {
    plume::DrawProgress("bench " + name, double(i) / jobs.size());
    // --quick (the test suite's smoke test): the first job through --job in a
    // new process as in a full run, the others in the forked child itself
    // (this process has made no GL context and started no threads so far)
    std::function<int()> here;
    if (quick && i > 0)
    {
      here = [&, i]() {
        int status = 0;
        std::string error;
        try
        {
          status = Bench(name, quick, jobs[i], backend, false);
        }
        catch (const std::exception& e)
        {
          error = e.what();
          status = 2;
        }
        return Messages->Finish(status, error);
      };
    }
    results[jobs[i]] = RunJobInChild(name, jobs[i], quick, plume::BackendName(backend), here);
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
  if (!std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    vtkSMPTools::SetBackend("STDThread");
  }
  plumeOutputWindow* vtkMessages = plumeOutputWindow::Install();
  Messages = vtkMessages;
  CLI::App app{ "plume bench: Plume's renderers against VTK's own (JSON lines)" };
  app.name("plume bench");
  std::string backendName = "auto";
  app.add_option("--backend", backendName, "OpenGL backend: auto (OSMesa, else X), osmesa, x")
    ->check(CLI::IsMember({ "auto", "osmesa", "x" }));
  std::string benchName, job;
  bool quick = false, list = false;
  app.add_option("name", benchName, "benchmark name (--list shows them)");
  app.add_flag("--quick", quick, "small sizes and few frames (smoke test)");
  app.add_flag("--list", list, "list the benchmarks");
  app.add_option("--job", job, "run one job in this process (used internally)")->group("");
  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& e)
  {
    if (e.get_exit_code() == 0)
    {
      return app.exit(e);
    }
    std::cerr << "plume: error: " << e.what() << " (plume bench --help)\n";
    return 2;
  }
  plume::Backend backend = plume::Backend::Auto;
  plume::ParseBackend(backendName, backend);
  int status = 0;
  std::string error;
  try
  {
    if (benchName.empty() && !list)
    {
      throw plume::SceneError("bench: name a benchmark (plume bench --list shows them)");
    }
    status = Bench(benchName, quick, job, backend, list);
  }
  catch (const std::exception& e)
  {
    error = e.what();
    status = 2;
  }
  return vtkMessages->Finish(status, error);
}
