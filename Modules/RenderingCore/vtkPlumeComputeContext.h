/**
 * @class   vtkPlumeComputeContext
 * @brief   the OpenGL context a GPU computation (splatting, the smoke solver) runs in
 *
 * A computation that is not part of a render runs in the window the user
 * gives it (so that its textures can be handed to the mappers of that window
 * without read-back) or, when none is given, in a small offscreen window this
 * object creates once and keeps. Resolve() picks the window, MakeCurrent()
 * makes its context current, creating it if the window never rendered. The
 * two are separate so that a caller whose GL objects belong to another window
 * can release them in between.
 */
#ifndef vtkPlumeComputeContext_h
#define vtkPlumeComputeContext_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For members

#include <string> // For std::string

class vtkOpenGLRenderWindow;
class vtkRenderWindow;

class PLUMERENDERINGCORE_EXPORT vtkPlumeComputeContext : public vtkObject
{
public:
  static vtkPlumeComputeContext* New();
  vtkTypeMacro(vtkPlumeComputeContext, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * `given` as an OpenGL window, or (`given` null) this object's own 8x8
   * offscreen window without multisampling. nullptr with `error` set when the
   * window is not a vtkOpenGLRenderWindow.
   */
  vtkOpenGLRenderWindow* Resolve(vtkRenderWindow* given, std::string& error);

  /**
   * Makes `window`'s context current, initializing the window first if it
   * has no context yet; false with `error` set when there is still none.
   */
  static bool MakeCurrent(vtkOpenGLRenderWindow* window, std::string& error);

  /** The pending GL errors as "0x502, 0x501" (cleared); "" when there are none. */
  static std::string DrainErrors();

protected:
  vtkPlumeComputeContext();
  ~vtkPlumeComputeContext() override;

  vtkSmartPointer<vtkRenderWindow> OwnWindow;

private:
  vtkPlumeComputeContext(const vtkPlumeComputeContext&) = delete;
  void operator=(const vtkPlumeComputeContext&) = delete;
};

#endif
