/**
 * @class   vtkPlumeOpaqueDepthTexture
 * @brief   copies the depth of the opaque scene (the current draw framebuffer) into a texture
 *
 * Volumetric renderers that must stop at opaque VTK actors (raycast volumes,
 * smoke sheets) call Capture() at the start of their Render(), before they
 * draw anything: it copies the depth buffer of the renderer's viewport from
 * the framebuffer VTK is drawing into (its offscreen render framebuffer or
 * the default one) into a 2D depth texture of the viewport's
 * size (nearest filtering). The texture is reallocated only when the
 * viewport size or the source's depth format changes (a fresh texture then:
 * a blit between unequal depth formats is illegal).
 *
 * In GLSL, read it with the fragment's position relative to the viewport:
 * @code
 *   uniform sampler2D OpaqueDepth;   // bind GetTextureObject()'s unit
 *   uniform vec2 ViewportOrigin;     // GetViewportOrigin()
 *   float d = texelFetch(OpaqueDepth, ivec2(gl_FragCoord.xy - ViewportOrigin), 0).r; // window depth 0..1
 * @endcode
 * and turn d into a ray parameter by unprojecting (ndc.xy, 2d - 1).
 *
 * The texture has the depth format of the source (24-bit fixed, 32-bit float, ...).
 * A multisampled framebuffer (VTK's default windows have 8 samples) is
 * resolved by a depth blit (one sample per pixel), or, with
 * ResolveToNearestSample (set on the compositing pass's shared depth, what
 * `plume` frames use), to the NEAREST sample of each pixel: its depth is copied
 * sample for sample into a multisampled texture and a full-screen pass writes
 * the minimum (with the blit, anti-aliased edge pixels of thin lines whose
 * sample missed the line got the background's depth, and volumes were drawn
 * over them: dashed lines). If that pass is unavailable, the blit; if even
 * that fails, Capture() returns false, GetLastError() says why and callers
 * should behave as if nothing opaque were in the scene.
 */
#ifndef vtkPlumeOpaqueDepthTexture_h
#define vtkPlumeOpaqueDepthTexture_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For members

#include <string> // For std::string

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkTextureObject;
class vtkWindow;

class PLUMERENDERINGCORE_EXPORT vtkPlumeOpaqueDepthTexture : public vtkObject
{
public:
  static vtkPlumeOpaqueDepthTexture* New();
  vtkTypeMacro(vtkPlumeOpaqueDepthTexture, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Copy the depth of `renderer`'s viewport. Returns false on failure (see class doc). */
  bool Capture(vtkRenderer* renderer);

  /** The depth texture (valid after a successful Capture). */
  vtkTextureObject* GetTextureObject();

  /** Lower-left corner (pixels, in the framebuffer) and size of the captured viewport. */
  const int* GetViewportOrigin() const { return this->Origin; }
  const int* GetViewportSize() const { return this->Size; }

  ///@{
  /**
   * Resolve a multisampled depth buffer to each pixel's nearest sample (true)
   * instead of a blit's one sample (false, the default).
   */
  vtkSetMacro(ResolveToNearestSample, bool);
  vtkGetMacro(ResolveToNearestSample, bool);
  ///@}

  /** Description of the last failure, "" after a successful Capture. */
  const std::string& GetLastError() const { return this->LastError; }

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkPlumeOpaqueDepthTexture();
  ~vtkPlumeOpaqueDepthTexture() override;

  vtkSmartPointer<vtkTextureObject> Texture;
  int Origin[2] = { 0, 0 };
  int Size[2] = { 0, 0 };
  int Format = -1;
  unsigned int ResolveFramebuffer = 0; // GL name, for multisampled sources
  // nearest-sample resolve of a multisampled source: its depth sample for sample, and the pass
  bool ResolveNearest(vtkOpenGLRenderWindow* window, int x, int y, int width, int height, int samples);
  vtkSmartPointer<vtkTextureObject> Multisampled;
  unsigned int MultisampleFramebuffer = 0; // GL name
  int MultisampledFormat = -1;
  bool ResolveToNearestSample = false;
  vtkOpenGLQuadHelper* Quad = nullptr;
  std::string LastError;

private:
  vtkPlumeOpaqueDepthTexture(const vtkPlumeOpaqueDepthTexture&) = delete;
  void operator=(const vtkPlumeOpaqueDepthTexture&) = delete;
};

#endif
