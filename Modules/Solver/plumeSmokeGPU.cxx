#include "plumeSmokeGPU.h"

#include "vtkPlumePingPongTexture3D.h"
#include "vtkPlumeShaderFeatures.h"
#include "vtkPlumeShaderProgramCache.h"

#include "vtkPlumeSmokeFS.h"
#include "vtkPlumeSmokeGS.h"
#include "vtkPlumeSmokeVS.h"

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPlumeComputeContext.h"
#include "vtkPlumeTexture3DSize.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include "vtk_glew.h"

#include <algorithm>
#include <initializer_list>
#include <sstream>
#include <utility>

namespace plume
{
namespace smoke
{
namespace
{

using Binding = std::pair<const char*, vtkTextureObject*>;

// vtkShaderProgram has no ivec3 setter (location -1, a uniform the pass does not use, is ignored by GL)
void SetIVec3(vtkShaderProgram* program, const char* name, int count, const int* values)
{
  glUniform3iv(program->FindUniform(name), count, values);
}
}

class SmokeGPU::Internals
{
public:
  vtkNew<vtkPlumeComputeContext> Compute; // the user's window or an own offscreen one
  vtkOpenGLRenderWindow* Window = nullptr;
  GPUGrid Grid{};
  vtkNew<vtkPlumePingPongTexture3D> U[3];
  vtkNew<vtkPlumePingPongTexture3D> Density;
  vtkNew<vtkPlumePingPongTexture3D> Temperature;
  vtkNew<vtkPlumePingPongTexture3D> Pressure;
  vtkSmartPointer<vtkTextureObject> Solid;
  vtkSmartPointer<vtkTextureObject> RHS;          // (-div u, the Poisson diagonal)
  vtkSmartPointer<vtkTextureObject> CellVelocity; // RGBA32F, for the glyph mapper
  vtkSmartPointer<vtkTextureObject> SourceCells;    // covering source + 1 per cell (0: none)
  vtkSmartPointer<vtkTextureObject> SourceFaces[3]; // the same per face (velocity sources); null: none
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> VAO;
  vtkNew<vtkPlumeShaderProgramCache> Programs;
  bool HasState = false;
  int PassCount = 0;

  void Release()
  {
    if (!this->Window)
    {
      return;
    }
    this->Window->MakeCurrent();
    for (auto& u : this->U)
    {
      u->ReleaseGraphicsResources(this->Window);
    }
    this->Density->ReleaseGraphicsResources(this->Window);
    this->Temperature->ReleaseGraphicsResources(this->Window);
    this->Pressure->ReleaseGraphicsResources(this->Window);
    this->ReleaseSourceMasks();
    for (vtkTextureObject* t : { this->Solid.Get(), this->RHS.Get(), this->CellVelocity.Get() })
    {
      if (t)
      {
        t->ReleaseGraphicsResources(this->Window);
      }
    }
    this->Solid = this->RHS = this->CellVelocity = nullptr;
    if (this->Framebuffer)
    {
      this->Framebuffer->ReleaseGraphicsResources(this->Window);
      this->Framebuffer = nullptr;
    }
    if (this->VAO)
    {
      this->VAO->ReleaseGraphicsResources();
      this->VAO = nullptr;
    }
    this->Programs->ReleaseGraphicsResources(nullptr);
    this->Window = nullptr;
    this->HasState = false;
  }

