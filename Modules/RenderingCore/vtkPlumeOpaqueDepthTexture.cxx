#include "vtkPlumeOpaqueDepthTexture.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"

#include "vtk_glew.h"

#include "vtkPlumeDepthResolveFS.h"

vtkStandardNewMacro(vtkPlumeOpaqueDepthTexture);

vtkPlumeOpaqueDepthTexture::vtkPlumeOpaqueDepthTexture()
  : Texture(vtkSmartPointer<vtkTextureObject>::New())
{
}

vtkPlumeOpaqueDepthTexture::~vtkPlumeOpaqueDepthTexture()
{
  delete this->Quad;
}

vtkTextureObject* vtkPlumeOpaqueDepthTexture::GetTextureObject()
{
  return this->Texture;
}

void vtkPlumeOpaqueDepthTexture::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->ResolveFramebuffer && this->Texture->GetContext())
  {
    this->Texture->GetContext()->MakeCurrent();
    glDeleteFramebuffers(1, &this->ResolveFramebuffer);
  }
  this->ResolveFramebuffer = 0;
  if (this->MultisampleFramebuffer && this->Texture->GetContext())
  {
    glDeleteFramebuffers(1, &this->MultisampleFramebuffer);
  }
  this->MultisampleFramebuffer = 0;
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    delete this->Quad;
    this->Quad = nullptr;
  }
  if (this->Multisampled)
  {
    this->Multisampled->ReleaseGraphicsResources(window);
  }
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
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples); // of the draw framebuffer: the one VTK draws into

  // read from the framebuffer VTK is drawing into
  state->PushReadFramebufferBinding();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawBinding);
  GLint componentType = 0, depthBits = 0;
  const GLenum attachment = drawBinding ? GL_DEPTH_ATTACHMENT : GL_DEPTH;
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &componentType);
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
  // same depth format as the source, so that a (multisample-resolving) blit is allowed
  const int format = componentType == GL_FLOAT ? vtkTextureObject::Float32
    : depthBits == 16                          ? vtkTextureObject::Fixed16
    : depthBits == 32                          ? vtkTextureObject::Fixed32
                                               : vtkTextureObject::Fixed24;
  bool ok = true;
  if (this->Texture->GetContext() != window || !this->Texture->GetHandle() ||
    this->Size[0] != width || this->Size[1] != height || this->Format != format)
  {
    if (this->Texture->GetHandle() && this->Format != format)
    {
      // A fresh texture object: vtkTextureObject::AllocateDepth keeps the
      // internal format of an earlier allocation, and a blit between depth
      // formats that differ is illegal ("depth attachment format mismatch").
      // The same mapper meets several formats, e.g. a vtkFramebufferPass's
      // float depth, then a window's DEPTH_COMPONENT32.
      this->Texture->ReleaseGraphicsResources(window);
      this->Texture = vtkSmartPointer<vtkTextureObject>::New();
    }
    this->Texture->SetContext(window);
    this->Texture->SetWrapS(vtkTextureObject::ClampToEdge);
    this->Texture->SetWrapT(vtkTextureObject::ClampToEdge);
    this->Texture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    ok = this->Texture->AllocateDepth(width, height, format);
    this->Format = format;
    if (!ok)
    {
      this->LastError = "could not allocate the depth texture";
    }
  }
  if (ok)
  {
    // Blit the depth into a framebuffer around the texture (resolves a
    // multisampled source too). Not vtkTextureObject::CopyFromFrameBuffer:
    // in VTK 9.1 it blits from a read framebuffer of its own choosing, which
    // inside a vtkFramebufferPass is not the one being drawn into.
    if (!this->ResolveFramebuffer)
    {
      glGenFramebuffers(1, &this->ResolveFramebuffer);
    }
    if (samples > 1 && this->ResolveToNearestSample &&
      this->ResolveNearest(window, x, y, width, height, samples))
    {
      state->PopReadFramebufferBinding();
      this->Origin[0] = x;
      this->Origin[1] = y;
      this->Size[0] = width;
      this->Size[1] = height;
      return true;
    }
    while (glGetError() != GL_NO_ERROR)
    {
      // a failed nearest-sample resolve: the resolving blit below instead
    }
    // the scissor box (VTK's viewport) applies to the blit's destination,
    // which starts at (0, 0): off, or other viewports than the lower left are cut
    vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->PushDrawFramebufferBinding();
    state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->ResolveFramebuffer);
    glFramebufferTexture2D(
      GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, this->Texture->GetHandle(), 0);
    glDrawBuffer(GL_NONE);
    glBlitFramebuffer(x, y, x + width, y + height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    state->PopDrawFramebufferBinding();
    if (glGetError() != GL_NO_ERROR)
    {
      ok = false;
      this->LastError = "could not copy the depth buffer (blit)";
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

bool vtkPlumeOpaqueDepthTexture::ResolveNearest(
  vtkOpenGLRenderWindow* window, int x, int y, int width, int height, int samples)
{
  vtkOpenGLState* state = window->GetState();
  // 1. the source's depth, sample for sample (same size, format and sample count: a plain copy)
  if (!this->Multisampled)
  {
    this->Multisampled = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTextureObject* ms = this->Multisampled;
  if (ms->GetContext() != window || !ms->GetHandle() || static_cast<int>(ms->GetWidth()) != width ||
    static_cast<int>(ms->GetHeight()) != height || ms->GetSamples() != samples ||
    this->Format != this->MultisampledFormat)
  {
    ms->ReleaseGraphicsResources(window);
    // a fresh object: AllocateDepth would keep an earlier internal format (see Capture)
    this->Multisampled = vtkSmartPointer<vtkTextureObject>::New();
    ms = this->Multisampled;
    ms->SetContext(window);
    ms->SetSamples(samples);
    if (!ms->AllocateDepth(width, height, this->Format))
    {
      return false;
    }
    this->MultisampledFormat = this->Format;
  }
  if (!this->MultisampleFramebuffer)
  {
    glGenFramebuffers(1, &this->MultisampleFramebuffer);
  }
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->PushDrawFramebufferBinding();
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->MultisampleFramebuffer);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D_MULTISAMPLE, ms->GetHandle(), 0);
  glDrawBuffer(GL_NONE);
  glBlitFramebuffer(x, y, x + width, y + height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  bool ok = glGetError() == GL_NO_ERROR;

  // 2. a full-screen pass writing each pixel's nearest sample into the depth texture
  if (ok)
  {
    if (!this->Quad)
    {
      this->Quad = new vtkOpenGLQuadHelper(
        window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), vtkPlumeDepthResolveFS, "");
    }
    else
    {
      window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
    }
    vtkShaderProgram* program = this->Quad->Program;
    ok = program && program->GetCompiled();
    if (ok)
    {
      state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->ResolveFramebuffer);
      glFramebufferTexture2D(
        GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, this->Texture->GetHandle(), 0);
      glDrawBuffer(GL_NONE);
      vtkOpenGLState::ScopedglViewport viewportSaver(state);
      vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
      vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
      vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
      vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
      state->vtkglViewport(0, 0, width, height);
      state->vtkglEnable(GL_DEPTH_TEST);
      state->vtkglDepthFunc(GL_ALWAYS);
      state->vtkglDepthMask(GL_TRUE);
      state->vtkglDisable(GL_BLEND);
      ms->Activate();
      program->SetUniformi("Source", ms->GetTextureUnit());
      program->SetUniformi("Samples", samples);
      this->Quad->Render();
      ms->Deactivate();
      ok = glGetError() == GL_NO_ERROR;
    }
  }
  state->PopDrawFramebufferBinding();
  return ok;
}

void vtkPlumeOpaqueDepthTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Origin: " << this->Origin[0] << " " << this->Origin[1] << "\n";
  os << indent << "Size: " << this->Size[0] << " " << this->Size[1] << "\n";
}
