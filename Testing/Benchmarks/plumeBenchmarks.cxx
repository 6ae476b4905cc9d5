#include "plumeBenchmarks.h"

#include <algorithm>
#include <chrono>
#include <sys/resource.h>

namespace plume
{
namespace bench
{

const std::map<std::string, Benchmark>& Registry()
{
  static const std::map<std::string, Benchmark> registry = [] {
    std::map<std::string, Benchmark> r;
    RegisterGlyphs(r);
    RegisterSplat(r);
    RegisterVolume(r);
    RegisterSheets(r);
    RegisterSolver(r);
    RegisterAirlight(r);
    return r;
  }();
  return registry;
}

double Now()
{
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

double PeakRSSMB()
{
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0; // Linux reports kB
}

double Median(std::vector<double> samples)
{
  if (samples.empty())
  {
    return 0;
  }
  std::sort(samples.begin(), samples.end());
  const size_t n = samples.size();
  return n % 2 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
}

}
}