  void ReleaseSourceMasks()
  {
    for (auto* t : { &this->SourceCells, &this->SourceFaces[0], &this->SourceFaces[1], &this->SourceFaces[2] })
    {
      if (*t)
      {
        (*t)->ReleaseGraphicsResources(this->Window);
        *t = nullptr;
      }
    }
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

  vtkSmartPointer<vtkTextureObject> Texture3D(const int dims[3], int components, const float* data)
  {
    auto t = vtkSmartPointer<vtkTextureObject>::New();
    t->SetContext(this->Window);
    t->SetMinificationFilter(vtkTextureObject::Nearest);
    t->SetMagnificationFilter(vtkTextureObject::Nearest);
    t->SetWrapS(vtkTextureObject::ClampToEdge);
    t->SetWrapT(vtkTextureObject::ClampToEdge);
    t->SetWrapR(vtkTextureObject::ClampToEdge);
    if (!t->Create3DFromRaw(dims[0], dims[1], dims[2], components, VTK_FLOAT, const_cast<float*>(data)))
    {
      return nullptr;
    }
    return t;
  }

  /** The program of one pass (compiled on first use), bound, with the grid's uniforms set. */
  vtkShaderProgram* Program(const char* pass, int axis)
  {
    vtkPlumeShaderFeatures features;
    features.Enable(pass);
    vtkShaderProgram* program =
      this->Programs->Ready(this->Window, vtkPlumeSmokeVS, vtkPlumeSmokeGS, vtkPlumeSmokeFS, features);
    if (!program)
    {
      return nullptr;
    }
    const GPUGrid& g = this->Grid;
    const int cells[3] = { g.Cells[0], g.Cells[1], g.Cells[2] };
    const int lo[3] = { g.Open[0], g.Open[2], g.Open[4] };
    const int hi[3] = { g.Open[1], g.Open[3], g.Open[5] };
    const float h[3] = { float(g.H[0]), float(g.H[1]), float(g.H[2]) };
    // a uniform the pass does not use is optimised away: SetUniform then fails harmlessly
    SetIVec3(program, "Cells", 1, cells);
    SetIVec3(program, "OpenLo", 1, lo);
    SetIVec3(program, "OpenHi", 1, hi);
    program->SetUniform3f("H", h);
    program->SetUniformi("Axis", axis);
    return program;
  }

  /** One layered pass: every texel of `target` (all its slices) from `inputs`. */
  bool Draw(vtkShaderProgram* program, std::initializer_list<Binding> inputs, vtkTextureObject* target,
    std::string& error)
  {
    std::vector<vtkTextureObject*> active;
    for (const Binding& b : inputs)
    {
      b.second->Activate();
      program->SetUniformi(b.first, b.second->GetTextureUnit());
      active.push_back(b.second);
    }
    if (this->Solid)
    {
      this->Solid->Activate();
      program->SetUniformi("Solid", this->Solid->GetTextureUnit());
      active.push_back(this->Solid);
    }
    glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target->GetHandle(), 0);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    bool ok = status == GL_FRAMEBUFFER_COMPLETE;
    if (!ok)
    {
      std::ostringstream s;
      s << "layered framebuffer incomplete (0x" << std::hex << status << ")";
      error = s.str();
    }
    else
    {
      this->Window->GetState()->vtkglViewport(0, 0, int(target->GetWidth()), int(target->GetHeight()));
      glDrawArrays(GL_POINTS, 0, GLsizei(target->GetDepth()));
      ++this->PassCount;
    }
    for (vtkTextureObject* t : active)
    {
      t->Deactivate();
    }
    return ok;
  }

