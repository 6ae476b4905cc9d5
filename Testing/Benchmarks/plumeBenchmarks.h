// `plume bench NAME`: named benchmarks. Each benchmark is a set of jobs; each
// job runs in a fresh child process (so peak memory is that job's own), prints
// one JSON object, and the benchmark combines the jobs into result lines with
// at least bench, case, ours_s, peer, peer_s, ratio (= peer_s / ours_s).
#ifndef plumeBenchmarks_h
#define plumeBenchmarks_h

#include "vtkSmartPointer.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <vector>

class vtkRenderWindow;

namespace plume
{
namespace bench
{
struct Context
{
  bool Quick = false;
  /** Creates an offscreen window with the backend chosen on the command line. */
  std::function<vtkSmartPointer<vtkRenderWindow>(int width, int height)> MakeWindow;
};

struct Benchmark
{
  std::string Description;
  /** Job identifiers, in the order they should run. */
  std::function<std::vector<std::string>(bool quick)> Jobs;
  /** Runs one job in this process and returns its measurements. */
  std::function<nlohmann::json(const Context&, const std::string& job)> Run;
  /** Turns all jobs' results (by job id) into output lines. */
  std::function<std::vector<nlohmann::json>(const std::map<std::string, nlohmann::json>& results, bool quick)> Report;
};

/** All benchmarks by name. */
const std::map<std::string, Benchmark>& Registry();

/** Benchmarks register themselves here (called once from Registry()). */
void RegisterGlyphs(std::map<std::string, Benchmark>& registry);
void RegisterSplat(std::map<std::string, Benchmark>& registry);
void RegisterVolume(std::map<std::string, Benchmark>& registry);
void RegisterSheets(std::map<std::string, Benchmark>& registry);
void RegisterSolver(std::map<std::string, Benchmark>& registry);
void RegisterAirlight(std::map<std::string, Benchmark>& registry);

/** Seconds on a monotonic clock. */
double Now();
/** Peak resident set size of this process, MB. */
double PeakRSSMB();
/** Median of the samples (the machine is shared and noisy). */
double Median(std::vector<double> samples);
}
}

#endif
