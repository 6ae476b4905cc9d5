// SPDX-License-Identifier: BSD-3-Clause
//
// glX* stand-ins exported from the plume executable.
//
// Why: Debian's VTK 9.1 loads every GL entry point through the system GLEW,
// which is a GLX build. vtkOpenGLRenderWindow::OpenGLInitContext() calls
// glewInit(), which
//   1. glewContextInit(): resolves all GL functions with glXGetProcAddressARB;
//   2. glxewInit(): resolves glXGetCurrentDisplay (again through
//      glXGetProcAddressARB) and fails with GLEW_ERROR_NO_GLX_DISPLAY if it
//      returns NULL, then calls glXQueryVersion / glXGetClientString.
// With an OSMesa context there is no GLX context, so the real functions return
// NULL and VTK stops with "GLEW could not be initialized".
//
// The executable is linked with ENABLE_EXPORTS (-rdynamic), so the functions
// below come first in the global symbol scope and interpose libGL/libGLX for
// every library (GLEW, VTK, Mesa). While the OSMesa backend is active they
// answer from OSMesa; otherwise they forward to the next definition
// (dlsym(RTLD_NEXT)), so the same executable still works with the X backend.
//
// VTK's direct GL 1.x calls (glViewport, glClear, ...) are not looked up by
// name: they bind to the first library exporting them, which must be libOSMesa
// (see HeadlessBackend.cmake, which links it ahead of everything else). In X
// mode those libOSMesa entry points still work: libOSMesa and Mesa's GLX driver
// share libglapi, whose current dispatch table is set by whichever Mesa context
// is current.
#include "plumeGLXShim.h"

#include <atomic>

#ifdef PLUME_HAVE_OSMESA

#ifndef _GNU_SOURCE
#define _GNU_SOURCE 1
#endif
#include <dlfcn.h>

#include <GL/osmesa.h>
#include <GL/glx.h>

#include <cstring>

#define PLUME_SHIM_EXPORT extern "C" __attribute__((visibility("default")))

namespace
{
std::atomic<bool> OSMesaActive{ false };

// Stand-in for the X Display while OSMesa is active: only ever compared
// against, never passed to Xlib.
struct FakeDisplayTag
{
  int unused;
};
FakeDisplayTag FakeDisplayStorage = { 0 };
Display* FakeDisplay()
{
  return reinterpret_cast<Display*>(&FakeDisplayStorage);
}

template <typename Fn>
Fn NextSymbol(const char* name)
{
  // Resolved once; RTLD_NEXT from the executable finds libGL / libGLX.
  void* sym = dlsym(RTLD_NEXT, name);
  Fn fn;
  static_assert(sizeof(fn) == sizeof(sym), "function pointer size");
  std::memcpy(&fn, &sym, sizeof(fn));
  return fn;
}

using GetProcFn = __GLXextFuncPtr (*)(const GLubyte*);
using GetCurrentDisplayFn = Display* (*)();
using QueryVersionFn = Bool (*)(Display*, int*, int*);
using GetClientStringFn = const char* (*)(Display*, int);

GetProcFn RealGetProcAddressARB()
{
  static GetProcFn fn = NextSymbol<GetProcFn>("glXGetProcAddressARB");
  return fn;
}
GetProcFn RealGetProcAddress()
{
  static GetProcFn fn = NextSymbol<GetProcFn>("glXGetProcAddress");
  return fn;
}
GetCurrentDisplayFn RealGetCurrentDisplay()
{
  static GetCurrentDisplayFn fn = NextSymbol<GetCurrentDisplayFn>("glXGetCurrentDisplay");
  return fn;
}
QueryVersionFn RealQueryVersion()
{
  static QueryVersionFn fn = NextSymbol<QueryVersionFn>("glXQueryVersion");
  return fn;
}
GetClientStringFn RealGetClientString()
{
  static GetClientStringFn fn = NextSymbol<GetClientStringFn>("glXGetClientString");
  return fn;
}

__GLXextFuncPtr OSMesaLookup(const GLubyte* name);
}

PLUME_SHIM_EXPORT Display* glXGetCurrentDisplay(void)
{
  if (OSMesaActive.load(std::memory_order_relaxed))
  {
    return FakeDisplay();
  }
  GetCurrentDisplayFn real = RealGetCurrentDisplay();
  return real ? real() : nullptr;
}

