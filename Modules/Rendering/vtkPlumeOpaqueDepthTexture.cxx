#include "vtkPlumeOpaqueDepthTexture.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"

#include "vtk_glew.h"

vtkStandardNewMacro(vtkPlumeOpaqueDepthTexture);

vtkPlumeOpaqueDepthTexture::vtkPlumeOpaqueDepthTexture()
  : Texture(vtkSmartPointer<vtkTextureObject>::New())
{
}

vtkPlumeOpaqueDepthTexture::~vtkPlumeOpaqueDepthTexture() = default;

vtkTextureObject* vtkPlumeOpaqueDepthTexture::GetTextureObject()
{
  return this->Texture;
}

void vtkPlumeOpaqueDepthTexture::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Texture->ReleaseGraphicsResources(window);
  this->Size[0] = this->Size[1] = 0;
}

bool vtkPlumeOpaqueDepthTexture::Capture(vtkRenderer* renderer)
{
  this->LastError.clear();
  auto* window = renderer ? vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow()) : nullptr;
  if (!window)
  {
    this->LastError = "an OpenGL render window is required";
    return false;
  }
  int width = 0, height = 0, x = 0, y = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  if (width <= 0 || height <= 0)
  {
    this->LastError = "empty viewport";
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  unsigned int drawBinding = 0, drawBuffer = 0;
  state->GetCurrentDrawFramebufferState(drawBinding, drawBuffer);

  // read from the framebuffer VTK is drawing into
  state->PushReadFramebufferBinding();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawBinding);
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  bool ok = samples == 0;
  if (!ok)
  {
    this->LastError = "the framebuffer is multisampled; its depth cannot be copied";
  }
  else
  {
    if (this->Texture->GetContext() != window || !this->Texture->GetHandle() ||
      this->Size[0] != width || this->Size[1] != height)
    {
      this->Texture->SetContext(window);
      this->Texture->SetWrapS(vtkTextureObject::ClampToEdge);
      this->Texture->SetWrapT(vtkTextureObject::ClampToEdge);
      this->Texture->SetMinificationFilter(vtkTextureObject::Nearest);
      this->Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
      ok = this->Texture->AllocateDepth(width, height, vtkTextureObject::Float32);
      if (!ok)
      {
        this->LastError = "could not allocate the depth texture";
      }
    }
    if (ok)
    {
      this->Texture->CopyFromFrameBuffer(x, y, 0, 0, width, height);
      this->Texture->Deactivate();
    }
  }
  state->PopReadFramebufferBinding();
  if (!ok)
  {
    this->Size[0] = this->Size[1] = 0;
    return false;
  }
  this->Origin[0] = x;
  this->Origin[1] = y;
  this->Size[0] = width;
  this->Size[1] = height;
  return true;
}

void vtkPlumeOpaqueDepthTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Origin: " << this->Origin[0] << " " << this->Origin[1] << "\n";
  os << indent << "Size: " << this->Size[0] << " " << this->Size[1] << "\n";
}
