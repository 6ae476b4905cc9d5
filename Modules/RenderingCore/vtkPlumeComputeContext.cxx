#include "vtkPlumeComputeContext.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"

#include "vtk_glew.h"

#include <sstream>

vtkStandardNewMacro(vtkPlumeComputeContext);

vtkPlumeComputeContext::vtkPlumeComputeContext() = default;
vtkPlumeComputeContext::~vtkPlumeComputeContext() = default;

vtkOpenGLRenderWindow* vtkPlumeComputeContext::Resolve(vtkRenderWindow* given, std::string& error)
{
  vtkRenderWindow* window = given;
  if (!window)
  {
    if (!this->OwnWindow)
    {
      this->OwnWindow = vtkSmartPointer<vtkRenderWindow>::New();
      this->OwnWindow->SetOffScreenRendering(1);
      this->OwnWindow->SetMultiSamples(0);
      this->OwnWindow->SetSize(8, 8);
    }
    window = this->OwnWindow;
  }
  auto* ogl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!ogl)
  {
    error = std::string("the render window is a ") + window->GetClassName() + ", not a vtkOpenGLRenderWindow";
  }
  return ogl;
}

bool vtkPlumeComputeContext::MakeCurrent(vtkOpenGLRenderWindow* window, std::string& error)
{
  // A window that never rendered has no context yet: make one.
  window->MakeCurrent();
  if (!window->IsCurrent())
  {
    window->Initialize();
    window->MakeCurrent();
  }
  if (!window->IsCurrent())
  {
    error = "no OpenGL context (an offscreen window needs a display with this VTK)";
    return false;
  }
  return true;
}

std::string vtkPlumeComputeContext::DrainErrors()
{
  std::string errors;
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
  {
    std::ostringstream s;
    s << (errors.empty() ? "" : ", ") << "0x" << std::hex << e;
    errors += s.str();
  }
  return errors;
}

void vtkPlumeComputeContext::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OwnWindow: " << (this->OwnWindow ? "created" : "none") << "\n";
}