  /** Runs `body` with the framebuffer bound and the fixed-function state a full-grid pass needs. */
  template <class F>
  bool Passes(F&& body, std::string& error)
  {
    if (!this->HasState || !this->Window)
    {
      error = "the GPU backend holds no state (upload first)";
      return false;
    }
    this->Window->MakeCurrent();
    vtkPlumeComputeContext::DrainErrors(); // not ours
    vtkOpenGLState* state = this->Window->GetState();
    state->PushFramebufferBindings();
    this->Framebuffer->Bind(GL_FRAMEBUFFER);
    const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &drawBuffer);
    bool ok;
    {
      vtkOpenGLState::ScopedglViewport viewport(state);
      vtkOpenGLState::ScopedglColorMask colorMask(state);
      vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
      vtkOpenGLState::ScopedglEnableDisable depth(state, GL_DEPTH_TEST);
      vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
      vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
      state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      state->vtkglDisable(GL_BLEND);
      state->vtkglDisable(GL_DEPTH_TEST);
      state->vtkglDisable(GL_SCISSOR_TEST);
      state->vtkglDisable(GL_CULL_FACE);
      this->VAO->Bind();
      ok = body();
      this->VAO->Release();
    }
    state->PopFramebufferBindings();
    const std::string errors = vtkPlumeComputeContext::DrainErrors();
    if (ok && !errors.empty())
    {
      error = "GL error " + errors;
      ok = false;
    }
    return ok;
  }
};

SmokeGPU::SmokeGPU()
  : Impl(new Internals)
{
}

SmokeGPU::~SmokeGPU()
{
  this->Release();
}

void SmokeGPU::Release()
{
  this->Impl->Release();
}

vtkOpenGLRenderWindow* SmokeGPU::GetWindow() const
{
  return this->Impl->Window;
}

vtkTextureObject* SmokeGPU::GetDensityTexture() const
{
  return this->Impl->HasState ? this->Impl->Density->GetFront() : nullptr;
}

vtkTextureObject* SmokeGPU::GetCellVelocityTexture() const
{
  return this->Impl->CellVelocity;
}

int SmokeGPU::GetLastPassCount() const
{
  return this->Impl->PassCount;
}

bool SmokeGPU::Upload(vtkRenderWindow* window, const GPUGrid& grid, const std::vector<double> u[3],
  const std::vector<double>& density, const std::vector<double>& temperature,
  const std::vector<unsigned char>& solid, std::string& error)
{
  Internals& impl = *this->Impl;
  impl.HasState = false;
  vtkOpenGLRenderWindow* win = impl.Context(window, error);
  if (!win)
  {
    return false;
  }
  vtkPlumeComputeContext::DrainErrors();
  // the face-velocity textures are one larger than the cells along each axis
  const int faces[3] = { grid.Cells[0] + 1, grid.Cells[1] + 1, grid.Cells[2] + 1 };
  int max3D = 0; // asked each time: the context may differ
  error = plume::Check3DTextureSize(win, faces, max3D);
  if (!error.empty())
  {
    return false;
  }
  impl.Grid = grid;
  const int* n = grid.Cells;
  std::vector<float> values;
  auto upload = [&](vtkPlumePingPongTexture3D* texture, const int dims[3], const std::vector<double>& v) {
    if (!texture->Allocate(win, dims, 1))
    {
      error = texture->GetLastError();
      return false;
    }
    values.assign(v.begin(), v.end());
    return texture->Upload(values.data());
  };
  for (int d = 0; d < 3; ++d)
  {
    int m[3] = { n[0], n[1], n[2] };
    ++m[d];
    if (!upload(impl.U[d], m, u[d]))
    {
      return false;
    }
  }
  const std::vector<double> zero(density.size(), 0.0);
  if (!upload(impl.Density, n, density) || !upload(impl.Temperature, n, temperature) ||
    !upload(impl.Pressure, n, zero))
  {
    return false;
  }
  values.assign(solid.begin(), solid.end());
  for (vtkTextureObject* t : { impl.Solid.Get(), impl.RHS.Get(), impl.CellVelocity.Get() })
  {
    if (t)
    {
      t->ReleaseGraphicsResources(win);
    }
  }
  impl.Solid = impl.Texture3D(n, 1, values.data());
  impl.RHS = impl.Texture3D(n, 2, nullptr); // (b, diagonal): RG32F
  impl.CellVelocity = impl.Texture3D(n, 4, nullptr);
  if (!impl.Solid || !impl.RHS || !impl.CellVelocity)
  {
    error = "could not create the solver's float 3D textures";
    return false;
  }
  if (!impl.Framebuffer)
  {
    impl.Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    impl.Framebuffer->SetContext(win);
  }
  if (!impl.VAO)
  {
    impl.VAO = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
  }
  const std::string errors = vtkPlumeComputeContext::DrainErrors();
  if (!errors.empty())
  {
    error = "GL error " + errors + " while uploading the state";
    return false;
  }
  impl.HasState = true;
  return true;
}

bool SmokeGPU::SetSourceMasks(
  const std::vector<float>& cells, const std::vector<float> faces[3], std::string& error)
{
  Internals& impl = *this->Impl;
  if (!impl.HasState)
  {
    error = "the GPU backend holds no state (upload first)";
    return false;
  }
  impl.Window->MakeCurrent();
  impl.ReleaseSourceMasks();
  const int* n = impl.Grid.Cells;
  if (!cells.empty())
  {
    impl.SourceCells = impl.Texture3D(n, 1, cells.data());
    if (!impl.SourceCells)
    {
      error = "could not create the source texture";
      return false;
    }
  }
  for (int d = 0; d < 3; ++d)
  {
    if (faces[d].empty())
    {
      continue;
    }
    int m[3] = { n[0], n[1], n[2] };
    ++m[d];
    impl.SourceFaces[d] = impl.Texture3D(m, 1, faces[d].data());
    if (!impl.SourceFaces[d])
    {
      error = "could not create the source face texture";
      return false;
    }
  }
  return true;
}

bool SmokeGPU::Step(const GPUStepSettings& s, std::string& error)
{
  Internals& impl = *this->Impl;
  if (int(s.Sources.size()) > MaxSources)
  {
    error = "the GPU backend applies at most " + std::to_string(MaxSources) + " sources, got " +
      std::to_string(s.Sources.size());
    return false;
  }
  impl.PassCount = 0;
  return impl.Passes(
    [&]() -> bool {
      const GPUGrid& g = impl.Grid;
      auto fail = [&](const char* pass) {
        if (error.empty())
        {
          error = std::string("could not build the smoke shader program (") + pass + ")";
        }
        return false;
      };
      vtkTextureObject* u0 = impl.U[0]->GetFront();
      vtkTextureObject* u1 = impl.U[1]->GetFront();
      vtkTextureObject* u2 = impl.U[2]->GetFront();
      // 1. advection by the velocity at the start of the step (scalars, then the three components)
      vtkShaderProgram* p = nullptr;
      auto advect = [&](vtkPlumePingPongTexture3D* field, int axis, double decay, double target) {
        vtkShaderProgram* prog = impl.Program("ADVECT", axis);
        if (!prog)
        {
          return fail("ADVECT");
        }
        prog->SetUniformf("Dt", float(s.Dt));
        prog->SetUniformf("Decay", float(decay));
        prog->SetUniformf("Target", float(target));
        return impl.Draw(prog, { { "Source", field->GetFront() }, { "U0", u0 }, { "U1", u1 }, { "U2", u2 } },
          field->GetBack(), error);
      };
      if (!advect(impl.Density, -1, s.DensityDecay, 0.0) ||
        !advect(impl.Temperature, -1, s.TemperatureDecay, s.Ambient))
      {
        return false;
      }
      impl.Density->Swap();
      impl.Temperature->Swap();
      for (int d = 0; d < 3; ++d)
      {
        if (!advect(impl.U[d], d, s.VelocityDecay, 0.0))
        {
          return false;
        }
      }
      for (int d = 0; d < 3; ++d)
      {
        impl.U[d]->Swap();
      }
      // 2. buoyancy on the faces along up
      for (int d = 0; d < 3; ++d)
      {
        if (s.Up[d] == 0)
        {
          continue;
        }
        p = impl.Program("BUOYANCY", d);
        if (!p)
        {
          return fail("BUOYANCY");
        }
        p->SetUniformf("Factor", float(s.Dt * s.Up[d]));
        p->SetUniformf("Buoyancy", float(s.Buoyancy));
        p->SetUniformf("SmokeWeight", float(s.SmokeWeight));
        p->SetUniformf("Ambient", float(s.Ambient));
        if (!impl.Draw(p,
              { { "Source", impl.U[d]->GetFront() }, { "Density", impl.Density->GetFront() },
                { "Temperature", impl.Temperature->GetFront() } },
              impl.U[d]->GetBack(), error))
        {
          return false;
        }
        impl.U[d]->Swap();
      }
      // 3. sources (the seed's immortal candle): which source (if any) covers each
      // cell and face was decided on the CPU, in double, by the CPU backend's own
      // test (a cell at exactly the radius is in or out as there); the passes
      // set the covering source's values
      if (!s.Sources.empty() && impl.SourceCells)
      {
        const int count = int(s.Sources.size());
        std::vector<float> values(count);
        p = impl.Program("SOURCE_CELLS", -1);
        if (!p)
        {
          return fail("SOURCE_CELLS");
        }
        for (int which = 0; which < 2; ++which)
        {
          for (int i = 0; i < count; ++i)
          {
            values[i] = float(which == 0 ? s.Sources[i].Density : s.Sources[i].Temperature);
          }
          p->SetUniform1fv("SourceValue", count, values.data());
          vtkPlumePingPongTexture3D* field = which == 0 ? impl.Density.Get() : impl.Temperature.Get();
          if (!impl.Draw(p, { { "Source", field->GetFront() }, { "SourceIndex", impl.SourceCells } },
                field->GetBack(), error))
          {
            return false;
          }
          field->Swap();
        }
        for (int d = 0; d < 3; ++d)
        {
          if (!impl.SourceFaces[d])
          {
            continue; // no source with a velocity
          }
          p = impl.Program("SOURCE_FACES", d);
          if (!p)
          {
            return fail("SOURCE_FACES");
          }
          for (int i = 0; i < count; ++i)
          {
            values[i] = float(s.Sources[i].Velocity[d]);
          }
          p->SetUniform1fv("SourceValue", count, values.data());
          if (!impl.Draw(p, { { "Source", impl.U[d]->GetFront() }, { "SourceIndex", impl.SourceFaces[d] } },
                impl.U[d]->GetBack(), error))
          {
            return false;
          }
          impl.U[d]->Swap();
        }
      }
      // 4. projection: b = -div u, Jacobi from q = 0, u -= grad q
      p = impl.Program("DIVERGENCE", -1);
      if (!p)
      {
        return fail("DIVERGENCE");
      }
      if (!impl.Draw(p,
            { { "U0", impl.U[0]->GetFront() }, { "U1", impl.U[1]->GetFront() }, { "U2", impl.U[2]->GetFront() } },
            impl.RHS, error))
      {
        return false;
      }
      // the seed's ClearSurface(Pressure.Ping, 0)
      glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, impl.Pressure->GetFront()->GetHandle(), 0);
      const float zero[4] = { 0, 0, 0, 0 };
      glClearBufferfv(GL_COLOR, 0, zero);
      p = impl.Program("JACOBI", -1);
      if (!p)
      {
        return fail("JACOBI");
      }
      const float invH2[3] = { float(1.0 / (g.H[0] * g.H[0])), float(1.0 / (g.H[1] * g.H[1])),
        float(1.0 / (g.H[2] * g.H[2])) };
      p->SetUniform3f("InvH2", invH2);
      p->SetUniformf("Weight", float(s.JacobiWeight));
      for (int it = 0; it < s.JacobiIterations; ++it)
      {
        if (!impl.Draw(p, { { "Pressure", impl.Pressure->GetFront() }, { "B", impl.RHS } },
              impl.Pressure->GetBack(), error))
        {
          return false;
        }
        impl.Pressure->Swap();
      }
      for (int d = 0; d < 3; ++d)
      {
        p = impl.Program("GRADIENT", d);
        if (!p)
        {
          return fail("GRADIENT");
        }
        if (!impl.Draw(p, { { "Source", impl.U[d]->GetFront() }, { "Pressure", impl.Pressure->GetFront() } },
              impl.U[d]->GetBack(), error))
        {
          return false;
        }
        impl.U[d]->Swap();
      }
      return true;
    },
    error);
}

