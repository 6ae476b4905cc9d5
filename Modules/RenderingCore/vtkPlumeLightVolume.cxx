#include "vtkPlumeLightVolume.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkPlumeLightVolume);

vtkPlumeLightVolume::vtkPlumeLightVolume() = default;
vtkPlumeLightVolume::~vtkPlumeLightVolume() = default;

double vtkPlumeLightVolume::GetTextureBytes(const int dims[3], int lights)
{
  return 2.0 * (lights == 3 ? 4 : lights) * double(dims[0]) * double(dims[1]) * double(dims[2]);
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

bool vtkPlumeLightVolume::Update(vtkOpenGLRenderWindow* window, const int dims[3], int lights,
  const std::vector<double>& key, const std::function<void(int)>& drawSlice)
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
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_CULL_FACE);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglViewport(0, 0, dims[0], dims[1]);
    const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &drawBuffer);
    for (int k = 0; k < dims[2] && ok; ++k)
    {
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, texture->GetHandle(), 0, k);
      ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
      if (ok)
      {
        drawSlice(k);
      }
    }
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 0, 0, 0);
  }
  state->PopFramebufferBindings();
  state->vtkglViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
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
  this->Framebuffer->ReleaseGraphicsResources(window);
  this->Key.clear();
}

void vtkPlumeLightVolume::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UpdateCount: " << this->UpdateCount << "\n";
}
