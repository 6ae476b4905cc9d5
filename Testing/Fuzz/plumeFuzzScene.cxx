// libFuzzer target: the scene parser. Any bytes as a scene file: parsed with
// the nesting bound, then built into a renderer (every representation type,
// dataset source and parameter check runs; nothing is drawn). Bad scenes
// must end in plume::SceneError; anything else (a crash, a sanitizer report,
// another exception) is a finding.
#include "plumeScene.h"
#include "plumeSceneError.h"

#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkSMPTools.h"
#include "vtkRenderer.h"

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  // small budgets: a fuzzed splat or resampling must fail fast, not run for minutes
  setenv("PLUME_MEMORY_BUDGET_MB", "64", 1);
  // One thread: code run by vtkSMPTools' worker threads (Debian's VTK links TBB)
  // gives coverage that depends on scheduling, so libFuzzer's feedback, and
  // with it the inputs a fixed seed explores, would differ from run to run.
  vtkSMPTools::SetBackend("Sequential");
  setenv("PLUME_WORK_BUDGET", "1e7", 1);
  // generated sources (vortex, splat) only: files of the data folder would make each run slow
  setenv("PLUME_DATA_DIR", "/nonexistent-fuzz-data", 1);
  vtkObject::GlobalWarningDisplayOff();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try
  {
    const nlohmann::json scene = plume::Scene::Parse(in, "fuzzed scene");
    vtkNew<vtkRenderer> renderer;
    plume::SceneOptions options;
    plume::Scene::Build(scene, "/nonexistent-fuzz-folder", renderer, options);
  }
  catch (const plume::SceneError&)
  {
    // the expected outcome for bad input
  }
  return 0;
}
