/**
 * @class   vtkPlumeCompositingPass
 * @brief   the frame every Plume renderer composites into: opaque scene, shared depth, translucent, media
 *
 * Plume's renderers read the depth of the opaque scene (smoke stops at walls)
 * and blend over what is behind them (glyph lines fade, smoke darkens and
 * tints). Drawn as ordinary actors in VTK's opaque pass they would see only
 * what was drawn before them, so the picture would depend on the order the
 * actors were added in. This pass fixes the order of a frame instead:
 *
 *   1. lights, then VTK's opaque pass (every opaque prop; Plume actors that
 *      declare a stage are skipped there);
 *   2. Plume blended surfaces (STAGE_SURFACES: velocity glyph lines, which
 *      write depth and blend their faded part over the opaque scene), back
 *      to front;
 *   3. the opaque depth (2 + 1) is copied once into a shared
 *      vtkPlumeOpaqueDepthTexture (GetSharedDepth) for every medium of the
 *      frame (not at all when the frame has no medium);
 *   4. VTK's translucent pass as vtkRenderer would run it: order-independent
 *      transparency, or dual depth peeling when the renderer's
 *      UseDepthPeeling is on;
 *   5. media (STAGE_MEDIA: smoke sheets, and every vtkVolume, Plume's or
 *      VTK's own), back to front by the distance from the camera to the
 *      centre of their bounds, each composited "over" the frame and bounded
 *      by the shared depth of step 3;
 *   6. VTK's overlay pass (2D actors, scalar bars).
 * Ties in a sort are broken by the bounds themselves, never by the order the
 * props were added, so permuting the actors gives the same image.
 *
 * Use:
 * @code
 *   vtkPlumeCompositingPass::Install(renderer); // once; keeps a pass already there
 * @endcode
 * In a renderer without this pass, Plume mappers keep their stand-alone
 * behaviour (documented in each mapper): they draw in VTK's opaque pass and
 * see what was drawn before them, and volumes capture the depth themselves.
 *
 * How a mapper takes part: it sets STAGE() in its vtkAlgorithm information
 * (vtkPlumeCompositingPass::SetStage(this, STAGE_MEDIA)) and starts its
 * Render() with `if (!vtkPlumeCompositingPass::ShouldDraw(ren, this)) return;`.
 * While the pass runs, CURRENT_STAGE() on the renderer's information says
 * which step is drawing and OPAQUE_DEPTH() holds the shared depth.
 *
 * A separate media layer for a pass around this one (vtkPlumeAirlightPass:
 * haze in front of a translucent medium is added to it, haze behind it is
 * dimmed by it). When the renderer's information holds MEDIA_LAYER() (a
 * vtkTextureObject of the viewport's size, set by the outer pass while its
 * delegate renders into a framebuffer object of its own), step 5 draws the
 * media into that texture instead of the frame's colour: it replaces the
 * bound framebuffer's colour attachment 0 by the layer (keeping its depth,
 * so media still stop at the opaque scene and an isosurface still writes
 * depth), clears it to (0, 0, 0, 0), draws, and puts the colour attachment
 * back after the overlay step (6), which draws into the layer too (2D
 * actors stay on top of the media). Every medium blends premultiplied "over", so the layer ends up as the
 * media's premultiplied colour C_v and opacity alpha_v: the frame without the
 * outer pass would be C_v + (1 - alpha_v) C_frame. The pass then sets
 * MEDIA_LAYER_DRAWN() to the number of media drawn into it (0: the layer was
 * not touched, not even cleared) and MEDIA_LAYER_DEPTH() to the shared opaque
 * depth (the depth before the media: where the final depth is nearer, a
 * medium wrote it). The outer pass removes the three keys after its delegate.
 */
#ifndef vtkPlumeCompositingPass_h
#define vtkPlumeCompositingPass_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // For members

#include <array>  // For std::array
#include <vector> // For std::vector

class vtkAlgorithm;
class vtkInformationIntegerKey;
class vtkInformationObjectBaseKey;
class vtkPlumeOpaqueDepthTexture;
class vtkProp;
class vtkRenderer;
class vtkRenderStepsPass;
class vtkTextureObject;

