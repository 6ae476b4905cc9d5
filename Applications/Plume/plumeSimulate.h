// `plume simulate`: a scene's smoke dataset run and written as a time series.
#ifndef plumeSimulate_h
#define plumeSimulate_h

#include <ostream>
#include <string>

namespace plume
{
struct SimulateOptions
{
  std::string Scene;      // scene file with a "source": "smoke" dataset
  std::string Output;     // the .pvd collection; the steps go to a folder of its stem
  std::string Dataset;    // which smoke dataset ("" = the only one)
  int Steps = -1;         // last step to simulate (-1 = the dataset's "step")
  int Every = 10;         // write every K-th step (and the last)
  std::string Restart;    // checkpoint to continue from ("" = from rest)
  std::string Checkpoint; // write the final state here ("" = none)
};

/** Run and write the series; prints one summary line to `out`; throws SceneError. */
int Simulate(const SimulateOptions& options, std::ostream& out);
}

#endif
