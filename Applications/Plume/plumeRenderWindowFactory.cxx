// SPDX-License-Identifier: BSD-3-Clause
#include "plumeRenderWindowFactory.h"

#include "plumeGLXShim.h"

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLRenderWindow.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <unistd.h>
#include <vector>

#ifdef PLUME_HAVE_OSMESA
#ifndef _GNU_SOURCE
#define _GNU_SOURCE 1
#endif
#include <dlfcn.h>

// After the VTK headers: gl.h must not precede a glew.h include.
#include <GL/osmesa.h>
#endif

#ifdef PLUME_HAVE_XLIB
#include <X11/Xlib.h>
#endif

namespace plume
{
namespace
{
void SetError(std::string* error, const std::string& message)
{
  if (error)
  {
    *error = message;
  }
}

// True when the window has a current context that VTK initialised (GLEW ok)
// and that is GL 3.2 or newer.
bool CheckContext(vtkOpenGLRenderWindow* win, const char* what, std::string* error)
{
  win->MakeCurrent();
  if (!win->IsCurrent())
  {
    SetError(error, std::string(what) + ": could not make the OpenGL context current");
    return false;
  }
  int major = 0;
  int minor = 0;
  win->GetOpenGLVersion(major, minor);
  if (major < 3 || (major == 3 && minor < 2))
  {
    std::ostringstream msg;
    msg << what << ": OpenGL " << major << "." << minor
        << " context, VTK needs 3.2 core or newer (GLEW may have failed to initialise)";
    SetError(error, msg.str());
    return false;
  }
  return true;
}

#ifdef PLUME_HAVE_OSMESA
//------------------------------------------------------------------------------
// vtkGenericOpenGLRenderWindow driven by an OSMesa core-profile context.
class OSMesaRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  static OSMesaRenderWindow* New();
  vtkTypeMacro(OSMesaRenderWindow, vtkGenericOpenGLRenderWindow);

  bool CreateContext(std::string* error)
  {
    if (this->Context)
    {
      return true;
    }
    // Same request as VTK's own vtkOSOpenGLRenderWindow, but core profile:
    // VTK 9.1's OpenGL2 backend needs 3.2 core; llvmpipe returns 4.5.
    const int attribs[] = {
      OSMESA_FORMAT, OSMESA_RGBA,                 //
      OSMESA_DEPTH_BITS, 24,                      //
      OSMESA_STENCIL_BITS, 8,                     //
      OSMESA_ACCUM_BITS, 0,                       //
      OSMESA_PROFILE, OSMESA_CORE_PROFILE,        //
      OSMESA_CONTEXT_MAJOR_VERSION, 3,            //
      OSMESA_CONTEXT_MINOR_VERSION, 3,            //
      0,
    };
    this->Context = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!this->Context)
    {
      SetError(error,
        "OSMesaCreateContextAttribs failed to create a 3.3 core-profile context "
        "(is libOSMesa a gallium/llvmpipe build?)");
      return false;
    }
    this->OwnContext = 1;
    return true;
  }