bool SmokeGPU::CellVelocity(float* rgba, std::string& error)
{
  Internals& impl = *this->Impl;
  const bool ok = impl.Passes(
    [&]() -> bool {
      vtkShaderProgram* p = impl.Program("CELL_VELOCITY", -1);
      if (!p)
      {
        error = "could not build the smoke shader program (CELL_VELOCITY)";
        return false;
      }
      return impl.Draw(p,
        { { "U0", impl.U[0]->GetFront() }, { "U1", impl.U[1]->GetFront() }, { "U2", impl.U[2]->GetFront() } },
        impl.CellVelocity, error);
    },
    error);
  if (!ok || !rgba)
  {
    return ok;
  }
  impl.CellVelocity->Activate();
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_FLOAT, rgba);
  impl.CellVelocity->Deactivate();
  const std::string errors = vtkPlumeComputeContext::DrainErrors();
  if (!errors.empty())
  {
    error = "GL error " + errors + " reading the cell velocity";
    return false;
  }
  return true;
}

bool SmokeGPU::TrivialPasses(int passes, std::string& error)
{
  Internals& impl = *this->Impl;
  const bool ok = impl.Passes(
    [&]() -> bool {
      vtkShaderProgram* p = impl.Program("TRIVIAL", -1);
      if (!p)
      {
        error = "could not build the smoke shader program (TRIVIAL)";
        return false;
      }
      for (int i = 0; i < passes; ++i)
      {
        if (!impl.Draw(p, {}, impl.RHS, error))
        {
          return false;
        }
      }
      return true;
    },
    error);
  glFinish();
  return ok;
}