PLUME_SHIM_EXPORT Bool glXQueryVersion(Display* dpy, int* major, int* minor)
{
  if (dpy == FakeDisplay() || (OSMesaActive.load(std::memory_order_relaxed) && !dpy))
  {
    if (major)
    {
      *major = 1;
    }
    if (minor)
    {
      *minor = 4;
    }
    return True;
  }
  QueryVersionFn real = RealQueryVersion();
  return real ? real(dpy, major, minor) : False;
}

PLUME_SHIM_EXPORT const char* glXGetClientString(Display* dpy, int name)
{
  if (dpy == FakeDisplay())
  {
    switch (name)
    {
      case GLX_VENDOR:
        return "plume OSMesa shim";
      case GLX_VERSION:
        return "1.4";
      default:
        return ""; // no GLX extensions
    }
  }
  GetClientStringFn real = RealGetClientString();
  return real ? real(dpy, name) : nullptr;
}

PLUME_SHIM_EXPORT __GLXextFuncPtr glXGetProcAddressARB(const GLubyte* name)
{
  if (OSMesaActive.load(std::memory_order_relaxed))
  {
    return OSMesaLookup(name);
  }
  GetProcFn real = RealGetProcAddressARB();
  return real ? real(name) : nullptr;
}

PLUME_SHIM_EXPORT __GLXextFuncPtr glXGetProcAddress(const GLubyte* name)
{
  if (OSMesaActive.load(std::memory_order_relaxed))
  {
    return OSMesaLookup(name);
  }
  GetProcFn real = RealGetProcAddress();
  return real ? real(name) : nullptr;
}

namespace
{
template <typename Fn>
__GLXextFuncPtr AsExt(Fn fn)
{
  return reinterpret_cast<__GLXextFuncPtr>(fn);
}

__GLXextFuncPtr OSMesaLookup(const GLubyte* name)
{
  const char* n = reinterpret_cast<const char*>(name);
  if (!n)
  {
    return nullptr;
  }
  if (std::strncmp(n, "glX", 3) == 0)
  {
    // Only the GLX functions GLEW needs; everything else must look absent
    // (Mesa's glapi would otherwise hand out a dispatch stub for any "gl*").
    if (std::strcmp(n, "glXGetCurrentDisplay") == 0)
    {
      return AsExt(&glXGetCurrentDisplay);
    }
    if (std::strcmp(n, "glXQueryVersion") == 0)
    {
      return AsExt(&glXQueryVersion);
    }
    if (std::strcmp(n, "glXGetClientString") == 0)
    {
      return AsExt(&glXGetClientString);
    }
    if (std::strcmp(n, "glXGetProcAddressARB") == 0)
    {
      return AsExt(&glXGetProcAddressARB);
    }
    if (std::strcmp(n, "glXGetProcAddress") == 0)
    {
      return AsExt(&glXGetProcAddress);
    }
    return nullptr;
  }
  return reinterpret_cast<__GLXextFuncPtr>(OSMesaGetProcAddress(n));
}
}

namespace plume
{
namespace glxshim
{
void SetOSMesaActive(bool active)
{
  OSMesaActive.store(active, std::memory_order_relaxed);
}

bool IsOSMesaActive()
{
  return OSMesaActive.load(std::memory_order_relaxed);
}

bool IsInstalled(std::string* why)
{
  // The global-scope definition must be ours, or GLEW binds to libGL's.
  void* global = dlsym(RTLD_DEFAULT, "glXGetProcAddressARB");
  void* ours = reinterpret_cast<void*>(&glXGetProcAddressARB);
  if (global != ours)
  {
    if (why)
    {
      *why = "the executable does not export its glX* stand-ins (link it with "
             "ENABLE_EXPORTS / -rdynamic, see HeadlessBackend.cmake)";
    }
    return false;
  }
  return true;
}
}
}

#else // !PLUME_HAVE_OSMESA

namespace plume
{
namespace glxshim
{
namespace
{
std::atomic<bool> OSMesaActive{ false };
}
void SetOSMesaActive(bool active)
{
  OSMesaActive.store(active);
}
bool IsOSMesaActive()
{
  return OSMesaActive.load();
}
bool IsInstalled(std::string* why)
{
  if (why)
  {
    *why = "plume was built without OSMesa (install libosmesa6-dev and reconfigure)";
  }
  return false;
}
}
}

#endif
