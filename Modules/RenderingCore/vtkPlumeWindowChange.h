// GL objects belong to the context they were made in. A mapper keeps its GL
// resources in one record with the window they live in; before it renders,
// this releases them in their old window when the renderer's window is
// another one (a mapper moved to a new window, or a window replaced).
#ifndef vtkPlumeWindowChange_h
#define vtkPlumeWindowChange_h

class vtkOpenGLRenderWindow;

namespace plume
{
/**
 * If `resources.Window` is set and is not `window`, calls
 * `resources.ReleaseGraphicsResources(resources.Window)` (which frees every GL
 * object of the record there); then `resources.Window = window`.
 */
template <class Resources>
void ReleaseOnWindowChange(Resources& resources, vtkOpenGLRenderWindow* window)
{
  if (resources.Window && resources.Window != window)
  {
    resources.ReleaseGraphicsResources(resources.Window);
  }
  resources.Window = window;
}
}

#endif
// VTK-HeaderTest-Exclude: vtkPlumeWindowChange.h
