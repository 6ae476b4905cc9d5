/**
 * @class   vtkPlumeVelocityGlyphMapper
 * @brief   velocity glyph lines drawn by a geometry shader from a 3D velocity texture
 *
 * Input port 0: a vtkImageData carrying a 3-component point array (the active
 * vectors unless VectorArrayName names another).
 * The velocity is uploaded once as a 3D texture and re-uploaded only when the
 * image or the chosen array changes. Optional input port 1: any vtkDataSet
 * whose points are glyph roots (seed mode).
 *
 * For every root p, a geometry shader samples the velocity v(p) (trilinear)
 * and emits a line from p to p + Scale·v(p), with alpha rising from RootAlpha
 * at the root to 1 at the tip (seed 002). In streamlet mode the shader
 * instead integrates K = StreamletSegments steps of length Scale/K through
 * the texture (RK2 or RK4), so each glyph follows the flow.
 *
 * Roots come from one of three sources:
 *  - ROOTS_SCREEN_ADAPTIVE (default): a lattice whose stride keeps about one
 *    glyph per ScreenSpacing×ScreenSpacing pixels of the volume's projected
 *    footprint; recomputed when the camera moves (an O(1) CPU cost).
 *  - ROOTS_LATTICE: every LatticeStride-th grid node along each axis.
 *  - ROOTS_SEEDS: the points of input port 1.
 *
 * Culling in the shader: roots outside the view frustum, outside the valid
 * mask (the point array named by ValidMaskArrayName, e.g. vtkResampleToImage's
 * "vtkValidPointMask", and any node whose vector has a NaN/Inf component) or
 * with |v| <= MinimumSpeed emit nothing.
 *
 * Colour: by |v| through LookupTable over ScalarRange (ColorByMagnitude on,
 * the default), or the actor property's diffuse colour. The colour is looked
 * up once per glyph, not per fragment.
 *
 * Two shader paths draw straight 1-pixel glyphs on a lattice (STRAIGHT,
 * LineWidth <= 1, not ROOTS_SEEDS), chosen by StraightLineShader:
 *  - VERTEX_SHADER (default): glDrawArrays(GL_LINES) of 2 vertices per root
 *    with no vertex buffer; each vertex shader invocation derives its root from
 *    gl_VertexID / 2, fetches the node's velocity with texelFetch and places
 *    the root or the tip; culled glyphs collapse to a point outside the clip
 *    volume. No geometry shader, which llvmpipe runs per primitive on one thread.
 *  - GEOMETRY_SHADER: one point per root expanded by the geometry shader.
 * Both give the same image. Streamlets (RK2/RK4), wide lines and seeds always
 * use the geometry shader.
 *
 * Memory: the velocity is converted and uploaded in slabs (no whole CPU copy).
 * On llvmpipe most of the peak memory of a dense frame is the driver's binned
 * line data, queued while its rasterizer threads catch up (about 470 MB for
 * 2M glyphs, whichever shader path, and growing with the glyph count).
 * MaximumGlyphsPerDraw splits the draw and waits (a fence) until the draw two
 * chunks back has finished, which bounds that memory whatever the glyph count
 * (2M glyphs in 256k chunks: ~400 MB peak instead of ~680 MB, for ~3 % more
 * time; 64k chunks: ~250 MB for ~10 %; 16k: ~210 MB for ~20 %, because
 * binning and rasterizing overlap less). Default 256k.
 *
 * Screen-adaptive stride: each frame the 8 corners of the volume are
 * projected to the viewport; A is the area in pixels of their screen-space
 * bounding box clipped to the viewport (the whole viewport if a corner lies
 * behind the camera). With N the moving nodes (valid nodes faster than 5 %
 * of the robust maximum speed, GetRobustMaximumSpeed(); all grid nodes if
 * none is) and a target of G = max(1, A / ScreenSpacing²) glyphs, the stride
 * is max(1, ceil(cbrt(N / G))), reported by GetEffectiveStride(). Counting
 * only moving nodes keeps about G visible glyphs when the flow fills a small
 * part of the grid (blood in carotid.vtk's vessels: 3 % of the nodes; over
 * all nodes its default first render drew a handful of glyphs).
 *
 * Pieces (data split over MPI ranks): with WholeExtent and MovingNodeCount
 * set to the whole data's, each piece uses the whole grid's footprint and
 * moving nodes for the stride, and puts its lattice roots on the whole
 * grid's lattice (WholeExtent start + k x stride), so the pieces together
 * draw the glyphs of a render of the whole grid.
 *
 * Compositing: glyphs are drawn with depth test and depth write on and
 * standard (non-premultiplied) alpha blending, (SRC_ALPHA,
 * ONE_MINUS_SRC_ALPHA) for colour and (ONE, ONE_MINUS_SRC_ALPHA) for alpha;
 * fragments with alpha < 1/512 are discarded (no depth write). Opaque actors
 * occlude glyphs and glyphs occlude what is behind them; the faded part of a
 * glyph (RootAlpha, a table with alpha, the actor's opacity, which multiplies
 * the glyph alpha) blends with what was drawn before it. Where they draw:
 *  - with a vtkPlumeCompositingPass on the renderer: always in its surface
 *    step, right after the whole opaque scene, whatever the actor's opacity
 *    and in any actor order; VTK's translucent actors (step 4) and the media
 *    (step 5) come after and see the glyphs' depth;
 *  - in a plain vtkRenderer: an actor with opacity 1 in the opaque pass (add
 *    it after the opaque actors its faded parts overlap); an actor with
 *    opacity < 1 in VTK's translucent pass (order-independent transparency
 *    or depth peeling), whose shader replacements the mapper applies.
 *
 * Precision: positions in the shaders are offsets from the volume centre;
 * the model-to-clip matrix is composed in double precision on the CPU
 * (camera x actor x translation to the centre), so data far from the origin
 * (e.g. at 1e6) renders like the same data at the origin.
 *
 * Image geometry: node (i, j, k) of the extent lies at
 * origin + D·(spacing ∘ (i, j, k)), D the image's direction matrix (the
 * frame every Plume renderer shares, vtkPlumeImageFrame.h); vectors are taken
 * in those physical coordinates, as VTK's filters write them.
 *
 * Errors (no input, no vectors, a named array that is missing or does not
 * have 3 components, a grid larger than GL_MAX_3D_TEXTURE_SIZE) are reported
 * with vtkErrorMacro and nothing is drawn. Hardware selection is not supported
 * (glyphs are skipped while a selector is active).
 */
