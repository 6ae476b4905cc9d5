#include "vtkPlumeComputeContext.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"

#include "vtk_glew.h"

#include <cstdlib>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkPlumeComputeContext);

namespace
{
// Whether the render window VTK makes by default is an X window and no
// display is named. Asked of the object factory without opening anything.
bool NeedsXDisplay()
{
  const char* display = std::getenv("DISPLAY");
  if (display && *display)
  {
    return false;
  }
  vtkSmartPointer<vtkRenderWindow> probe = vtkSmartPointer<vtkRenderWindow>::New();
  return probe && std::string(probe->GetClassName()) == "vtkXOpenGLRenderWindow";
}
}

vtkPlumeComputeContext::vtkPlumeComputeContext() = default;
vtkPlumeComputeContext::~vtkPlumeComputeContext() = default;

vtkOpenGLRenderWindow* vtkPlumeComputeContext::Resolve(vtkRenderWindow* given, std::string& error)
{
  vtkRenderWindow* window = given;
  if (!window)
  {
    // VTK's X window aborts the process when it cannot open a display: say so
    // instead (the usual headless case: DISPLAY unset). A window handed over,
    // e.g. plume's OSMesa one, needs no display.
    if (!this->OwnWindow && NeedsXDisplay())
    {
      error = "no OpenGL context: this VTK's offscreen window needs an X display and DISPLAY is not set "
              "(run under an X server, e.g. xvfb-run, or hand the computation a render window)";
      return nullptr;
    }
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
