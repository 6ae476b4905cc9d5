/**
 * @class   vtkPlumePassProfiler
 * @brief   per-pass times of one frame: the GL work finished after each pass, wall and process CPU seconds
 *
 * What a renderer's `ProfilePasses` diagnostics record (vtkPlumeVolumeMapper,
 * vtkPlumeAirlightPass; the benchmarks report them). The renderer calls
 * Start at the beginning of a frame and Mark after each pass: Mark finishes
 * the GL work submitted so far (glFinish, so passes that would overlap run
 * one after the other and the frame is slower) and records the time since
 * the last Start or Mark under the pass's name. Wall time covers the CPU and
 * the GL work; the process's CPU time (all its threads, llvmpipe's raster
 * threads included) is steadier on a loaded machine.
 *
 * Disabled (the default), Start and Mark cost nothing: no glFinish, no clock
 * read, no name built; the passes of the last timed frame stay readable.
 * Start and Mark need the renderer's context current when enabled.
 */
#ifndef vtkPlumePassProfiler_h
#define vtkPlumePassProfiler_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkWrappingHints.h"         // For VTK_WRAPEXCLUDE

#include <chrono> // For std::chrono::steady_clock
#include <string> // For std::string
#include <vector> // For std::vector

class PLUMERENDERINGCORE_EXPORT VTK_WRAPEXCLUDE vtkPlumePassProfiler
{
public:
  /** Time the passes of the frames that Start from now on. Default off. */
  void SetEnabled(bool enabled) { this->Enabled = enabled; }
  bool GetEnabled() const { return this->Enabled; }

  /**
   * A new frame: the passes recorded so far are forgotten, the GL work so
   * far is finished and the clocks start. Nothing when disabled.
   */
  void Start();

  /**
   * The GL work so far finished and the time since the last Start or Mark
   * recorded as pass `name`, or "`name` `level`" when `level` > 0 (a
   * renderer's finer levels: "nodes 1"; the name is built only when
   * enabled). Nothing when disabled.
   */
  void Mark(const char* name, int level = 0);

  /** Forget the passes recorded. */
  void Clear() { this->Passes.clear(); }

  ///@{
  /**
   * The passes recorded since the last Start, in order: their names and
   * their wall and process CPU seconds. Out of range: nullptr and 0.
   */
  int GetNumberOfPasses() const { return static_cast<int>(this->Passes.size()); }
  const char* GetPassName(int pass) const;
  double GetPassSeconds(int pass) const;
  double GetPassCPUSeconds(int pass) const;
  ///@}

private:
  struct Pass
  {
    std::string Name;
    double Seconds;
    double CPUSeconds;
  };
  bool Enabled = false;
  std::vector<Pass> Passes;
  // when the pass being timed began (the last Start or Mark)
  std::chrono::steady_clock::time_point WallStart;
  double CPUStart = 0.0;
  // finishes the GL work and reads both clocks
  void Finish(std::chrono::steady_clock::time_point& wall, double& cpu) const;
};

#endif
// VTK-HeaderTest-Exclude: vtkPlumePassProfiler.h
