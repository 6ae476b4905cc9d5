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
 */
#ifndef vtkPlumeCompositingPass_h
#define vtkPlumeCompositingPass_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // For members

#include <vector> // For std::vector

class vtkAlgorithm;
class vtkInformationIntegerKey;
class vtkInformationObjectBaseKey;
class vtkPlumeOpaqueDepthTexture;
class vtkProp;
class vtkRenderer;
class vtkRenderStepsPass;

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

  vtkSmartPointer<vtkRenderStepsPass> Steps;
  vtkSmartPointer<vtkRenderPass> Opaque;
  vtkSmartPointer<vtkRenderPass> Translucent;      // plain vtkTranslucentPass
  vtkSmartPointer<vtkRenderPass> OrderIndependent; // around Translucent
  vtkSmartPointer<vtkRenderPass> DepthPeeling;     // around Translucent
  vtkSmartPointer<vtkPlumeOpaqueDepthTexture> Depth;
  std::vector<vtkProp*> LastSurfaceOrder;
  std::vector<vtkProp*> LastMediaOrder;
  bool LastDepthShared = false;
  bool WarnedDepth = false;

private:
  vtkPlumeCompositingPass(const vtkPlumeCompositingPass&) = delete;
  void operator=(const vtkPlumeCompositingPass&) = delete;
};

#endif
