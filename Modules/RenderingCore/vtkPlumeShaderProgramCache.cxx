#include "vtkPlumeShaderProgramCache.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkPlumeShaderFeatures.h"
#include "vtkPlumeShaderVariants.h"
#include "vtkShaderProgram.h"

#include <sstream>

vtkStandardNewMacro(vtkPlumeShaderProgramCache);

vtkPlumeShaderProgramCache::vtkPlumeShaderProgramCache() = default;
vtkPlumeShaderProgramCache::~vtkPlumeShaderProgramCache()
{
  this->DeleteQuads();
}

void vtkPlumeShaderProgramCache::DeleteQuads()
{
  for (auto& q : this->Quads)
  {
    delete q.second; // releases its vertex array through the window's resource callback
  }
  this->Quads.clear();
}

void vtkPlumeShaderProgramCache::SetWindow(vtkOpenGLRenderWindow* window)
{
  if (window != this->Window)
  {
    this->Programs.clear();
    this->DeleteQuads();
    this->Window = window;
  }
}

vtkShaderProgram* vtkPlumeShaderProgramCache::Ready(vtkOpenGLRenderWindow* window, const char* vs,
  const char* gs, const char* fs, const vtkPlumeShaderFeatures& features)
{
  if (!window)
  {
    return nullptr;
  }
  this->SetWindow(window);
  std::ostringstream key;
  key << static_cast<const void*>(vs) << "/" << static_cast<const void*>(gs) << "/"
      << static_cast<const void*>(fs) << "/" << features.GetKey();
  auto it = this->Programs.find(key.str());
  if (it != this->Programs.end())
  {
    if (vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(it->second))
    {
      return program;
    }
    this->Programs.erase(it);
  }
  const std::string defines = features.GetDefines();
  const std::string v = vtkPlumeShaderVariants::Select(vs, features.GetEnabled(), defines);
  const std::string g = gs ? vtkPlumeShaderVariants::Select(gs, features.GetEnabled(), defines) : std::string();
  const std::string f = vtkPlumeShaderVariants::Select(fs, features.GetEnabled(), defines);
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(v.c_str(), f.c_str(), g.c_str());
  ++this->BuildCount;
  if (program)
  {
    this->Programs[key.str()] = program;
  }
  return program;
}

vtkOpenGLQuadHelper* vtkPlumeShaderProgramCache::ReadyQuad(
  vtkOpenGLRenderWindow* window, const char* fs, const vtkPlumeShaderFeatures& features)
{
  if (!window)
  {
    return nullptr;
  }
  this->SetWindow(window);
  std::ostringstream key;
  key << static_cast<const void*>(fs) << "/" << features.GetKey();
  auto it = this->Quads.find(key.str());
  if (it != this->Quads.end())
  {
    if (window->GetShaderCache()->ReadyShaderProgram(it->second->Program))
    {
      return it->second;
    }
    delete it->second;
    this->Quads.erase(it);
  }
  const std::string f = vtkPlumeShaderVariants::Select(fs, features.GetEnabled(), features.GetDefines());
  auto* quad = new vtkOpenGLQuadHelper(
    window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), f.c_str(), "");
  ++this->BuildCount;
  if (!quad->Program || !quad->Program->GetCompiled())
  {
    delete quad;
    return nullptr;
  }
  this->Quads[key.str()] = quad;
  return quad;
}

void vtkPlumeShaderProgramCache::ReleaseGraphicsResources(vtkWindow*)
{
  this->Programs.clear(); // the programs themselves belong to the window's shader cache
  this->DeleteQuads();
  this->Window = nullptr;
}

void vtkPlumeShaderProgramCache::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Programs: " << this->Programs.size() << "\n";
  os << indent << "Quads: " << this->Quads.size() << "\n";
  os << indent << "BuildCount: " << this->BuildCount << "\n";
}