void SmokeGPU::Finish()
{
  if (this->Impl->Window)
  {
    this->Impl->Window->MakeCurrent();
    glFinish();
  }
}

bool SmokeGPU::Download(std::vector<double> u[3], std::vector<double>& density, std::vector<double>& temperature,
  std::vector<double>& q, std::string& error)
{
  Internals& impl = *this->Impl;
  if (!impl.HasState)
  {
    error = "the GPU backend holds no state";
    return false;
  }
  impl.Window->MakeCurrent();
  vtkPlumeComputeContext::DrainErrors();
  std::vector<float> values;
  auto download = [&](vtkPlumePingPongTexture3D* texture, std::vector<double>& out) {
    const int* m = texture->GetDimensions();
    values.resize(size_t(m[0]) * m[1] * m[2]);
    texture->Download(values.data());
    out.assign(values.begin(), values.end());
  };
  for (int d = 0; d < 3; ++d)
  {
    download(impl.U[d], u[d]);
  }
  download(impl.Density, density);
  download(impl.Temperature, temperature);
  download(impl.Pressure, q);
  const std::string errors = vtkPlumeComputeContext::DrainErrors();
  if (!errors.empty())
  {
    error = "GL error " + errors + " reading the state back";
    return false;
  }
  return true;
}
}
}
