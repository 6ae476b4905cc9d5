// vtkPlumePassProfiler: disabled (the default), Start and Mark record nothing
// and do not wait for queued GL work; enabled, the passes come in order with
// their level suffixes, times >= 0, a queued draw is finished and timed in
// the pass that queued it, a sleep counts in wall time and not in CPU time,
// busy CPU work counts in CPU time; Start forgets the last frame, disabling
// keeps it readable, Clear forgets it; out-of-range passes read nullptr and 0.
#include "vtkPlumePassProfiler.h"
#include "vtkPlumeShaderFeatures.h"
#include "vtkPlumeShaderProgramCache.h"

#include "plumeRenderingCoreTestUtil.h"

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtk_glew.h"

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <string>
#include <thread>

namespace
{
// A full-screen quad whose every fragment loops ITERATIONS times: GL work
// that llvmpipe only rasterizes when the queue is flushed or finished.
const char* SlowFS = "//VTK::System::Dec\n"
                     "//VTK::Output::Dec\n"
                     "//PLUME::Defines\n"
                     "in vec2 texCoord;\n"
                     "void main() {\n"
                     "  float v = texCoord.x + texCoord.y;\n"
                     "  for (int i = 0; i < ITERATIONS; ++i) v = fract(sin(v * 12.9898 + float(i)) * 43758.5453);\n"
                     "  gl_FragData[0] = vec4(v, 0.0, 0.0, 1.0);\n"
                     "}\n";
constexpr int Size = 256;

double Seconds(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// This thread's CPU seconds (a clock the profiler does not read).
double ThreadCPU()
{
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}
}

int TestPassProfiler(int, char*[])
{
  int failures = 0;
  auto window = plumetest::MakeTestWindow();
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  gl->MakeCurrent();
  vtkNew<vtkPlumeShaderProgramCache> cache;
  vtkPlumeShaderFeatures slow;
  slow.Define("ITERATIONS", 200);
  vtkOpenGLQuadHelper* quad = cache->ReadyQuad(gl, SlowFS, slow);
  CHECK(quad != nullptr);
  if (!quad)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkOpenGLFramebufferObject> fbo;
  fbo->SetContext(gl);
  vtkOpenGLState* state = gl->GetState();
  state->PushFramebufferBindings();
  fbo->PopulateFramebuffer(Size, Size, true, 1, VTK_FLOAT, false, 0, 0, false);
  fbo->Bind();
  fbo->ActivateDrawBuffer(0);
  state->vtkglViewport(0, 0, Size, Size);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_SCISSOR_TEST);
  // the slow draw's time when finished (the first one also readies the program)
  quad->Render();
  glFinish();
  auto t0 = std::chrono::steady_clock::now();
  quad->Render();
  glFinish();
  const double drawSeconds = Seconds(t0);
  std::printf("slow draw: %.1f ms\n", 1e3 * drawSeconds);
  CHECK(drawSeconds > 0.005); // else the draw checks below prove nothing

  // disabled (the default): nothing recorded, the queued draw not waited for
  vtkPlumePassProfiler profiler;
  CHECK(!profiler.GetEnabled());
  profiler.Start();
  quad->Render();
  t0 = std::chrono::steady_clock::now();
  profiler.Mark("draw");
  profiler.Mark("nodes", 1);
  const double disabledSeconds = Seconds(t0);
  glFinish();
  CHECK(profiler.GetNumberOfPasses() == 0);
  CHECK(disabledSeconds < 0.25 * drawSeconds);

  // enabled: a frame of five passes
  profiler.SetEnabled(true);
  profiler.Start();
  quad->Render();
  profiler.Mark("draw");
  profiler.Mark("nodes", 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  profiler.Mark("nodes", 1);
  const double cpu0 = ThreadCPU();
  volatile double sink = 0.0;
  while (ThreadCPU() - cpu0 < 0.03)
  {
    for (int i = 0; i < 10000; ++i)
    {
      sink = sink + 1e-9 * i;
    }
  }
  profiler.Mark("interpolate", 2);
  profiler.Mark("refine");
  const char* expected[] = { "draw", "nodes", "nodes 1", "interpolate 2", "refine" };
  CHECK(profiler.GetNumberOfPasses() == 5);
  for (int p = 0; p < profiler.GetNumberOfPasses(); ++p)
  {
    const char* name = profiler.GetPassName(p);
    std::printf("%-14s %8.3f ms wall %8.3f ms CPU\n", name ? name : "(null)", 1e3 * profiler.GetPassSeconds(p),
      1e3 * profiler.GetPassCPUSeconds(p));
    CHECK(p < 5 && name && std::string(name) == expected[p]);
    CHECK(profiler.GetPassSeconds(p) >= 0.0);
    CHECK(profiler.GetPassCPUSeconds(p) >= 0.0);
  }
  // the draw finished in its own pass, not in the next one
  CHECK(profiler.GetPassSeconds(0) > 0.5 * drawSeconds);
  CHECK(profiler.GetPassSeconds(1) < profiler.GetPassSeconds(0));
  // the sleep: wall time, (almost) no CPU time
  CHECK(profiler.GetPassSeconds(2) >= 0.03);
  CHECK(profiler.GetPassCPUSeconds(2) < 0.5 * profiler.GetPassSeconds(2));
  // the busy loop: at least this thread's CPU time, and as much wall time
  CHECK(profiler.GetPassCPUSeconds(3) >= 0.029);
  CHECK(profiler.GetPassSeconds(3) >= 0.029);

  // out of range
  CHECK(profiler.GetPassName(-1) == nullptr && profiler.GetPassName(5) == nullptr);
  CHECK(profiler.GetPassSeconds(5) == 0.0 && profiler.GetPassCPUSeconds(-1) == 0.0);

  // disabled again: the last timed frame stays readable
  profiler.SetEnabled(false);
  profiler.Start();
  profiler.Mark("other");
  CHECK(profiler.GetNumberOfPasses() == 5);
  // a new timed frame forgets the last one
  profiler.SetEnabled(true);
  profiler.Start();
  profiler.Mark("scene");
  CHECK(profiler.GetNumberOfPasses() == 1 && std::string(profiler.GetPassName(0)) == "scene");
  profiler.Clear();
  CHECK(profiler.GetNumberOfPasses() == 0);

  state->PopFramebufferBindings();
  cache->ReleaseGraphicsResources(window);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