  void MakeCurrent() override
  {
    if (!this->Context)
    {
      return;
    }
    plume::glxshim::SetOSMesaActive(true);
    const int w = std::max(1, this->Size[0]);
    const int h = std::max(1, this->Size[1]);
    if (OSMesaGetCurrentContext() == this->Context && w == this->BufferSize[0] &&
      h == this->BufferSize[1])
    {
      return;
    }
    // VTK renders into its own framebuffer objects; this buffer only backs the
    // default framebuffer (it is never read: use VTK's pixel readers).
    this->Buffer.resize(static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
    if (OSMesaMakeCurrent(this->Context, this->Buffer.data(), GL_UNSIGNED_BYTE, w, h))
    {
      this->BufferSize[0] = w;
      this->BufferSize[1] = h;
    }
    else
    {
      vtkErrorMacro("OSMesaMakeCurrent failed (" << w << "x" << h << ")");
    }
  }

  bool IsCurrent() override
  {
    return this->Context && OSMesaGetCurrentContext() == this->Context;
  }

  int SupportsOpenGL() override { return this->Context ? 1 : 0; }
  vtkTypeBool IsDirect() override { return 1; }

  void Initialize() override
  {
    if (!this->Context && !this->CreateContext(nullptr))
    {
      vtkErrorMacro("could not create an OSMesa context");
      return;
    }
    this->MakeCurrent();
    if (!this->Initialized)
    {
      this->OpenGLInit();
    }
  }

  void OpenGLInit() override
  {
    this->MakeCurrent();
    this->Superclass::OpenGLInit();
  }

  bool IsGLInitialized() const { return this->Initialized; }

  // Nothing to present: the image stays in VTK's framebuffers.
  void Frame() override {}

  void Finalize() override
  {
    if (this->Context)
    {
      this->MakeCurrent();
      this->Superclass::Finalize();
    }
  }

protected:
  OSMesaRenderWindow() = default;
  ~OSMesaRenderWindow() override
  {
    // Release VTK's GL objects while the context still exists (the base
    // destructor's Finalize() would run without it).
    this->Finalize();
    if (this->Context)
    {
      if (OSMesaGetCurrentContext() == this->Context)
      {
        OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
      }
      OSMesaDestroyContext(this->Context);
      this->Context = nullptr;
    }
    plume::glxshim::SetOSMesaActive(false);
  }

private:
  OSMesaRenderWindow(const OSMesaRenderWindow&) = delete;
  void operator=(const OSMesaRenderWindow&) = delete;

  OSMesaContext Context = nullptr;
  std::vector<unsigned char> Buffer;
  int BufferSize[2] = { 0, 0 };
};
vtkStandardNewMacro(OSMesaRenderWindow);

// Path of the shared object that defines `addr`, or "" if unknown.
std::string ObjectOf(void* addr)
{
  Dl_info info;
  if (addr && dladdr(addr, &info) && info.dli_fname)
  {
    return info.dli_fname;
  }
  return std::string();
}

// VTK's direct GL 1.x calls bind to the first library exporting them in the
// global scope; with libGL/libOpenGL first they miss the OSMesa context.
bool CheckLinkOrder(std::string* error)
{
  const std::string osmesa = ObjectOf(reinterpret_cast<void*>(&OSMesaCreateContextAttribs));
  const std::string viewport = ObjectOf(dlsym(RTLD_DEFAULT, "glViewport"));
  if (osmesa.empty() || viewport != osmesa)
  {
    SetError(error,
      "glViewport resolves to '" + viewport + "', not to libOSMesa ('" + osmesa +
        "'): link libOSMesa ahead of libGL/libOpenGL (see HeadlessBackend.cmake)");
    return false;
  }
  return true;
}

vtkSmartPointer<vtkRenderWindow> CreateOSMesaWindow(int width, int height, std::string* error)
{
  std::string why;
  if (!plume::glxshim::IsInstalled(&why))
  {
    SetError(error, "osmesa backend unavailable: " + why);
    return nullptr;
  }
  if (!CheckLinkOrder(&why))
  {
    SetError(error, "osmesa backend unavailable: " + why);
    return nullptr;
  }
  vtkNew<OSMesaRenderWindow> win;
  win->SetSize(width, height);
  win->SetShowWindow(false);
  win->SetUseOffScreenBuffers(true);
  if (!win->CreateContext(&why))
  {
    SetError(error, "osmesa backend unavailable: " + why);
    return nullptr;
  }
  win->Initialize();
  if (!win->IsGLInitialized())
  {
    SetError(error, "osmesa backend: VTK could not initialise the OSMesa context "
                    "(GLEW initialisation failed; see the VTK error above)");
    return nullptr;
  }
  if (!CheckContext(win, "osmesa backend", error))
  {
    return nullptr;
  }
  return vtkSmartPointer<vtkRenderWindow>(win.GetPointer());
}
#endif // PLUME_HAVE_OSMESA

/**
 * The X display for plume's windows. vtkXOpenGLRenderWindow abort()s when
 * its own XOpenDisplay fails, so the connection is made here and handed to
 * every X window. It stays open for the life of the process (windows may
 * outlive any owner we could give it; the OS closes it at exit). An X server
 * started without -noreset refuses connections for a moment after its last
 * client leaves: retry briefly before giving up.
 */
void* OpenXDisplay(std::string* error)
{
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    SetError(error,
      "x backend: DISPLAY is not set; run under xvfb-run "
      "(xvfb-run -a -s \"-screen 0 1024x768x24 -noreset\" plume ...) or use --backend osmesa");
    return nullptr;
  }
#ifdef PLUME_HAVE_XLIB
  static Display* shared = nullptr;
  for (int attempt = 0; !shared && attempt < 20; ++attempt)
  {
    shared = XOpenDisplay(nullptr);
    if (!shared)
    {
      usleep(50000);
    }
  }
  if (shared)
  {
    return shared;
  }
  SetError(error,
    std::string("x backend: cannot open X display '") + display +
      "'; run under xvfb-run or use --backend osmesa");
  return nullptr;
#else
  return reinterpret_cast<void*>(1); // no Xlib to probe with: VTK opens it
#endif
}

