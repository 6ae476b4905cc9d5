/**
 * @class   vtkPlumeShaderProgramCache
 * @brief   a renderer's shader programs, one per variant, for one window
 *
 * Ready() returns the program of a variant (the .glsl templates and a
 * vtkPlumeShaderFeatures) bound and ready, building it the first time that
 * variant is asked for on this window; a different window drops the cache
 * (its programs belong to the old window's shader cache). Programs are owned
 * by the window's vtkOpenGLShaderCache, as VTK's mappers' are: call
 * ReleaseGraphicsResources with the mapper's.
 *
 * Full-screen passes (a vtkRenderPass that runs one fragment shader over the
 * viewport) take ReadyQuad(): the same variant selection and key, with VTK's
 * full-screen-quad vertex shader and a quad whose vertex array is bound to
 * that program (a vtkOpenGLQuadHelper per variant, owned by the cache and
 * deleted with its window).
 */
#ifndef vtkPlumeShaderProgramCache_h
#define vtkPlumeShaderProgramCache_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkWeakPointer.h" // For Window

#include <map>    // For std::map
#include <string> // For std::string

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkPlumeShaderFeatures;
class vtkShaderProgram;
class vtkWindow;

class PLUMERENDERINGCORE_EXPORT vtkPlumeShaderProgramCache : public vtkObject
{
public:
  static vtkPlumeShaderProgramCache* New();
  vtkTypeMacro(vtkPlumeShaderProgramCache, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

#ifndef __VTK_WRAP__
  /**
   * The program of templates `vs`, `gs` (nullptr: none), `fs` selected by
   * `features`, bound; nullptr if it does not compile or link (the shader
   * cache reports why). The templates are identified by address: pass the
   * encoded strings themselves.
   */
  vtkShaderProgram* Ready(vtkOpenGLRenderWindow* window, const char* vs, const char* gs, const char* fs,
    const vtkPlumeShaderFeatures& features);

  /**
   * The full-screen quad of fragment template `fs` selected by `features`
   * (vertex shader: VTK's full-screen quad, which passes `texCoord`), its
   * program bound; draw with its Render(). nullptr if the program does not
   * compile or link. The quad stays owned by the cache. As for Ready(),
   * `window`'s context must be current (the quad's vertex array is made in
   * the current context).
   */
  vtkOpenGLQuadHelper* ReadyQuad(
    vtkOpenGLRenderWindow* window, const char* fs, const vtkPlumeShaderFeatures& features);
#endif

  /** Programs built so far, quads included (tests: switching back to a variant builds nothing). */
  vtkGetMacro(BuildCount, int);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkPlumeShaderProgramCache();
  ~vtkPlumeShaderProgramCache() override;

  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  std::map<std::string, vtkShaderProgram*> Programs; // owned by the window's shader cache
  std::map<std::string, vtkOpenGLQuadHelper*> Quads;  // owned here (their vertex arrays)
  int BuildCount = 0;

private:
  void SetWindow(vtkOpenGLRenderWindow* window);
  void DeleteQuads();

  vtkPlumeShaderProgramCache(const vtkPlumeShaderProgramCache&) = delete;
  void operator=(const vtkPlumeShaderProgramCache&) = delete;
};

#endif
