#include "plumeSplatGPU.h"
#include "vtkPlumeShaderFeatures.h"
#include "vtkPlumeShaderProgramCache.h"

#include "vtkPlumeSplatFS.h"
#include "vtkPlumeSplatGS.h"
#include "vtkPlumeSplatVS.h"

#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPlumeComputeContext.h"
#include "vtkPlumeTexture3DSize.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include "vtk_glew.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace plume
{
namespace splat
{
namespace
{
// Per-batch limits: floats in the buffers hold integers exactly below 2^24.
constexpr size_t MaxBatchSplats = 1 << 16;
constexpr size_t MaxBatchWeights = 1 << 22;

}

class SplatGPU::Internals
{
public:
  vtkNew<vtkPlumeComputeContext> Compute; // the user's window or an own offscreen one
  vtkOpenGLRenderWindow* Window = nullptr; // the context the GL objects below belong to
  vtkSmartPointer<vtkOpenGLVertexArrayObject> VAO;
  vtkSmartPointer<vtkOpenGLBufferObject> SplatBuffer;
  vtkSmartPointer<vtkOpenGLBufferObject> WeightBuffer;
  vtkSmartPointer<vtkTextureObject> SplatTexture;
  vtkSmartPointer<vtkTextureObject> WeightTexture;
  vtkSmartPointer<vtkTextureObject> Target;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkNew<vtkPlumeShaderProgramCache> Programs;

  void Release()
  {
    if (!this->Window)
    {
      return;
    }
    this->Window->MakeCurrent();
    for (vtkTextureObject* t : { this->SplatTexture.Get(), this->WeightTexture.Get(), this->Target.Get() })
    {
      if (t)
      {
        t->ReleaseGraphicsResources(this->Window);
      }
    }
    for (vtkOpenGLBufferObject* b : { this->SplatBuffer.Get(), this->WeightBuffer.Get() })
    {
      if (b)
      {
        b->ReleaseGraphicsResources();
      }
    }
    if (this->VAO)
    {
      this->VAO->ReleaseGraphicsResources();
    }
    if (this->Framebuffer)
    {
      this->Framebuffer->ReleaseGraphicsResources(this->Window);
    }
    this->SplatTexture = this->WeightTexture = this->Target = nullptr;
    this->SplatBuffer = this->WeightBuffer = nullptr;
    this->VAO = nullptr;
    this->Framebuffer = nullptr;
    this->Programs->ReleaseGraphicsResources(nullptr);
    this->Window = nullptr;
  }

  vtkOpenGLRenderWindow* Context(vtkRenderWindow* given, std::string& error)
  {
    vtkOpenGLRenderWindow* ogl = this->Compute->Resolve(given, error);
    if (!ogl)
    {
      return nullptr;
    }
    if (this->Window && this->Window != ogl)
    {
      this->Release();
    }
    if (!vtkPlumeComputeContext::MakeCurrent(ogl, error))
    {
      return nullptr;
    }
    this->Window = ogl;
    return ogl;
  }
};

SplatGPU::SplatGPU()
  : Impl(new Internals)
{
}

SplatGPU::~SplatGPU()
{
  this->Release();
}

vtkTextureObject* SplatGPU::GetResult(vtkOpenGLRenderWindow*& window)
{
  window = this->Impl->Window;
  return this->Impl->Target;
}

void SplatGPU::Release()
{
  this->Impl->Release();
}

bool SplatGPU::Run(vtkRenderWindow* window, const Grid& grid, const Settings& settings,
  const std::vector<Splat>& splats, float* out, size_t& touched, std::string& error)
{
  Internals& impl = *this->Impl;
  touched = 0;
  vtkOpenGLRenderWindow* win = impl.Context(window, error);
  if (!win)
  {
    return false;
  }
  vtkPlumeComputeContext::DrainErrors(); // not ours
  const bool sum = settings.Mode == Kind::Sum;
  const int comps = settings.Components;

  int max3D = 0; // asked each run: the context may differ
  error = plume::Check3DTextureSize(win, grid.Dims, max3D);
  if (!error.empty())
  {
    return false;
  }
  GLint maxBuffer = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxBuffer);
  if (size_t(maxBuffer) < MaxBatchWeights || size_t(maxBuffer) < 3 * MaxBatchSplats)
  {
    error = "GL_MAX_TEXTURE_BUFFER_SIZE " + std::to_string(maxBuffer) + " is too small";
    return false;
  }

  // ---- render target: a float 3D texture, all layers attached (layered FBO)
  const int targetComps = comps == 3 ? 4 : 1; // RGB32F is not colour-renderable everywhere
  if (!impl.Target || int(impl.Target->GetWidth()) != grid.Dims[0] ||
    int(impl.Target->GetHeight()) != grid.Dims[1] || int(impl.Target->GetDepth()) != grid.Dims[2] ||
    impl.Target->GetComponents() != targetComps)
  {
    if (impl.Target)
    {
      impl.Target->ReleaseGraphicsResources(win);
    }
    impl.Target = vtkSmartPointer<vtkTextureObject>::New();
    impl.Target->SetContext(win);
    if (!impl.Target->Create3DFromRaw(grid.Dims[0], grid.Dims[1], grid.Dims[2], targetComps, VTK_FLOAT, nullptr))
    {
      impl.Target = nullptr;
      error = "could not create the float 3D texture";
      return false;
    }
  }
  if (!impl.Framebuffer)
  {
    impl.Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    impl.Framebuffer->SetContext(win);
  }
  if (!impl.VAO)
  {
    impl.VAO = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
    impl.SplatBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    impl.WeightBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    impl.SplatTexture = vtkSmartPointer<vtkTextureObject>::New();
    impl.SplatTexture->SetContext(win);
    impl.WeightTexture = vtkSmartPointer<vtkTextureObject>::New();
    impl.WeightTexture->SetContext(win);
  }

  // ---- program (only the variant in use is compiled)
  vtkPlumeShaderFeatures features;
  features.Enable(sum ? "SUM" : "DISTANCE");
  vtkShaderProgram* program = impl.Programs->Ready(win, vtkPlumeSplatVS, vtkPlumeSplatGS, vtkPlumeSplatFS, features);
  if (!program)
  {
    error = "could not build the splat shader program (" + features.GetKey() + ")";
    return false;
  }

  vtkOpenGLState* state = win->GetState();
  state->PushFramebufferBindings();
  impl.Framebuffer->Bind(GL_FRAMEBUFFER);
  glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, impl.Target->GetHandle(), 0);
  const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &drawBuffer);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
  {
    state->PopFramebufferBindings();
    std::ostringstream s;
    s << "layered framebuffer incomplete (0x" << std::hex << status << ")";
    error = s.str();
    return false;
  }

  {
    vtkOpenGLState::ScopedglViewport viewport(state);
    vtkOpenGLState::ScopedglClearColor clearColor(state);
    vtkOpenGLState::ScopedglColorMask colorMask(state);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
    vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depth(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
    state->vtkglViewport(0, 0, grid.Dims[0], grid.Dims[1]);
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_SCISSOR_TEST); // before the clear: VTK leaves a scissor box behind
    // vectors: a = 1 (the fragment shader adds 0), the valid mask of the
    // layout Plume's glyph mapper uploads, so the texture can be handed over
    state->vtkglClearColor(0, 0, 0, targetComps == 4 ? 1 : 0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT); // every layer of a layered attachment
    state->vtkglDisable(GL_CULL_FACE);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFunc(GL_ONE, GL_ONE);
    state->vtkglBlendEquation(sum ? GL_FUNC_ADD : GL_MAX);

    const float gridXY[2] = { float(grid.Dims[0]), float(grid.Dims[1]) };
    program->SetUniform2f("GridXY", gridXY);
    if (!sum)
    {
      const float spacing[3] = { float(grid.Spacing[0]), float(grid.Spacing[1]), float(grid.Spacing[2]) };
      program->SetUniform3f("Spacing", spacing);
    }
    impl.VAO->Bind();

    // ---- batches: footprints and weights on the CPU, grouped by slice count
    struct Item
    {
      int Lo[3];
      int N[3];
      size_t Splat;
    };
    std::vector<Item> items;
    std::vector<float> texels, weights;
    size_t next = 0;
    while (next < splats.size())
    {
      items.clear();
      size_t batchWeights = 0;
      for (; next < splats.size() && items.size() < MaxBatchSplats; ++next)
      {
        const Splat& sp = splats[next];
        const double reach = sum ? settings.Cutoff * sp.Radius : sp.Radius;
        Item it;
        int hi[3];
        bool touches = true;
        for (int a = 0; a < 3 && touches; ++a)
        {
          touches = AxisSpan(grid, a, sp.Center[a], reach, sum && settings.Integrate, it.Lo[a], hi[a]);
          if (touches) // else the span is undefined (UBSan: overflow on a far-away splat)
          {
            it.N[a] = hi[a] - it.Lo[a] + 1;
          }
        }
        if (!touches)
        {
          continue;
        }
        const size_t w = sum ? size_t(it.N[0]) + it.N[1] + it.N[2] : 0;
        if (batchWeights + w > MaxBatchWeights && !items.empty())
        {
          break; // this splat starts the next batch
        }
        batchWeights += w;
        it.Splat = next;
        items.push_back(it);
      }
      if (items.empty())
      {
        continue;
      }
      touched += items.size();
      std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.N[2] < b.N[2]; });
      texels.assign(12 * items.size(), 0.0f);
      weights.assign(std::max<size_t>(1, batchWeights), 0.0f);
      size_t base = 0;
      for (size_t m = 0; m < items.size(); ++m)
      {
        const Item& it = items[m];
        const Splat& sp = splats[it.Splat];
        float* t = &texels[12 * m];
        for (int a = 0; a < 3; ++a)
        {
          t[a] = float(it.Lo[a]);
          t[4 + a] = float(it.N[a]);
        }
        if (sum)
        {
          t[3] = float(base);
          for (int a = 0; a < 3; ++a)
          {
            t[8 + a] = float(sp.Value[a]);
            AxisWeights(grid, a, sp.Center[a], sp.Radius, settings.Integrate, it.Lo[a], it.Lo[a] + it.N[a] - 1,
              &weights[base]);
            base += it.N[a];
          }
        }
        else
        {
          t[3] = float(sp.Value[0]);
          for (int a = 0; a < 3; ++a)
          {
            t[8 + a] = float((sp.Center[a] - grid.Origin[a]) / grid.Spacing[a]);
          }
          t[11] = float(sp.Radius);
        }
      }
      impl.SplatBuffer->Upload(texels, vtkOpenGLBufferObject::TextureBuffer);
      impl.SplatTexture->CreateTextureBuffer(
        static_cast<unsigned int>(items.size() * 3), 4, VTK_FLOAT, impl.SplatBuffer);
      impl.SplatTexture->Activate();
      program->SetUniformi("Splats", impl.SplatTexture->GetTextureUnit());
      if (sum)
      {
        impl.WeightBuffer->Upload(weights, vtkOpenGLBufferObject::TextureBuffer);
        impl.WeightTexture->CreateTextureBuffer(
          static_cast<unsigned int>(weights.size()), 1, VTK_FLOAT, impl.WeightBuffer);
        impl.WeightTexture->Activate();
        program->SetUniformi("Weights", impl.WeightTexture->GetTextureUnit());
      }
      // one instanced draw per slice count: instance = splat, vertex = slice
      for (size_t g = 0; g < items.size();)
      {
        size_t e = g;
        while (e < items.size() && items[e].N[2] == items[g].N[2])
        {
          ++e;
        }
        program->SetUniformi("FirstSplat", static_cast<int>(g));
        glDrawArraysInstanced(GL_POINTS, 0, items[g].N[2], static_cast<GLsizei>(e - g));
        g = e;
      }
      impl.SplatTexture->Deactivate();
      if (sum)
      {
        impl.WeightTexture->Deactivate();
      }
    }
    impl.VAO->Release();
    state->vtkglBlendEquation(GL_FUNC_ADD);
  }
  state->PopFramebufferBindings();

  // ---- read back
  impl.Target->Activate();
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTexImage(GL_TEXTURE_3D, 0, comps == 3 ? GL_RGB : GL_RED, GL_FLOAT, out);
  impl.Target->Deactivate();
  const std::string errors = vtkPlumeComputeContext::DrainErrors();
  if (!errors.empty())
  {
    error = "GL error " + errors;
    return false;
  }
  return true;
}
}
}
