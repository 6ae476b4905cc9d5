/**
 * @class   vtkPlumePingPongTexture3D
 * @brief   two float 3D textures of one size, read from one and rendered into the other, then swapped
 *
 * The seed's "slab" (seed 004, after Harris, GPU Gems ch. 38): a pass reads
 * the front texture and renders into the back one (a texture cannot be read
 * and written in one draw), then Swap() makes the result the front. Both are
 * vtkTextureObject 3D textures of `components` float channels (1: GL_R32F,
 * 4: GL_RGBA32F; 2 and 3 are not colour-renderable everywhere and refused),
 * nearest filtering and clamp-to-edge wrapping (passes read them with
 * texelFetch), so texel (i, j, k) is grid node (i, j, k).
 *
 * Allocate() re-creates the textures only when the window, the size or the
 * channel count changed. Upload()/Download() move the front texture's
 * values from/to the host (float, x fastest).
 */
#ifndef vtkPlumePingPongTexture3D_h
#define vtkPlumePingPongTexture3D_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For members
#include "vtkWeakPointer.h"  // For members

#include <string> // For std::string

class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class PLUMERENDERINGCORE_EXPORT vtkPlumePingPongTexture3D : public vtkObject
{
public:
  static vtkPlumePingPongTexture3D* New();
  vtkTypeMacro(vtkPlumePingPongTexture3D, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Two dims[0] x dims[1] x dims[2] textures of `components` (1 or 4) float
   * channels in `window` (current), contents undefined; false if they cannot
   * be created (GetLastError() says why).
   */
  bool Allocate(vtkOpenGLRenderWindow* window, const int dims[3], int components);

  /** The texture passes read (the last result). */
  vtkTextureObject* GetFront();
  /** The texture the next pass renders into. */
  vtkTextureObject* GetBack();
  /** The back texture becomes the front one. */
  void Swap() { this->FrontIndex = 1 - this->FrontIndex; }

  /** Front texture <- `values` (dims product x components floats). */
  bool Upload(const float* values);
  /** `values` <- the front texture. */
  bool Download(float* values);

  /** Size along each axis (0 before Allocate). */
  const int* GetDimensions() const { return this->Dimensions; }
  int GetComponents() const { return this->Components; }
  const char* GetLastError() const { return this->LastError.c_str(); }

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkPlumePingPongTexture3D();
  ~vtkPlumePingPongTexture3D() override;

  vtkSmartPointer<vtkTextureObject> Textures[2];
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  int FrontIndex = 0;
  int Dimensions[3] = { 0, 0, 0 };
  int Components = 0;
  std::string LastError;

private:
  vtkPlumePingPongTexture3D(const vtkPlumePingPongTexture3D&) = delete;
  void operator=(const vtkPlumePingPongTexture3D&) = delete;
};

#endif
