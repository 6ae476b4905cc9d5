/**
 * @class   vtkPlumeSheetMapper
 * @brief   triangle meshes drawn as volumetric Gaussian smoke sheets (seed 000)
 *
 * Input: a vtkPolyData. Its polygons (fanned into triangles) and triangle
 * strips are drawn; vertices and lines are ignored with a warning. Cells
 * flagged DUPLICATECELL or HIDDENCELL in the vtkGhostType cell array are
 * skipped (another piece draws them), as VTK's own mappers do. Every point
 * carries a density d (mass per unit area), a blurring radius sigma_b (in the
 * surface) and a thickness sigma_t (across it), each from a named point array
 * or, when the name is empty or the array is missing, a constant. The smoke is
 *   density(x) = sum over triangles of the integral over the triangle of
 *                d(p) G(x - p) dA(p),
 * G a unit-mass anisotropic Gaussian with sigma_b, sigma_t interpolated
 * barycentrically at p. Each pixel is darkened by T = exp(-tau), tau the
 * integral of the density along the view ray (times the optional per-point
 * RGB absorption, so coloured smoke darkens channels differently).
 *
 * How: a geometry shader emits, per triangle, a screen box covering every
 * ray that passes within Cutoff standard deviations of the triangle (seed 000
 * Appendix A, with a 1/3-pixel lower bound on both sigmas). The fragment
 * shader integrates over the triangle on a GridA x GridB grid aligned with
 * the ray's footprint, sampled twice with per-fragment random offsets, using
 * the closed-form line integral of the Gaussian along the ray (bounded to
 * the part of the ray between the near plane and the opaque depth already in
 * the depth buffer, in erf form). The optical depths are added in a private
 * float target (order-independent, no sorting, no 8-bit round-off per
 * triangle); one composite pass then multiplies the frame by T and, if
 * SmokeColor is not black, adds SmokeColor·(1 - T).
 *
 * Why a vtkMapper with private GL rather than a vtkOpenGLPolyDataMapper
 * subclass: the sheet needs its own per-triangle-corner attributes, a copy
 * of the opaque depth buffer, a float accumulation target and a composite
 * pass; none of the polydata mapper's lighting/colouring template is used,
 * and the same pattern as vtkPlumeVelocityGlyphMapper keeps GL state private.
 *
 * Compositing: with a vtkPlumeCompositingPass on the renderer (what `plume`
 * and the ParaView plugin use), the sheet is a medium: it draws after the
 * opaque scene, the glyphs and VTK's translucent pass, sorted back to front
 * with the other media and volumes, bounded by the frame's shared opaque
 * depth, whatever the order the actors were added in. In a plain
 * vtkRenderer it draws in the opaque pass, without depth writes, and sees
 * the depth buffer as it is when the actor renders: add it after the opaque
 * actors it overlaps. Either way the depth is read through
 * vtkPlumeOpaqueDepthTexture (which resolves multisampled windows); if it
 * cannot be read the sheet warns once and is not bounded by it.
 *
 * Bad values: a point whose density is NaN, Inf or negative counts as zero
 * density; a non-finite or negative sigma counts as zero (then the 1/3-pixel
 * lower bound applies); a triangle with a non-finite corner position, zero
 * density at all three corners or zero area is skipped. Nothing is rejected,
 * so a partly broken mesh still draws its valid part (GetSkippedTriangles
 * reports how many were dropped for non-finite positions).
 *
 * Actor transform: positions go through the actor's matrix; sigma_b and
 * sigma_t are model lengths, multiplied by the matrix's length scale
 * cbrt(|det|) (exact for uniform scales); densities stay per unit of world
 * area. vtkPlumeSheetReference::SetModelMatrix follows the same rules.
 *
 * Precision: positions are uploaded relative to the mesh centre and the
 * model-to-eye matrix is composed in double, so meshes far from the origin
 * render like meshes at the origin. Uploads happen only when the mesh, the
 * arrays or the density/sigma settings change: camera moves upload nothing.
 */
#ifndef vtkPlumeSheetMapper_h
#define vtkPlumeSheetMapper_h

#include "PlumeSheetsModule.h" // For export macro
#include "vtkMapper.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class vtkPlumeParameterTable;
class vtkPolyData;

