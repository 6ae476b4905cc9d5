/**
 * @class   vtkPlumeLightVolume
 * @brief   cached per-node lighting: a 3D texture of transmittances towards up to 4 lights, swept along each light
 *
 * A 3D texture of the volume's grid size with one 16-bit normalised channel
 * per light (up to 4): texel (i, j, k) holds the transmittance from node
 * (i, j, k) towards each (directional) light through the volume. Samples
 * interpolate it trilinearly instead of marching a shadow ray each.
 *
 * It is made by a sweep along each light, O(N^3) instead of a march per node
 * (O(N^4)): the nodes are visited layer by layer along the light's dominant
 * index axis (GetSweep), starting at the face the light enters through; a
 * node's transmittance is an earlier layer's (in the volume mapper's shader:
 * the last one whose number is a multiple of 8, interpolated bicubically
 * where the ray towards the light meets it), times the segment's own. The
 * caller's shader draws each layer into a float scratch texture laid out
 * along the sweep (layers of the dominant axis; it reads earlier layers, a
 * texture barrier apart), then copies the light's channel into the volume
 * one z-slice at a time.
 *
 * Update() recomputes it only when the window or the key (grid size, lights,
 * data version, transfer-function version, shadow step: whatever the
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
   * The sweep towards a light of index-space direction `towards` (pointing
   * at the light): along index axis `axis` (its largest component), layer q
   * holding the nodes whose coordinate on that axis is q (`flip` false) or
   * dims[axis] - 1 - q (`flip` true), so that layer 0 is the face the light
   * enters through. Scratch texel (u, v, q) is the node whose coordinates on
   * axes (axis + 1) % 3 and (axis + 2) % 3 are u and v.
   */
  static void GetSweep(const float towards[3], int& axis, bool& flip);

  /**
   * Makes the texture dims[0] x dims[1] x dims[2] with `lights` (1..4)
   * channels current for `key`; `towards` holds the lights' index-space
   * directions (3 per light). If it is stale, for each light l:
   *  - `drawLayer(l, q)` for q = 0, 1, ... along its sweep (GetSweep), with
   *    layer q of the scratch texture (GetSweepTexture, one float channel,
   *    sized dims[(axis + 1) % 3] x dims[(axis + 2) % 3] x dims[axis]) as
   *    the only colour target and the viewport its size; the caller may read
   *    the layers before q from the scratch texture (a texture barrier
   *    separates the draws), never layer q;
   *  - `copySlice(l, k)` for every z-slice k of the texture, as its only
   *    colour target with only channel l writable and the viewport
   *    dims[0] x dims[1]: fragment (i, j) writes node (i, j, k) from the scratch.
   * Each draws a full-viewport triangle. `window` must be current. False if
   * a texture or the framebuffer cannot be made.
   */
  bool Update(vtkOpenGLRenderWindow* window, const int dims[3], int lights, const float* towards,
    const std::vector<double>& key, const std::function<void(int, int)>& drawLayer,
    const std::function<void(int, int)>& copySlice);

  /** Whether Update() with these arguments would recompute the texture. */
  bool IsStale(vtkOpenGLRenderWindow* window, const int dims[3], int lights, const std::vector<double>& key) const;

  /** The texture (linear filtering, clamp to edge); null before Update. */
  vtkTextureObject* GetTextureObject();

  /** The sweep's scratch texture while Update() runs (nearest filtering); null otherwise. */
  vtkTextureObject* GetSweepTexture();

  /** Bytes of a texture for `dims` and `lights`, and (`scratch`) of the scratch texture Update() holds while it runs. */
  static double GetTextureBytes(const int dims[3], int lights, bool scratch = false);

  /** Recomputations so far. */
  vtkGetMacro(UpdateCount, int);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkPlumeLightVolume();
  ~vtkPlumeLightVolume() override;

  vtkNew<vtkTextureObject> Texture;
  vtkNew<vtkTextureObject> Sweep; // scratch, released after each Update
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  std::vector<double> Key; // what the texture holds (empty: nothing)
  static std::vector<double> FullKey(const int dims[3], int lights, const std::vector<double>& key);
  int UpdateCount = 0;

private:
  vtkPlumeLightVolume(const vtkPlumeLightVolume&) = delete;
  void operator=(const vtkPlumeLightVolume&) = delete;
};

#endif