#ifndef vtkPlumeVelocityGlyphMapper_h
#define vtkPlumeVelocityGlyphMapper_h

#include "PlumeGlyphsModule.h" // For export macro
#include "vtkMapper.h"
#include "vtkPlumePercentile.h" // For vtkPlumePercentile::Sum

#include <limits> // For std::numeric_limits
#include <memory> // For std::unique_ptr
#include <string> // For std::string

class vtkImageData;
class vtkDataSet;
class vtkPlumeParameterTable;

class PLUMEGLYPHS_EXPORT vtkPlumeVelocityGlyphMapper : public vtkMapper
{
public:
  static vtkPlumeVelocityGlyphMapper* New();
  vtkTypeMacro(vtkPlumeVelocityGlyphMapper, vtkMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

#ifndef __VTK_WRAP__
  /**
   * The one declaration of the glyphs' user parameters (scene keys, defaults,
   * ranges, documentation) that the scene reader, Documentation/SceneFormat.md
   * and the ParaView XML are made from; the constructor applies its defaults.
   */
  static const vtkPlumeParameterTable& GetParameterTable();
#endif

  enum RootModes
  {
    ROOTS_SCREEN_ADAPTIVE = 0,
    ROOTS_LATTICE = 1,
    ROOTS_SEEDS = 2
  };
  enum StraightLineShaders
  {
    VERTEX_SHADER = 0,  ///< GL_LINES from gl_VertexID, no geometry shader
    GEOMETRY_SHADER = 1 ///< points expanded by the geometry shader
  };
  enum ScaleModes
  {
    SCALE_FIXED = 0, ///< glyph length Scale·|v|
    SCALE_AUTO = 1   ///< Scale chosen from the data (GetEffectiveScale)
  };
  enum IntegratorTypes
  {
    STRAIGHT = 0, ///< one straight segment p → p + Scale·v(p) (seed 002)
    RK2 = 2,      ///< streamlet, midpoint rule
    RK4 = 4       ///< streamlet, classical Runge–Kutta
  };

  ///@{
  /** The image whose vectors are drawn (input port 0). */
  void SetInputData(vtkImageData* input);
  vtkImageData* GetInput();
  ///@}

  ///@{
  /** Seed points for ROOTS_SEEDS (input port 1; only the points are used). */
  void SetSeedData(vtkDataSet* seeds);
  void SetSeedConnection(vtkAlgorithmOutput* output);
  ///@}

  ///@{
  /** Name of the 3-component point array to draw; empty (default) = the active vectors. */
  vtkSetStdStringFromCharMacro(VectorArrayName);
  vtkGetCharFromStdStringMacro(VectorArrayName);
  ///@}

  ///@{
  /**
   * Name of a point array whose zero entries mark invalid nodes (no glyph, and
   * no sampling across them). Default "vtkValidPointMask"; ignored if absent.
   */
  vtkSetStdStringFromCharMacro(ValidMaskArrayName);
  vtkGetCharFromStdStringMacro(ValidMaskArrayName);
  ///@}

  ///@{
  /** Where glyph roots come from. Default ROOTS_SCREEN_ADAPTIVE. */
  vtkSetClampMacro(RootMode, int, ROOTS_SCREEN_ADAPTIVE, ROOTS_SEEDS);
  vtkGetMacro(RootMode, int);
  ///@}

  ///@{
  /** Lattice stride in grid nodes along each axis for ROOTS_LATTICE. Default 1 (every node). */
  vtkSetClampMacro(LatticeStride, int, 1, VTK_INT_MAX);
  vtkGetMacro(LatticeStride, int);
  ///@}

  ///@{
  /** Target spacing in pixels between glyphs for ROOTS_SCREEN_ADAPTIVE. Default 12. */
  vtkSetClampMacro(ScreenSpacing, double, 1.0, 1e6);
  vtkGetMacro(ScreenSpacing, double);
  ///@}

  /** The lattice stride used by the last render (equals LatticeStride unless screen-adaptive). */
  vtkGetMacro(EffectiveStride, int);

  ///@{
  /**
   * The extent of the whole grid the input is one piece of (data split over
   * MPI ranks), in the input's index space (same origin, spacing and
   * direction). Lattice roots, fixed or screen-adaptive, then sit on the
   * whole grid's lattice (nodes WholeExtent start + k x stride along each
   * axis), and the screen-adaptive stride comes from the whole grid's
   * projected footprint: each piece draws what a render of the whole grid
   * draws there. Default empty (a minimum above its maximum): the input's
   * own extent.
   */
  vtkSetVector6Macro(WholeExtent, int);
  vtkGetVector6Macro(WholeExtent, int);
  ///@}

  ///@{
  /**
   * The moving nodes (valid, faster than 5 % of the robust maximum speed)
   * the screen-adaptive stride spreads its glyph budget over. < 0 (default):
   * the input's own. Set it when the input is one piece of larger data
   * (ParaView's representation sets ComputeMovingNodes over all MPI ranks'
   * pieces, so every rank picks the stride of the whole data).
   */
  vtkSetMacro(MovingNodeCount, vtkIdType);
  vtkGetMacro(MovingNodeCount, vtkIdType);
  ///@}

  ///@{
  /** Glyph length per unit of velocity, in world units (SCALE_FIXED only). Default 1. */
  vtkSetMacro(Scale, double);
  vtkGetMacro(Scale, double);
  ///@}

  ///@{
  /**
   * SCALE_AUTO (default): the scale is chosen so that a glyph at the robust
   * maximum speed (the 99th percentile of the valid nodes' speeds, so one
   * outlier does not shrink every glyph; or AutomaticScaleSpeed if set)
   * spans about two root spacings: 2 × the largest grid spacing × the
   * effective stride (GetAutomaticScale(GetEffectiveStride())): LatticeStride
   * for ROOTS_LATTICE, the screen-adaptive stride of each frame for
   * ROOTS_SCREEN_ADAPTIVE (so the glyphs keep their length on screen as the
   * camera zooms, and change length where the stride steps), 1 for
   * ROOTS_SEEDS. A velocity field with no valid non-zero node falls back to
   * Scale. SCALE_FIXED: glyphs are Scale·|v| long (set it with Scale).
   */
  vtkSetClampMacro(ScaleMode, int, SCALE_FIXED, SCALE_AUTO);
  vtkGetMacro(ScaleMode, int);
  ///@}

  ///@{
  /**
   * The speed SCALE_AUTO draws two root spacings long. NaN (default) or <= 0:
   * GetRobustMaximumSpeed() of the input. Set it when the input is one piece
   * of larger data (ParaView's representation sets the percentile over all
   * MPI ranks' pieces, ComputeRobustMaximumSpeed, so every rank draws the
   * same lengths) or to keep one scale over the time steps of a series.
   */
  vtkSetMacro(AutomaticScaleSpeed, double);
  vtkGetMacro(AutomaticScaleSpeed, double);
  ///@}

  /**
   * The scale glyphs are drawn with: Scale, or the automatic one of
   * SCALE_AUTO for the current input (updates the input) at the effective
   * stride: LatticeStride for ROOTS_LATTICE, the last render's stride for
   * ROOTS_SCREEN_ADAPTIVE (1 before the first render), 1 for ROOTS_SEEDS.
   * GetBounds pads screen-adaptive glyphs with the scale at stride 1 (the
   * stride needs a camera; bounds that followed the last frame's stride made
   * a render and an interactive view's still frame differ): tips that reach
   * further out of the data than two cells' worth may meet the clipping
   * planes.
   */
  double GetEffectiveScale();

  /**
   * The SCALE_AUTO scale for roots `stride` grid nodes apart: a glyph at the
   * robust maximum speed (or AutomaticScaleSpeed if set) spans 2 × stride ×
   * the largest grid spacing. Scale when the input has no valid moving node
   * or no spacing.
   */
  double GetAutomaticScale(int stride);

  /**
   * The 99th percentile of the speeds of the input's valid nodes (finite,
   * not masked), the robust maximum SCALE_AUTO uses; 0 without input.
   */
  double GetRobustMaximumSpeed();

#ifndef __VTK_WRAP__
  /**
   * GetRobustMaximumSpeed of data split into pieces (MPI ranks): the 99th
   * percentile of the valid speeds (this mapper's VectorArrayName and
   * ValidMaskArrayName) of every piece's nodes whose grid index lies within
   * `extent` (nullptr: all of `image`), the counts summed over the pieces by
   * `sum` (empty: this piece alone). Exact (vtkPlumePercentile): equals
   * GetRobustMaximumSpeed of the whole data when the pieces' extents tile it
   * without overlap. Collective: every piece calls it, a piece without data
   * with image nullptr. 0 when no piece has a valid node. With
   * `movingNodes`, also ComputeMovingNodes at the speed found, from the same
   * pass over the piece (the speeds are collected once; the sums are made in
   * the same order as by the two calls).
   */
  double ComputeRobustMaximumSpeed(vtkImageData* image, const int extent[6], const vtkPlumePercentile::Sum& sum,
    vtkIdType* movingNodes = nullptr);

  /**
   * The moving nodes of data split into pieces, for MovingNodeCount: valid
   * nodes (as ComputeRobustMaximumSpeed counts them, within `extent`)
   * faster than 5 % of `speed` (the robust maximum of the whole data),
   * summed over the pieces by `sum` (empty: this piece alone). Collective,
   * as ComputeRobustMaximumSpeed.
   */
  vtkIdType ComputeMovingNodes(
    vtkImageData* image, const int extent[6], double speed, const vtkPlumePercentile::Sum& sum);
#endif

  ///@{
  /** STRAIGHT (default), RK2 or RK4; other values are treated as STRAIGHT. */
  vtkSetMacro(Integrator, int);
  vtkGetMacro(Integrator, int);
  ///@}

  ///@{
  /**
   * Segments per streamlet for RK2/RK4. Default 8, clamped to 1..32.
   * Streamlets stop where they leave the volume or reach an invalid node. On a
   * grid one node thick along an axis (a slice), the velocity component along
   * that axis is ignored while integrating, so streamlets stay in the slice.
   */
  vtkSetClampMacro(StreamletSegments, int, 1, 32);
  vtkGetMacro(StreamletSegments, int);
  ///@}

  ///@{
  /** Roots with |v| <= MinimumSpeed emit nothing. Default 0 (only zero vectors are culled). */
  vtkSetClampMacro(MinimumSpeed, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MinimumSpeed, double);
  ///@}

  ///@{
  /** Alpha at the root; the tip has alpha 1. Default 0 (seed 002's fade-in). */
  vtkSetClampMacro(RootAlpha, double, 0.0, 1.0);
  vtkGetMacro(RootAlpha, double);
  ///@}

  ///@{
  /** Line width in pixels (wide lines are expanded to quads by the shader). Default 1. */
  vtkSetClampMacro(LineWidth, double, 0.5, 64.0);
  vtkGetMacro(LineWidth, double);
  ///@}

  ///@{
  /**
   * Colour by |v| through the lookup table (default on). Off: the actor's
   * property colour. The table is vtkMapper's LookupTable; the range is
   * vtkMapper's ScalarRange unless UseDataRange is on (default), in which case
   * it is the magnitude range of the valid nodes.
   */
  vtkSetMacro(ColorByMagnitude, bool);
  vtkGetMacro(ColorByMagnitude, bool);
  vtkBooleanMacro(ColorByMagnitude, bool);
  vtkSetMacro(UseDataRange, bool);
  vtkGetMacro(UseDataRange, bool);
  vtkBooleanMacro(UseDataRange, bool);
  ///@}

  ///@{
  /**
   * Shader path for straight 1-pixel lattice glyphs: VERTEX_SHADER (default)
   * or GEOMETRY_SHADER; both give the same image (see the class documentation).
   * Other glyphs always use the geometry shader.
   */
  vtkSetClampMacro(StraightLineShader, int, VERTEX_SHADER, GEOMETRY_SHADER);
  vtkGetMacro(StraightLineShader, int);
  ///@}

  ///@{
  /**
   * Largest number of roots per draw call; with more, the draws are throttled
   * to two in flight (see the class documentation: bounded driver memory,
   * slightly more time). 0 = all roots in one draw. Default 262144. Does not
   * change the image.
   */
  vtkSetClampMacro(MaximumGlyphsPerDraw, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MaximumGlyphsPerDraw, vtkIdType);
  ///@}

  /** Number of glyph roots submitted by the last render (before shader culling). */
  vtkGetMacro(LastRootCount, vtkIdType);

  /**
   * Number of velocity-texture uploads so far (tests check that re-renders do
   * not upload). A new upload happens only when the image, the chosen vector
   * array or the mask array changes (pointer or MTime) or after
   * ReleaseGraphicsResources (vtkPlumeVectorTexture3D decides).
   */
  int GetUploadCount();

  /**
   * Number of times a GPU copy of the vector array handed over by the filter
   * that computed it (vtkPlumeTextureHandOver, e.g. vtkPlumeGaussianSplatter
   * with GPUHandOver on, in this render window) was used instead of an upload.
   * Used only when there is no mask array and the texture is an RGBA32F grid
   * of the input's dimensions; otherwise the array is uploaded as usual.
   */
  int GetHandOverCount();

  /**
   * The mapper reports opaque geometry only; vtkActor still sends an actor
   * with opacity < 1 to the translucent pass. Which pass draws the glyphs,
   * with and without a vtkPlumeCompositingPass: "Compositing" in the class
   * documentation.
   */
  bool HasOpaqueGeometry() override { return true; }
  bool HasTranslucentPolygonalGeometry() override { return false; }

  void Render(vtkRenderer* ren, vtkActor* actor) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;
  /**
   * The image bounds (plus the seed bounds in ROOTS_SEEDS mode), extended
   * along each axis by how far a glyph can reach: Scale times the range of
   * that velocity component over the valid nodes (straight glyphs and RK
   * streamlets alike move by convex combinations of sampled vectors), so
   * VTK's automatic clipping range never cuts glyphs and camera resets frame
   * the data rather than a worst case. The padding is capped at 10 data diagonals so that
   * absurd vectors (1e30) do not ruin the automatic clipping range; glyphs
   * longer than that may be clipped by the far plane.
   */
  double* GetBounds() override;
  void GetBounds(double bounds[6]) override { this->vtkMapper::GetBounds(bounds); }

protected:
  vtkPlumeVelocityGlyphMapper();
  ~vtkPlumeVelocityGlyphMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  // Bring the inputs up to date (unless Static).
  void UpdateInputs();

  std::string VectorArrayName;
  std::string ValidMaskArrayName = "vtkValidPointMask";
  int RootMode = ROOTS_SCREEN_ADAPTIVE;
  int LatticeStride = 1;
  double ScreenSpacing = 12.0;
  int EffectiveStride = 1;
  int WholeExtent[6] = { 0, -1, 0, -1, 0, -1 };
  vtkIdType MovingNodeCount = -1;
  double Scale = 1.0;
  int ScaleMode = SCALE_AUTO;
  double AutomaticScaleSpeed = std::numeric_limits<double>::quiet_NaN();
  int Integrator = STRAIGHT;
  int StreamletSegments = 8;
  double MinimumSpeed = 0.0;
  double RootAlpha = 0.0;
  double LineWidth = 1.0;
  bool ColorByMagnitude = true;
  bool UseDataRange = true;
  int StraightLineShader = VERTEX_SHADER;
  vtkIdType MaximumGlyphsPerDraw = 262144;
  vtkIdType LastRootCount = 0;

private:
  vtkPlumeVelocityGlyphMapper(const vtkPlumeVelocityGlyphMapper&) = delete;
  void operator=(const vtkPlumeVelocityGlyphMapper&) = delete;

  class Internals; // GL state lives here
  std::unique_ptr<Internals> Impl;
};

#endif
