// SPDX-License-Identifier: BSD-3-Clause
// Offscreen render windows for the plume executable: in-process OSMesa (no X
// server at all) or VTK's own X/GLX window (needs $DISPLAY, e.g. xvfb-run).
#ifndef plumeRenderWindowFactory_h
#define plumeRenderWindowFactory_h

#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>

#include <string>

namespace plume
{
enum class Backend
{
  Auto,   ///< OSMesa if it can create a context, else X
  OSMesa, ///< in-process OSMesa context, no X server needed
  X       ///< VTK's vtkXOpenGLRenderWindow (GLX), needs $DISPLAY
};

/// "auto" | "osmesa" | "x" (case-insensitive; "glx" and "xvfb" also mean X).
bool ParseBackend(const std::string& text, Backend& backend);

/// "auto", "osmesa" or "x".
const char* BackendName(Backend backend);

/**
 * Create an offscreen render window of width x height pixels with a GL 3.2+
 * core context already initialised (GLEW done), ready for AddRenderer() and
 * Render(). Read pixels back through VTK (GetRGBAPixelData, GetZbufferData,
 * vtkWindowToImageFilter); OSMesa's own colour buffer is not written.
 *
 * Returns nullptr on failure with a message in *error. *used receives the
 * backend actually chosen (never Auto).
 *
 * Only one backend may be in use at a time in a process: destroy all windows
 * of one backend before creating a window of the other (GLEW's function
 * pointers are process-global and are reloaded for each new context).
 */
vtkSmartPointer<vtkRenderWindow> CreateRenderWindow(
  Backend requested, int width, int height, Backend* used, std::string* error);

/** CreateRenderWindow, or std::runtime_error naming the backend and the reason. */
vtkSmartPointer<vtkRenderWindow> RequireRenderWindow(Backend requested, int width, int height);

/**
 * An on-screen X/GLX window (plume view) of width x height pixels, context
 * initialised; std::runtime_error naming the reason without a usable $DISPLAY.
 */
vtkSmartPointer<vtkRenderWindow> RequireInteractiveWindow(int width, int height);
}

#endif
