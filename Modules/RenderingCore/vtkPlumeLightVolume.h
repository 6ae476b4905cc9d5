/**
 * @class   vtkPlumeLightVolume
 * @brief   cached per-node lighting: a 3D texture of transmittances towards up to 4 lights, drawn slice by slice
 *
 * A 3D texture of the volume's grid size with one 16-bit normalised channel
 * per light (up to 4): texel (i, j, k) holds the transmittance from node
 * (i, j, k) towards each light through the volume, computed by the caller's
 * shader one z-slice at a time (the same shadow march a sample would run).
 * Samples then interpolate it trilinearly instead of marching a shadow ray
 * each. Update() recomputes it only when the window or the key (grid size,
 * lights, data version, transfer-function version, shadow step: whatever the
 * transmittances depend on) differs from the one it was last made with;
 * GetUpdateCount() counts the recomputations (tests, no stale light).
 */
#ifndef vtkPlumeLightVolume_h
#define vtkPlumeLightVolume_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkNew.h"                    // For members
#include "vtkObject.h"

#include <functional> // For std::function
#include <vector>     // For std::vector

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class PLUMERENDERINGCORE_EXPORT vtkPlumeLightVolume : public vtkObject
{
public:
  static vtkPlumeLightVolume* New();
  vtkTypeMacro(vtkPlumeLightVolume, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Makes the texture dims[0] x dims[1] x dims[2] with `lights` (1..4)
   * channels current for `key`: if it is stale, `drawSlice(k)` is called for
   * every slice k with that slice bound as the only colour target and the
   * viewport set to dims[0] x dims[1] (it draws a full-viewport triangle
   * whose fragment (i, j) writes node (i, j, k)). `window` must be current.
   * False if the texture or framebuffer cannot be made.
   */
  bool Update(vtkOpenGLRenderWindow* window, const int dims[3], int lights, const std::vector<double>& key,
    const std::function<void(int)>& drawSlice);

  /** Whether Update() with these arguments would recompute the texture. */
  bool IsStale(vtkOpenGLRenderWindow* window, const int dims[3], int lights, const std::vector<double>& key) const;

  /** The texture (linear filtering, clamp to edge); null before Update. */
  vtkTextureObject* GetTextureObject();

  /** Bytes of a texture for `dims` and `lights`. */
  static double GetTextureBytes(const int dims[3], int lights);

  /** Recomputations so far. */
  vtkGetMacro(UpdateCount, int);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkPlumeLightVolume();
  ~vtkPlumeLightVolume() override;

  vtkNew<vtkTextureObject> Texture;
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  std::vector<double> Key; // what the texture holds (empty: nothing)
  static std::vector<double> FullKey(const int dims[3], int lights, const std::vector<double>& key);
  int UpdateCount = 0;

private:
  vtkPlumeLightVolume(const vtkPlumeLightVolume&) = delete;
  void operator=(const vtkPlumeLightVolume&) = delete;
};

#endif