vtkSmartPointer<vtkRenderWindow> CreateXWindow(int width, int height, std::string* error, bool onScreen = false)
{
  void* dpy = OpenXDisplay(error);
  if (!dpy)
  {
    return nullptr;
  }
  // Make the glX* stand-ins forward to the real libGL/libGLX.
  plume::glxshim::SetOSMesaActive(false);
  auto win = vtkSmartPointer<vtkRenderWindow>::New(); // vtkXOpenGLRenderWindow
  auto* glwin = vtkOpenGLRenderWindow::SafeDownCast(win);
  if (!glwin)
  {
    SetError(error,
      std::string("x backend: VTK's render window is a ") + win->GetClassName() +
        ", not an OpenGL window");
    return nullptr;
  }
#ifdef PLUME_HAVE_XLIB
  win->SetDisplayId(dpy);
#endif
  win->SetSize(width, height);
  win->SetOffScreenRendering(onScreen ? 0 : 1);
  glwin->Initialize();
  if (!CheckContext(glwin, "x backend", error))
  {
    return nullptr;
  }
  return win;
}
}

bool ParseBackend(const std::string& text, Backend& backend)
{
  std::string t = text;
  std::transform(t.begin(), t.end(), t.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (t == "auto")
  {
    backend = Backend::Auto;
  }
  else if (t == "osmesa")
  {
    backend = Backend::OSMesa;
  }
  else if (t == "x" || t == "glx" || t == "xvfb")
  {
    backend = Backend::X;
  }
  else
  {
    return false;
  }
  return true;
}

const char* BackendName(Backend backend)
{
  switch (backend)
  {
    case Backend::OSMesa:
      return "osmesa";
    case Backend::X:
      return "x";
    case Backend::Auto:
    default:
      return "auto";
  }
}

vtkSmartPointer<vtkRenderWindow> CreateRenderWindow(
  Backend requested, int width, int height, Backend* used, std::string* error)
{
  if (width <= 0 || height <= 0)
  {
    SetError(error, "render window size must be positive");
    return nullptr;
  }
  std::string osmesaError;
  if (requested == Backend::OSMesa || requested == Backend::Auto)
  {
#ifdef PLUME_HAVE_OSMESA
    vtkSmartPointer<vtkRenderWindow> win = CreateOSMesaWindow(width, height, &osmesaError);
#else
    vtkSmartPointer<vtkRenderWindow> win;
    osmesaError = "osmesa backend unavailable: plume was built without OSMesa "
                  "(install libosmesa6-dev and reconfigure)";
#endif
    if (win)
    {
      if (used)
      {
        *used = Backend::OSMesa;
      }
      return win;
    }
    if (requested == Backend::OSMesa)
    {
      SetError(error, osmesaError);
      return nullptr;
    }
  }

  std::string xError;
  vtkSmartPointer<vtkRenderWindow> win = CreateXWindow(width, height, &xError);
  if (win)
  {
    if (used)
    {
      *used = Backend::X;
    }
    return win;
  }
  if (requested == Backend::Auto)
  {
    SetError(error, "no render backend available:\n  " + osmesaError + "\n  " + xError);
  }
  else
  {
    SetError(error, xError);
  }
  return nullptr;
}

vtkSmartPointer<vtkRenderWindow> RequireRenderWindow(Backend requested, int width, int height)
{
  Backend used;
  std::string error;
  auto window = CreateRenderWindow(requested, width, height, &used, &error);
  if (!window)
  {
    throw std::runtime_error(
      "cannot create a render window (backend " + std::string(BackendName(requested)) + "): " + error);
  }
  return window;
}

vtkSmartPointer<vtkRenderWindow> RequireInteractiveWindow(int width, int height)
{
  std::string error;
  auto window = CreateXWindow(width, height, &error, true);
  if (!window)
  {
    throw std::runtime_error("plume view needs an X display for its window: " + error);
  }
  return window;
}
}