class PLUMERENDERINGCORE_EXPORT vtkPlumeCompositingPass : public vtkRenderPass
{
public:
  static vtkPlumeCompositingPass* New();
  vtkTypeMacro(vtkPlumeCompositingPass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Where a Plume mapper draws when the pass runs. */
  enum Stage
  {
    STAGE_VTK = 0,      ///< VTK's own steps (opaque, translucent, overlay)
    STAGE_SURFACES = 1, ///< after the opaque scene, before the depth is shared
    STAGE_MEDIA = 2     ///< after the translucent pass, sorted with the volumes
  };

  /** On a mapper's information: the Stage it draws in (absent: an ordinary VTK mapper). */
  static vtkInformationIntegerKey* STAGE();
  /** On the renderer's information while the pass renders: the step now drawing. */
  static vtkInformationIntegerKey* CURRENT_STAGE();
  /** On the renderer's information while the pass renders: the shared opaque depth. */
  static vtkInformationObjectBaseKey* OPAQUE_DEPTH();

  /** On the renderer's information, set by an outer pass: the vtkTextureObject media are drawn into (see above). */
  static vtkInformationObjectBaseKey* MEDIA_LAYER();
  /** Set by this pass: how many media were drawn into MEDIA_LAYER() (absent or 0: none, layer untouched). */
  static vtkInformationIntegerKey* MEDIA_LAYER_DRAWN();
  /** Set by this pass with MEDIA_LAYER_DRAWN(): the vtkPlumeOpaqueDepthTexture of the depth before the media. */
  static vtkInformationObjectBaseKey* MEDIA_LAYER_DEPTH();

  /**
   * On the renderer's information, set by an outer pass with MEDIA_LAYER():
   * a second texture of the same size. When the media include a prop that
   * is not a vtkVolume (smoke sheets multiply the frame by an RGB
   * transmittance instead of blending "over" with one opacity), the media
   * (and the overlay) are drawn a second time into it, cleared to (1, 1, 1, 1):
   * every medium's blending is affine in what lies behind it, so this layer
   * minus MEDIA_LAYER() is the media's RGB transmittance. Volumes alone are
   * drawn once (their transmittance is 1 - alpha).
   */
  static vtkInformationObjectBaseKey* MEDIA_TRANSMITTANCE();
  /** Set by this pass to 1 when it drew into MEDIA_TRANSMITTANCE(). */
  static vtkInformationIntegerKey* MEDIA_TRANSMITTANCE_DRAWN();

  /**
   * True for a prop this pass draws in its media step (a visible vtkVolume or
   * an actor whose mapper declared STAGE_MEDIA): the rule an outer pass uses
   * to find the media's bounds.
   */
  static bool IsMedium(vtkProp* prop);

  /** Declares the stage `mapper` draws in (call it in the mapper's constructor). */
  static void SetStage(vtkAlgorithm* mapper, int stage);
  /** The stage `mapper` declared, or -1. */
  static int GetStage(vtkAlgorithm* mapper);

  /**
   * True when `mapper` should draw now: always in a renderer without the
   * pass; with the pass, only in the step of the mapper's declared stage.
   */
  static bool ShouldDraw(vtkRenderer* renderer, vtkAlgorithm* mapper);

  /**
   * The opaque depth the pass captured for this frame (step 3), or nullptr
   * when the renderer has no compositing pass or the depth could not be read.
   */
  static vtkPlumeOpaqueDepthTexture* GetSharedDepth(vtkRenderer* renderer);

  /**
   * The opaque depth a mapper should read now: the shared one when the pass
   * runs, else `own` after capturing the current depth buffer into it (the
   * stand-alone behaviour). nullptr when neither can be had; then `own`'s
   * GetLastError() says why.
   */
  static vtkPlumeOpaqueDepthTexture* AcquireDepth(vtkRenderer* renderer, vtkPlumeOpaqueDepthTexture* own);

  /**
   * Whether anything but `self` may have written the opaque depth a medium
   * drawn by `self` now would read. False means the depth is the far plane
   * everywhere, so copying it and testing rays against it would change
   * nothing. Conservative: under this pass, any visible prop that is not a
   * medium (media draw after the shared depth is captured) and not a 2D
   * actor, and has opaque geometry or draws in STAGE_SURFACES; without the
   * pass, any visible prop but `self` and 2D actors with opaque or
   * translucent geometry (vtkVolume says it has opaque geometry, and an
   * isosurface writes depth). Always true for a renderer that keeps the
   * depth of an earlier one (PreserveDepthBuffer) or no renderer.
   */
  static bool HasOtherDepthWriters(vtkRenderer* renderer, vtkProp* self);

  /**
   * Sets a new compositing pass on `renderer` unless its pass already is one;
   * returns the renderer's compositing pass.
   */
  static vtkPlumeCompositingPass* Install(vtkRenderer* renderer);

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /**
   * The props of the last frame's surface and media steps, in the order they
   * were drawn (for tests and diagnostics; not reference-counted).
   */
  const std::vector<vtkProp*>& GetLastSurfaceOrder() const { return this->LastSurfaceOrder; }
  const std::vector<vtkProp*>& GetLastMediaOrder() const { return this->LastMediaOrder; }
  ///@}

  /** Whether the last frame's shared depth was captured (false: no medium, or media drew unbounded). */
  bool GetLastDepthShared() const { return this->LastDepthShared; }

protected:
  vtkPlumeCompositingPass();
  ~vtkPlumeCompositingPass() override;

  // the steps, called by the vtkRenderStepsPass below
  void RenderOpaqueAndSurfaces(const vtkRenderState* s);
  void RenderTranslucent(const vtkRenderState* s);
  void RenderMedia(const vtkRenderState* s);
  void RenderOverlay(const vtkRenderState* s);
  void RestoreColorAttachment();
  void AttachAndClear(vtkRenderer* ren, vtkTextureObject* texture, double value);

  vtkSmartPointer<vtkRenderStepsPass> Steps;
  vtkSmartPointer<vtkRenderPass> Opaque;
  vtkSmartPointer<vtkRenderPass> Translucent;      // plain vtkTranslucentPass
  vtkSmartPointer<vtkRenderPass> OrderIndependent; // around Translucent
  vtkSmartPointer<vtkRenderPass> DepthPeeling;     // around Translucent
  vtkSmartPointer<vtkRenderPass> Overlay;          // VTK's overlay pass (2D actors)
  vtkSmartPointer<vtkPlumeOpaqueDepthTexture> Depth;
  std::vector<vtkProp*> LastSurfaceOrder;
  std::vector<vtkProp*> LastMediaOrder;
  bool LastDepthShared = false;
  bool WarnedDepth = false;
  bool WarnedLayer = false;
  bool LayerAttached = false;             // the media layer is the bound framebuffer's colour 0 now
  std::array<int, 2> LayerAttachment{};   // what it replaced: GL object type and name
  vtkTextureObject* Layer = nullptr;         // this frame's media layers (not counted: the outer pass holds them)
  vtkTextureObject* Transmittance = nullptr;

private:
  vtkPlumeCompositingPass(const vtkPlumeCompositingPass&) = delete;
  void operator=(const vtkPlumeCompositingPass&) = delete;
};

#endif