class vtkPlumeSheetDensityGrid;
class PLUMESHEETS_EXPORT vtkPlumeSheetMapper : public vtkMapper
{
public:
  static vtkPlumeSheetMapper* New();
  vtkTypeMacro(vtkPlumeSheetMapper, vtkMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

#ifndef __VTK_WRAP__
  /**
   * The one declaration of the sheet's user parameters (scene keys, defaults,
   * ranges, documentation) that the scene reader, Documentation/SceneFormat.md
   * and the ParaView XML are made from; the constructor applies its defaults.
   */
  static const vtkPlumeParameterTable& GetParameterTable();
#endif

  ///@{
  /** The sheet mesh. */
  void SetInputData(vtkPolyData* input);
  vtkPolyData* GetInput();
  ///@}

  ///@{
  /** Point array of density (1 component). Empty (default): the constant Density. */
  vtkSetStdStringFromCharMacro(DensityArrayName);
  vtkGetCharFromStdStringMacro(DensityArrayName);
  /** Density (per unit area, optical depth per unit of area) where no array is used. Default 1. */
  vtkSetMacro(Density, double);
  vtkGetMacro(Density, double);
  /** Multiplies every density (array or constant). Default 1. */
  vtkSetMacro(DensityScale, double);
  vtkGetMacro(DensityScale, double);
  ///@}

  /**
   * Largest sigma_b and sigma_t drawn (model units, 1e15): larger blur or thickness values
   * (constants or array values) are clamped to it. The shaders square and multiply sigmas
   * in 32-bit floats, which overflow to NaN (a black frame) from about 1e18; at 1e15 the
   * smoke of any real mesh is already spread to nothing.
   */
  static constexpr double MaximumSigma = 1e15;

  ///@{
  /** Point array of the blurring radius sigma_b (model units). Empty (default): BlurRadius. */
  vtkSetStdStringFromCharMacro(BlurArrayName);
  vtkGetCharFromStdStringMacro(BlurArrayName);
  /** sigma_b where no array is used, model units. Default 0.05. */
  vtkSetMacro(BlurRadius, double);
  vtkGetMacro(BlurRadius, double);
  ///@}

  ///@{
  /** Point array of the thickness sigma_t (model units). Empty (default): Thickness. */
  vtkSetStdStringFromCharMacro(ThicknessArrayName);
  vtkGetCharFromStdStringMacro(ThicknessArrayName);
  /** sigma_t where no array is used, model units. Default 0.05. */
  vtkSetMacro(Thickness, double);
  vtkGetMacro(Thickness, double);
  ///@}

  ///@{
  /**
   * Optional 3-component point array of RGB absorption: the density of channel
   * c is d·absorption_c. Empty (default): grey smoke (1, 1, 1).
   */
  vtkSetStdStringFromCharMacro(AbsorptionArrayName);
  vtkGetCharFromStdStringMacro(AbsorptionArrayName);
  ///@}

  ///@{
  /**
   * Colour the smoke sends back: each pixel becomes frame·T + SmokeColor·(1 - T).
   * Default (0, 0, 0): zero albedo, the smoke only absorbs (as in the paper).
   */
  vtkSetVector3Macro(SmokeColor, double);
  vtkGetVector3Macro(SmokeColor, double);
  ///@}

  ///@{
  /**
   * Thin-sheet mode: sigma_t = 0 exactly (the density is a surface layer,
   * 2D Gaussian in the plane, divided by |cos| of the view angle), ignoring
   * Thickness and the thickness array. Default off.
   */
  vtkSetMacro(ThinSheet, bool);
  vtkGetMacro(ThinSheet, bool);
  vtkBooleanMacro(ThinSheet, bool);
  ///@}

  ///@{
  /**
   * Integrate only from the near plane to the opaque depth already in the
   * depth buffer (default on), so sheets crossing opaque actors are right in
   * front of, behind and across them. Off: the whole line, as in the paper.
   */
  vtkSetMacro(BoundedByDepth, bool);
  vtkGetMacro(BoundedByDepth, bool);
  vtkBooleanMacro(BoundedByDepth, bool);
  ///@}

  ///@{
  /**
   * Support radius Lambda in standard deviations. Default 3.5: a 2D Gaussian
   * keeps all but exp(-3.5²/2) = 0.2 % of its mass inside, below the 1 % error
   * goal measured by the tests. Clamped to 1..10.
   */
  vtkSetClampMacro(Cutoff, double, 1.0, 10.0);
  vtkGetMacro(Cutoff, double);
  ///@}

  ///@{
  /** Lower bound on sigma_b and sigma_t in pixels at each corner's depth. Default 1/3 (seed 000). */
  vtkSetClampMacro(MinimumSigmaPixels, double, 0.0, 100.0);
  vtkGetMacro(MinimumSigmaPixels, double);
  ///@}

  ///@{
  /**
   * Quadrature resolution. QUADRATURE_ANALYTIC: GridA Gauss-Legendre nodes on
   * each smooth piece along the ray's footprint; across it, where sigma_b or
   * sigma_t differ between a triangle's corners, GridB nodes per piece of the
   * correction to the frozen-sigma closed form (pieces graded 2, 4, 8, ...
   * sigma_b out from the footprint; 5 met the goal on every varying-sigma
   * test scene, up to a tenfold sigma_b ratio). QUADRATURE_GRID:
   * GridA cells along the footprint, GridB across it, each sampled twice with
   * random offsets (seed 000). Defaults 8 x 5: with the analytic quadrature, 8
   * is the smallest GridA that met the accuracy goal on every test scene (4
   * did not: 15 % max error with sub-pixel sigmas). Clamped to 1..32.
   */
  vtkSetClampMacro(GridA, int, 1, 32);
  vtkGetMacro(GridA, int);
  vtkSetClampMacro(GridB, int, 1, 32);
  vtkGetMacro(GridB, int);
  ///@}

  enum QuadratureModes
  {
    QUADRATURE_GRID = 0,    ///< seed 000: GridA x GridB samples over the triangle, twice
    QUADRATURE_ANALYTIC = 1 ///< GridA jittered rows along the footprint, closed form across it
  };
  ///@{
  /**
   * How the fragment shader integrates over the triangle. Default
   * QUADRATURE_ANALYTIC: only the direction along the ray's footprint is
   * sampled (GridA cells, twice); the direction across it is integrated in
   * closed form over the triangle's chord (erf), which removes the sampling
   * noise at triangle edges. QUADRATURE_GRID is the paper's regular grid.
   */
  vtkSetClampMacro(Quadrature, int, QUADRATURE_GRID, QUADRATURE_ANALYTIC);
  vtkGetMacro(Quadrature, int);
  ///@}

  ///@{
  /**
   * Adaptive sampling (QUADRATURE_ANALYTIC only): a triangle whose diameter is
   * below 0.5 sigma_b (at its smallest corner value) is integrated with a
   * 3-point rule instead of the Gauss-Legendre pieces; the integrand varies on
   * the scale sigma_b or slower, so the rule's error stays well inside the
   * accuracy goal (measured by the real-mesh test). Default on.
   */
  vtkSetMacro(AdaptiveSampling, bool);
  vtkGetMacro(AdaptiveSampling, bool);
  vtkBooleanMacro(AdaptiveSampling, bool);
  ///@}

  ///@{
  /**
   * Largest number of triangles per draw call; with more, the draws are
   * throttled to two in flight (vtkPlumeThrottledDraw.h): llvmpipe otherwise
   * queues the binned boxes of the whole mesh, about 1.3 KB per triangle.
   * Measured on 327k triangles (the bench's subdivided fire isosurface,
   * 256x256): peak memory 576 MB in one draw, 412 MB in 64k-triangle draws,
   * 235 MB in 16k-triangle draws, at the same frame time (24-25 s: each
   * triangle's fragments cost far more than the lost overlap of binning and
   * rasterizing). 0 = one draw. Default 16384. Does not change the image
   * (each triangle keeps its id, which seeds the grid's random offsets).
   */
  vtkSetClampMacro(MaximumTrianglesPerDraw, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MaximumTrianglesPerDraw, vtkIdType);
  ///@}

  enum RenderModes
  {
    RENDER_EXACT = 0, ///< every triangle integrated per pixel (the reference-quality renderer)
    RENDER_GRID = 1   ///< the smoke sampled once on a grid, raycast every frame (interactive)
  };
  ///@{
  /**
   * RENDER_EXACT (default): each triangle's smoke integrated along every
   * pixel's ray by the geometry/fragment shaders above. RENDER_GRID: the
   * density field (view-independent) is computed once per mesh or parameter
   * change on a regular grid whose spacing is the smallest sigma divided by
   * GridSamplesPerSigma (vtkPlumeSheetDensityGrid: a quadrature of each
   * triangle, not vertex splats) and raycast every frame by a
   * vtkPlumeVolumeMapper (absorption and smoke colour, opaque depth,
   * empty-space skipping, camera inside): a camera move costs one raycast
   * whatever the triangle count. In grid mode RGB absorption arrays are
   * ignored (grey smoke, a warning), sigmas below GridSamplesPerSigma x the
   * spacing are raised to it instead of the 1/3-pixel floor (thin sheets get
   * that thickness), and every change of the mesh, its arrays or the
   * density/sigma settings recomputes the grid (GetGridComputeCount).
   */
  vtkSetClampMacro(RenderMode, int, RENDER_EXACT, RENDER_GRID);
  vtkGetMacro(RenderMode, int);
  ///@}

  ///@{
  /** Grid mode: grid nodes per smallest sigma. Default 2 (measured: see Documentation/Renderers.md). Clamped to 0.25..16. */
  vtkSetClampMacro(GridSamplesPerSigma, double, 0.25, 16.0);
  vtkGetMacro(GridSamplesPerSigma, double);
  ///@}

  ///@{
  /** Grid mode: raycast step in grid spacings. Default 1. Clamped to 0.05..16. */
  vtkSetClampMacro(GridSampleDistance, double, 0.05, 16.0);
  vtkGetMacro(GridSampleDistance, double);
  ///@}

  ///@{
  /** Grid mode: most grid nodes (4 bytes each); the spacing grows to fit. Default 2^25 (128 MB). */
  vtkSetClampMacro(GridMaximumNodes, double, 8.0, 1e12);
  vtkGetMacro(GridMaximumNodes, double);
  ///@}

  ///@{
  /**
   * Grid mode: the quadrature points in each cubic cell of this many grid
   * spacings become one Gaussian (mass, centroid and second moment kept)
   * before the grid is computed (vtkPlumeSheetDensityGrid::SetMergeCellSize);
   * 0 splats every point (exact, minutes on large meshes). Default 2. Clamped to 0..4.
   */
  vtkSetClampMacro(GridMergeCellSize, double, 0.0, 4.0);
  vtkGetMacro(GridMergeCellSize, double);
  ///@}

  ///@{
  /**
   * Grid mode: coarse while the camera moves, refined when it stops (VTK's
   * convention, as vtkPlumeVolumeMapper's AutoAdjustSampleDistances): a frame
   * is interactive when the actor's allocated render time is below 1 s, i.e.
   * the render window's DesiredUpdateRate is above 1 frame/s (the interactor
   * sets its DesiredUpdateRate while the user moves the camera and its
   * StillUpdateRate when the user lets go, then renders once more). An
   * interactive frame raycasts the same grid with steps of
   * InteractiveGridSampleDistance spacings on a lattice of one ray per
   * InteractiveImageSampleDistance pixels (interpolated where the lattice
   * agrees, vtkPlumeVolumeMapper's error-controlled lattice); a still frame
   * uses GridSampleDistance and one ray per pixel. Both read the same grid,
   * so the switch computes and uploads nothing, and every frame is cast anew
   * (no stale frame). A still frame is skipped when the window's abort check
   * reports waiting input (VTK's AbortCheckEvent): VTK then does not show the
   * frame, and the interaction goes on. Off: every frame is a still frame.
   * Default on.
   */
  vtkSetMacro(AutoAdjustQuality, bool);
  vtkGetMacro(AutoAdjustQuality, bool);
  vtkBooleanMacro(AutoAdjustQuality, bool);
  /** Grid mode, interactive frames: raycast step in grid spacings. Default 2. Clamped to 0.05..16. */
  vtkSetClampMacro(InteractiveGridSampleDistance, double, 0.05, 16.0);
  vtkGetMacro(InteractiveGridSampleDistance, double);
  /** Grid mode, interactive frames: one ray per this many pixels (1: every pixel). Default 2. Clamped to 1..16. */
  vtkSetClampMacro(InteractiveImageSampleDistance, int, 1, 16);
  vtkGetMacro(InteractiveImageSampleDistance, int);
  /**
   * Grid mode, interactive frames: the largest difference (transmittance,
   * 0..1) between the four lattice rays around a pixel for which it
   * interpolates them instead of casting its own ray
   * (vtkPlumeVolumeMapper::LatticeTolerance). Default 0.004. Clamped to 0..1.
   */
  vtkSetClampMacro(InteractiveLatticeTolerance, double, 0.0, 1.0);
  vtkGetMacro(InteractiveLatticeTolerance, double);
  ///@}

  /** Grid mode: whether the last frame was drawn with the interactive settings. */
  vtkGetMacro(LastInteractive, bool);
  /**
   * Grid mode: still frames not drawn because the render window's abort
   * check (vtkCommand::AbortCheckEvent, SetAbortRender) reported waiting input.
   */
  vtkGetMacro(AbortedStillFrames, int);
  /**
   * Grid mode: whether the last frame read the opaque depth. Only when
   * BoundedByDepth is on and the renderer holds another visible prop that
   * may write depth (any but 2D actors): with none, the depth is the far
   * plane everywhere, and reading it (a copy of the depth buffer, and every
   * pixel's depth in the ray lattice's classification) would change nothing.
   */
  vtkGetMacro(LastOpaqueDepth, bool);
  /** Grid mode: the raycast step (grid spacings) of the last frame. */
  vtkGetMacro(LastGridSampleDistance, double);
  /** Grid mode: the ray lattice (pixels) of the last frame, as the volume mapper used it. */
  vtkGetMacro(LastImageSampleDistance, int);

  /** Grid mode: grids computed so far (camera moves add none; data and sigma changes add one). */
  vtkGetMacro(GridComputeCount, int);
  /** Grid mode: the spacing of the current grid (model units), 0 before the first. */
  vtkGetMacro(GridSpacing, double);
  /** Grid mode: seconds the last grid took to compute. */
  vtkGetMacro(GridComputeSeconds, double);
  /** Grid mode: the density grid builder (its last Compute's parts and counts). */
  vtkPlumeSheetDensityGrid* GetDensityGrid();

  /** Draw calls of the sheet's triangles in the last render (MaximumTrianglesPerDraw splits them). */
  vtkGetMacro(LastDrawCount, int);

  /** Number of triangle uploads so far (camera moves must not add any). */
  vtkGetMacro(UploadCount, int);
  /** Triangles drawn by the last upload (after culling zero density, bad and zero-area input). */
  vtkGetMacro(TriangleCount, vtkIdType);
  /** Triangles skipped by the last upload because a corner position was not finite. */
  vtkGetMacro(SkippedTriangles, vtkIdType);

  bool HasOpaqueGeometry() override { return true; }
  bool HasTranslucentPolygonalGeometry() override { return false; }

  void Render(vtkRenderer* ren, vtkActor* actor) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;
  /** Mesh bounds padded by Cutoff times the largest sigma (capped at 10 mesh diagonals). */
  double* GetBounds() override;
  void GetBounds(double bounds[6]) override { this->vtkMapper::GetBounds(bounds); }

  /**
   * Whether drawing `mesh` with the current parameters fits the budgets
   * (vtkPlumeInputValidation): "" or the message Render() would give, naming
   * the triangle count and the budget. Exact mode: the vertex data (96 bytes
   * per triangle, twice) against PLUME_MEMORY_BUDGET_MB and one draw call's
   * vertex count; grid mode: the quadrature against the memory and the work
   * budget (vtkPlumeSheetDensityGrid::CheckBudget). Cheap: one pass over the
   * triangles, nothing drawn or splatted.
   */
  std::string CheckBudget(vtkPolyData* mesh);

protected:
  vtkPlumeSheetMapper();
  ~vtkPlumeSheetMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  std::string DensityArrayName;
  std::string BlurArrayName;
  std::string ThicknessArrayName;
  std::string AbsorptionArrayName;
  double Density = 1.0;
  double DensityScale = 1.0;
  double BlurRadius = 0.05;
  double Thickness = 0.05;
  double SmokeColor[3] = { 0, 0, 0 };
  bool ThinSheet = false;
  bool BoundedByDepth = true;
  double Cutoff = 3.5;
  double MinimumSigmaPixels = 1.0 / 3.0;
  int GridA = 8;
  int GridB = 5;
  int Quadrature = QUADRATURE_ANALYTIC;
  bool AdaptiveSampling = true;
  vtkIdType MaximumTrianglesPerDraw = 16384;
  int RenderMode = RENDER_EXACT;
  double GridSamplesPerSigma = 2.0;
  double GridSampleDistance = 1.0;
  double GridMaximumNodes = 33554432.0;
  double GridMergeCellSize = 2.0;
  bool AutoAdjustQuality = true;
  double InteractiveGridSampleDistance = 2.0;
  int InteractiveImageSampleDistance = 2;
  double InteractiveLatticeTolerance = 0.004;
  bool LastInteractive = false;
  bool LastOpaqueDepth = false;
  double LastGridSampleDistance = 0.0;
  int LastImageSampleDistance = 0;
  int AbortedStillFrames = 0;
  int GridComputeCount = 0;
  double GridSpacing = 0.0;
  double GridComputeSeconds = 0.0;
  int LastDrawCount = 0;
  int UploadCount = 0;
  vtkIdType TriangleCount = 0;
  vtkIdType SkippedTriangles = 0;

private:
  vtkPlumeSheetMapper(const vtkPlumeSheetMapper&) = delete;
  void operator=(const vtkPlumeSheetMapper&) = delete;

  void ConfigureGrid(vtkPlumeSheetDensityGrid* grid, vtkPolyData* poly);

  class Internals; // GL state and the render steps live here
  std::unique_ptr<Internals> Impl;
};

#endif
