// GPU backend of vtkPlumeGaussianSplatter: layered instanced rendering into a
// float 3D texture (seed 002), read back. GL state lives in the private Internals.
#ifndef plumeSplatGPU_h
#define plumeSplatGPU_h

#include "plumeSplatKernel.h"

#include <memory>
#include <string>

class vtkOpenGLRenderWindow;
class vtkRenderWindow;
class vtkTextureObject;

namespace plume
{
namespace splat
{
class SplatGPU
{
public:
  SplatGPU();
  ~SplatGPU();
  /**
   * Same contract as SplatCPU. `window` (may be null: an offscreen window of
   * our own is created once) provides the GL context. Returns false and sets
   * `error` if GL cannot do it (no context, no float render target, grid
   * larger than GL_MAX_3D_TEXTURE_SIZE, incomplete framebuffer, GL error).
   */
  bool Run(vtkRenderWindow* window, const Grid& grid, const Settings& settings, const std::vector<Splat>& splats,
    float* out, size_t& touched, std::string& error);
  /**
   * The 3D texture of the last successful Run() (RGBA32F with a = 1 for 3
   * components, R32F for 1) and the window it lives in. The next Run()
   * renders into the same texture.
   */
  vtkTextureObject* GetResult(vtkOpenGLRenderWindow*& window);
  /** Free GL objects (needs the context still alive). */
  void Release();

private:
  class Internals;
  std::unique_ptr<Internals> Impl;
};
}
}

#endif
