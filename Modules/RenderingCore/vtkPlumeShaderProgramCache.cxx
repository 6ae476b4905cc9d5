#include "vtkPlumeShaderProgramCache.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkPlumeShaderFeatures.h"
#include "vtkPlumeShaderVariants.h"
#include "vtkShaderProgram.h"

#include <sstream>

vtkStandardNewMacro(vtkPlumeShaderProgramCache);

vtkPlumeShaderProgramCache::vtkPlumeShaderProgramCache() = default;
vtkPlumeShaderProgramCache::~vtkPlumeShaderProgramCache() = default;

vtkShaderProgram* vtkPlumeShaderProgramCache::Ready(vtkOpenGLRenderWindow* window, const char* vs,
  const char* gs, const char* fs, const vtkPlumeShaderFeatures& features)
{
  if (!window)
  {
    return nullptr;
  }
  if (window != this->Window)
  {
    this->Programs.clear();
    this->Window = window;
  }
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

void vtkPlumeShaderProgramCache::ReleaseGraphicsResources(vtkWindow*)
{
  this->Programs.clear(); // the programs themselves belong to the window's shader cache
  this->Window = nullptr;
}

void vtkPlumeShaderProgramCache::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Programs: " << this->Programs.size() << "\n";
  os << indent << "BuildCount: " << this->BuildCount << "\n";
}
