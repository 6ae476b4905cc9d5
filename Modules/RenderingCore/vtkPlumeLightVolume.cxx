#include "vtkPlumeLightVolume.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <cmath> // For std::abs

vtkStandardNewMacro(vtkPlumeLightVolume);

namespace
{
// what was drawn into a texture is visible to the texture look-ups of the next draws
void Barrier()
{
  if (glTextureBarrier)
  {
    glTextureBarrier(); // GL 4.5 / ARB_texture_barrier
  }
  else
  {
    glFinish();
  }
}
}

vtkPlumeLightVolume::vtkPlumeLightVolume() = default;
vtkPlumeLightVolume::~vtkPlumeLightVolume() = default;

double vtkPlumeLightVolume::GetTextureBytes(const int dims[3], int lights, bool scratch)
{
  const double nodes = double(dims[0]) * double(dims[1]) * double(dims[2]);
  return 2.0 * (lights == 3 ? 4 : lights) * nodes + (scratch ? 4.0 * nodes : 0.0);
}

void vtkPlumeLightVolume::GetSweep(const float towards[3], int& axis, bool& flip)
{
  axis = 0;
  for (int a = 1; a < 3; ++a)
  {
    axis = std::abs(towards[a]) > std::abs(towards[axis]) ? a : axis;
  }
  // the light enters through the face the direction points at
  flip = towards[axis] > 0.0f;
}

vtkTextureObject* vtkPlumeLightVolume::GetSweepTexture()
{
  return this->Sweep->GetHandle() ? this->Sweep.GetPointer() : nullptr;
}

vtkTextureObject* vtkPlumeLightVolume::GetTextureObject()
{
  return this->Texture->GetHandle() ? this->Texture.GetPointer() : nullptr;
}

std::vector<double> vtkPlumeLightVolume::FullKey(const int dims[3], int lights, const std::vector<double>& key)
{
  // (three channels are not colour-renderable everywhere: four then)
  const int components = lights == 3 ? 4 : lights;
  std::vector<double> full = { double(dims[0]), double(dims[1]), double(dims[2]), double(components) };
  full.insert(full.end(), key.begin(), key.end());
  return full;
}

bool vtkPlumeLightVolume::IsStale(
  vtkOpenGLRenderWindow* window, const int dims[3], int lights, const std::vector<double>& key) const
{
  return !this->Texture->GetHandle() || this->Texture->GetContext() != window ||
    FullKey(dims, lights, key) != this->Key;
}

bool vtkPlumeLightVolume::Update(vtkOpenGLRenderWindow* window, const int dims[3], int lights, const float* towards,
  const std::vector<double>& key, const std::function<void(int, int)>& drawLayer,
  const std::function<void(int, int)>& copySlice)
{
  if (!this->IsStale(window, dims, lights, key))
  {
    return true;
  }
  const int components = lights == 3 ? 4 : lights;
  const std::vector<double> full = FullKey(dims, lights, key);
  vtkTextureObject* texture = this->Texture;
  this->Key.clear();
  if (!texture->GetHandle() || texture->GetContext() != window ||
    int(texture->GetWidth()) != dims[0] || int(texture->GetHeight()) != dims[1] ||
    int(texture->GetDepth()) != dims[2] || int(texture->GetComponents()) != components)
  {
    texture->ReleaseGraphicsResources(window);
    texture->SetContext(window);
    texture->SetMinificationFilter(vtkTextureObject::Linear);
    texture->SetMagnificationFilter(vtkTextureObject::Linear);
    texture->SetWrapS(vtkTextureObject::ClampToEdge);
    texture->SetWrapT(vtkTextureObject::ClampToEdge);
    texture->SetWrapR(vtkTextureObject::ClampToEdge);
    // 16-bit normalised (GL_R16 .. GL_RGBA16): 1.5e-5 steps of transmittance
    if (!texture->Allocate3D(dims[0], dims[1], dims[2], components, VTK_UNSIGNED_SHORT))
    {
      return false;
    }
  }
  vtkTextureObject* sweep = this->Sweep;
  sweep->SetContext(window);
  sweep->SetMinificationFilter(vtkTextureObject::Nearest);
  sweep->SetMagnificationFilter(vtkTextureObject::Nearest);
  this->Framebuffer->SetContext(window);
  vtkOpenGLState* state = window->GetState();
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  state->PushFramebufferBindings();
  this->Framebuffer->Bind(GL_FRAMEBUFFER);
  bool ok = true;
  {
    vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
    vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglColorMask maskSaver(state);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_CULL_FACE);
    state->vtkglDisable(GL_SCISSOR_TEST);
    const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &drawBuffer);
    for (int l = 0; l < lights && ok; ++l)
    {
      int axis;
      bool flip;
      GetSweep(towards + 3 * l, axis, flip);
      const int w = dims[(axis + 1) % 3], h = dims[(axis + 2) % 3], layers = dims[axis];
      // (one float channel: the transmittance is carried from layer to layer
      // without the 16-bit rounding of the result)
      if (!sweep->GetHandle() || int(sweep->GetWidth()) != w || int(sweep->GetHeight()) != h ||
        int(sweep->GetDepth()) != layers)
      {
        sweep->Deactivate();
        sweep->ReleaseGraphicsResources(window);
        sweep->SetContext(window);
        if (!sweep->Create3DFromRaw(w, h, layers, 1, VTK_FLOAT, nullptr))
        {
          ok = false;
          break;
        }
      }
      state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      state->vtkglViewport(0, 0, w, h);
      for (int q = 0; q < layers && ok; ++q)
      {
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, sweep->GetHandle(), 0, q);
        ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
        if (ok)
        {
          // the previous layers' writes become visible to this draw's reads
          // (GL 4.5: reading texels a draw does not write is then defined)
          Barrier();
          drawLayer(l, q);
        }
      }
      Barrier();
      state->vtkglColorMask(l == 0, l == 1, l == 2, l == 3);
      state->vtkglViewport(0, 0, dims[0], dims[1]);
      for (int k = 0; k < dims[2] && ok; ++k)
      {
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, texture->GetHandle(), 0, k);
        ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
        if (ok)
        {
          copySlice(l, k);
        }
      }
    }
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 0, 0, 0);
  }
  state->PopFramebufferBindings();
  state->vtkglViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  // (the scratch is as large as the volume: not kept between remakes)
  sweep->Deactivate();
  sweep->ReleaseGraphicsResources(window);
  if (ok)
  {
    this->Key = full;
    ++this->UpdateCount;
  }
  return ok;
}

void vtkPlumeLightVolume::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Texture->ReleaseGraphicsResources(window);
  this->Sweep->ReleaseGraphicsResources(window);
  this->Framebuffer->ReleaseGraphicsResources(window);
  this->Key.clear();
}

void vtkPlumeLightVolume::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UpdateCount: " << this->UpdateCount << "\n";
}
