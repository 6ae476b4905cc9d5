#include "plumeBenchFloorMapper.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(plumeBenchFloorMapper);

namespace
{
// the full-screen quad's vertex shader (vtkOpenGLQuadHelper's default) gives texCoord
const char* const FillFS = R"(//VTK::System::Dec
in vec2 texCoord;
//VTK::Output::Dec
void main()
{
  // a premultiplied colour that varies over the lattice (a "ray" that costs nothing)
  gl_FragData[0] = vec4(0.4 * texCoord.x, 0.3 * texCoord.y, 0.2, 0.5);
}
)";
const char* const ConstantFS = R"(//VTK::System::Dec
in vec2 texCoord;
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = vec4(0.2, 0.15, 0.1 + 1e-6 * texCoord.x, 0.5); // (texCoord used: the quad binds it)
}
)";
const char* const UpsampleFS = R"(//VTK::System::Dec
in vec2 texCoord;
uniform sampler2D lattice;
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = texture(lattice, texCoord);
}
)";
}

struct plumeBenchFloorMapper::Internals
{
  std::unique_ptr<vtkOpenGLQuadHelper> Fill;
  std::unique_ptr<vtkOpenGLQuadHelper> Draw;
  vtkNew<vtkTextureObject> Texture;
  vtkNew<vtkOpenGLFramebufferObject> FBO;
  int Size = 0;
  int Bits = 0;
};

plumeBenchFloorMapper::plumeBenchFloorMapper()
  : Impl(new Internals)
{
}

plumeBenchFloorMapper::~plumeBenchFloorMapper() = default;

void plumeBenchFloorMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Impl->Fill.reset();
  this->Impl->Draw.reset();
  this->Impl->Texture->ReleaseGraphicsResources(window);
  this->Impl->FBO->ReleaseGraphicsResources(window);
  this->Impl->Size = 0;
}

void plumeBenchFloorMapper::Render(vtkRenderer* renderer, vtkVolume* volume)
{
  Internals& impl = *this->Impl;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  const bool lattice = this->LatticeSize > 0;
  if (!impl.Draw)
  {
    impl.Draw.reset(new vtkOpenGLQuadHelper(window, nullptr, lattice ? UpsampleFS : ConstantFS, nullptr));
    impl.Fill.reset(lattice ? new vtkOpenGLQuadHelper(window, nullptr, FillFS, nullptr) : nullptr);
  }
  if (lattice && (impl.Size != this->LatticeSize || impl.Bits != this->Bits))
  {
    vtkTextureObject* texture = impl.Texture;
    texture->SetContext(window);
    texture->SetMinificationFilter(vtkTextureObject::Linear);
    texture->SetMagnificationFilter(vtkTextureObject::Linear);
    texture->SetWrapS(vtkTextureObject::ClampToEdge);
    texture->SetWrapT(vtkTextureObject::ClampToEdge);
    if (this->Bits == 16)
    {
      texture->SetInternalFormat(GL_RGBA16F);
      texture->SetFormat(GL_RGBA);
      texture->SetDataType(GL_FLOAT);
    }
    texture->Allocate2D(
      this->LatticeSize, this->LatticeSize, 4, this->Bits == 8 ? VTK_UNSIGNED_CHAR : VTK_FLOAT);
    impl.FBO->SetContext(window);
    impl.Size = this->LatticeSize;
    impl.Bits = this->Bits;
  }
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  state->vtkglDisable(GL_DEPTH_TEST);
  if (lattice)
  {
    // the lattice: one fragment per texel, no blending
    state->PushFramebufferBindings();
    impl.FBO->Bind();
    impl.FBO->AddColorAttachment(0, impl.Texture);
    impl.FBO->ActivateDrawBuffers(1);
    state->vtkglDisable(GL_BLEND);
    state->vtkglViewport(0, 0, this->LatticeSize, this->LatticeSize);
    window->GetShaderCache()->ReadyShaderProgram(impl.Fill->Program);
    impl.Fill->Render();
    impl.FBO->RemoveColorAttachment(0);
    state->PopFramebufferBindings();
  }
  // one quad, premultiplied blending: over the viewport, or with a lattice
  // over the screen rectangle of the volume's bounds (as the fixed-point
  // mapper draws its image)
  int size[2], origin[2];
  renderer->GetTiledSizeAndOrigin(size, size + 1, origin, origin + 1);
  int lo[2] = { 0, 0 }, hi[2] = { size[0], size[1] };
  if (lattice)
  {
    double bounds[6];
    volume->GetBounds(bounds);
    double dlo[2] = { 1e300, 1e300 }, dhi[2] = { -1e300, -1e300 };
    for (int c = 0; c < 8; ++c)
    {
      renderer->SetWorldPoint(bounds[c & 1], bounds[2 + ((c >> 1) & 1)], bounds[4 + ((c >> 2) & 1)], 1.0);
      renderer->WorldToDisplay();
      const double* d = renderer->GetDisplayPoint();
      for (int k = 0; k < 2; ++k)
      {
        dlo[k] = std::min(dlo[k], d[k]);
        dhi[k] = std::max(dhi[k], d[k]);
      }
    }
    for (int k = 0; k < 2; ++k)
    {
      lo[k] = std::max(0, static_cast<int>(std::floor(dlo[k])) - origin[k]);
      hi[k] = std::min(size[k], static_cast<int>(std::ceil(dhi[k])) - origin[k]);
    }
  }
  this->LastCoverage = double(std::max(0, hi[0] - lo[0])) * std::max(0, hi[1] - lo[1]) / (double(size[0]) * size[1]);
  state->vtkglViewport(origin[0] + lo[0], origin[1] + lo[1], hi[0] - lo[0], hi[1] - lo[1]);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  window->GetShaderCache()->ReadyShaderProgram(impl.Draw->Program);
  if (lattice)
  {
    impl.Texture->Activate();
    impl.Draw->Program->SetUniformi("lattice", impl.Texture->GetTextureUnit());
  }
  impl.Draw->Render();
  if (lattice)
  {
    impl.Texture->Deactivate();
  }
}
