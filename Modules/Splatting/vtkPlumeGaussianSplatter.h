/**
 * @class   vtkPlumeGaussianSplatter
 * @brief   splats points and flow lines as normalised 3D Gaussians into an image (CPU or GPU)
 *
 * Seed 002 ("3D Gaussian Splat", "Flowline Extrusion"): a path sketched
 * through space becomes a space-filling velocity field.
 *
 * Inputs (both optional; an empty or missing input gives a valid all-zero image):
 *  - port 0, points: any vtkPointSet. Every point splats its value: the
 *    vector array (VECTOR_SUM; VectorArrayName, default the active vectors)
 *    or the scalar array (SCALAR_SUM and DISTANCE_MAX; ScalarArrayName,
 *    default the active scalars, or 1 when there are none: a density).
 *    Points flagged DUPLICATEPOINT in the vtkGhostType point array are
 *    skipped (the piece that owns them splats them).
 *  - port 1, lines: a vtkPolyData whose polylines are flow lines. Vertex i
 *    splats the velocity LineScaleFactor·(p[i+1] − p[i]) (VECTOR_SUM), its
 *    length (SCALAR_SUM) or 1 (DISTANCE_MAX). A closed loop (last point id
 *    equal to the first, or the same position) wraps around as in the seed's
 *    torus; the last vertex of an open line uses the backward difference.
 *    Zero-length segments and single-vertex lines contribute nothing (sums).
 *    Lines cut into pieces (over ranks, or into cells) splat each vertex once,
 *    as the uncut line does: a line cell flagged DUPLICATECELL or HIDDENCELL
 *    in vtkGhostType is not splatted, nor is a vertex flagged DUPLICATEPOINT
 *    (it is still the neighbour of the next), and an open line's last vertex
 *    is not splatted when another open line starts at the same position (the
 *    line continues there; that start splats it with the forward difference).
 *    vtkPlumePGaussianSplatter applies the last rule across MPI ranks.
 *
 * Splat radius σ: Radius (world units, default 0.1), or per point the
 * point array RadiusArrayName when set and present (in either input).
 *
 * Modes:
 *  - VECTOR_SUM (default): output point array "velocity" (3 floats), the sum
 *    of v·G_σ(x − c) over all splats;
 *  - SCALAR_SUM: "density" (1 float), the sum of s·G_σ(x − c);
 *  - DISTANCE_MAX: "distance" (1 float), the max over splats of
 *    s·max(0, 1 − |x − c|/R) with R the radius (seed: a distance-like field
 *    with linear falloff and MAX blending), point-sampled; background 0.
 *
 * G_σ is the normalised 3D Gaussian (its integral is 1). With
 * IntegrateOverVoxel on (default) each output value is the average of the
 * splat over the voxel (the cell of size Spacing centred on the point; erf
 * differences per axis), so the sum of all voxel values times the voxel
 * volume equals the splat's value exactly (up to the cutoff), however small
 * σ is. Off: the Gaussian sampled at the point (what vtkGaussianSplatter
 * does); the sum then misses mass when σ is below about one voxel (relative
 * error of the sum: ≈ 2 % at σ = 0.5 voxel, ~100 % at 0.1 voxel).
 *
 * Cutoff: a splat touches only the voxels within CutoffFactor·σ along each
 * axis (a box; the measured worst error against the uncut reference is
 * about exp(−k²/2) of the splat's peak, 3.4e-4 at the default k = 4, see
 * Documentation/Splatting.md). DISTANCE_MAX touches the voxels within R.
 * Splats whose box misses the grid are culled (GetCulledCount()).
 *
 * Grid: the reference image's origin, spacing and dimensions when
 * ReferenceImage is set; else Dimensions (default 64³) over ModelBounds
 * (points at the bounds, as vtkImageData), or, if ModelBounds is not valid
 * (default), the inputs' bounds padded by k·σmax (R in DISTANCE_MAX).
 *
 * Non-finite positions, values or radii (and radii ≤ 0) are skipped with one
 * warning giving their count (GetSkippedCount()).
 *
 * Backends (same results to float rounding; a test checks it):
 *  - BACKEND_CPU: vtkSMPTools over z-slabs, each owned by one task: no races,
 *    no atomics, bit-identical output for any thread count.
 *  - BACKEND_GPU: OpenGL 3.2+. Splats are grouped by the number of z slices
 *    they touch; one instanced draw per group (one instance per splat, one
 *    point per slice), a geometry shader sends each (splat, slice) quad to its
 *    layer with gl_Layer, additive (or MAX) blending into a float 3D texture
 *    attached as a layered framebuffer, then read back. Needs a GL context:
 *    RenderWindow if set (a vtkOpenGLRenderWindow), else an offscreen window
 *    of its own (needs an X display with Debian's VTK).
 *  - BACKEND_AUTO (default): the backend measured to be faster for the job
 *    (voxel-touches of all splats) on this kind of machine; see
 *    Documentation/Splatting.md. Falls back to the CPU if the GPU fails.
 *
 * The output is recomputed only when an input, the reference image or a
 * setting changed (GetExecuteCount()).
 */
#ifndef vtkPlumeGaussianSplatter_h
#define vtkPlumeGaussianSplatter_h

#include "PlumeSplattingModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For std::vector

class vtkImageData;
class vtkPlumeParameterTable;
class vtkPolyData;
class vtkRenderWindow;

class PLUMESPLATTING_EXPORT vtkPlumeGaussianSplatter : public vtkImageAlgorithm
{
public:
  static vtkPlumeGaussianSplatter* New();
  vtkTypeMacro(vtkPlumeGaussianSplatter, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

#ifndef __VTK_WRAP__
  /**
   * The one declaration of the splatter's user parameters (the ParaView
   * filter's properties and the keys of a scene's splat dataset are made
   * from it); the constructor applies its defaults. Dimensions, ModelBounds
   * and the inputs are not in it.
   */
  static const vtkPlumeParameterTable& GetParameterTable();
#endif

  enum Modes
  {
    VECTOR_SUM = 0,
    SCALAR_SUM = 1,
    DISTANCE_MAX = 2
  };
  enum Backends
  {
    BACKEND_AUTO = 0,
    BACKEND_CPU = 1,
    BACKEND_GPU = 2
  };

  ///@{
  /** Flow lines (input port 1): polylines of a vtkPolyData. Optional. */
  void SetLinesData(vtkPolyData* lines);
  void SetLinesConnection(vtkAlgorithmOutput* output);
  ///@}

  ///@{
  /** VECTOR_SUM (default), SCALAR_SUM or DISTANCE_MAX. */
  vtkSetClampMacro(Mode, int, VECTOR_SUM, DISTANCE_MAX);
  vtkGetMacro(Mode, int);
  ///@}

  ///@{
  /** BACKEND_AUTO (default), BACKEND_CPU or BACKEND_GPU. */
  vtkSetClampMacro(Backend, int, BACKEND_AUTO, BACKEND_GPU);
  vtkGetMacro(Backend, int);
  /** The backend the last execution used (BACKEND_CPU or BACKEND_GPU). */
  vtkGetMacro(LastBackend, int);
  ///@}

  ///@{
  /** Output dimensions when there is no reference image. Default 64, 64, 64 (each ≥ 1). */
  vtkSetVector3Macro(Dimensions, int);
  vtkGetVector3Macro(Dimensions, int);
  ///@}

  ///@{
  /** Output bounds (xmin, xmax, ...) when there is no reference image. Default invalid (1, -1, ...): from the inputs. */
  vtkSetVector6Macro(ModelBounds, double);
  vtkGetVector6Macro(ModelBounds, double);
  ///@}

  ///@{
  /** Take origin, spacing and dimensions from this image (its data is not used). Default none. */
  void SetReferenceImage(vtkImageData* image);
  vtkImageData* GetReferenceImage();
  ///@}

  ///@{
  /** Splat radius σ (DISTANCE_MAX: the falloff radius R), world units. Default 0.1. */
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /** Point array with a per-point radius (either input); empty (default) or absent: Radius. */
  vtkSetStdStringFromCharMacro(RadiusArrayName);
  vtkGetCharFromStdStringMacro(RadiusArrayName);
  ///@}

  ///@{
  /** Vector array of the points (VECTOR_SUM); empty (default): the active vectors. */
  vtkSetStdStringFromCharMacro(VectorArrayName);
  vtkGetCharFromStdStringMacro(VectorArrayName);
  ///@}

  ///@{
  /** Scalar array of the points (SCALAR_SUM, DISTANCE_MAX); empty (default): active scalars, else 1. */
  vtkSetStdStringFromCharMacro(ScalarArrayName);
  vtkGetCharFromStdStringMacro(ScalarArrayName);
  ///@}

  ///@{
  /** Factor on the line velocities p[i+1] − p[i]. Default 1. */
  vtkSetMacro(LineScaleFactor, double);
  vtkGetMacro(LineScaleFactor, double);
  ///@}

  ///@{
  /** k: splats touch voxels within k·σ per axis. Default 4 (error ≈ exp(−k²/2) of the peak). Clamped to [0.5, 40]. */
  vtkSetClampMacro(CutoffFactor, double, 0.5, 40.0);
  vtkGetMacro(CutoffFactor, double);
  ///@}

  ///@{
  /** Average each splat over the voxel (erf) instead of sampling it at the point. Default on. */
  vtkSetMacro(IntegrateOverVoxel, bool);
  vtkGetMacro(IntegrateOverVoxel, bool);
  vtkBooleanMacro(IntegrateOverVoxel, bool);
  ///@}

  ///@{
  /** GL context for the GPU backend (a vtkOpenGLRenderWindow). Default none: an offscreen window of its own. */
  void SetRenderWindow(vtkRenderWindow* window);
  vtkRenderWindow* GetRenderWindow();
  ///@}

  /** Splats of the last execution: touching the grid, culled outside it, skipped (non-finite or radius ≤ 0). */
  vtkGetMacro(SplatCount, vtkIdType);
  vtkGetMacro(CulledCount, vtkIdType);
  vtkGetMacro(SkippedCount, vtkIdType);
  /** Number of executions so far (unchanged inputs do not re-execute). */
  vtkGetMacro(ExecuteCount, int);
  /** Wall time of the last splatting step (backend only), seconds. */
  vtkGetMacro(LastSplatSeconds, double);

  /**
   * Why the last execution produced no field ("" after a successful one): inputs whose cells
   * reference points that do not exist or whose arrays are shorter than them, a grid over the
   * memory budget, or footprints whose voxel count is over the work budget
   * (vtkPlumeInputValidation: $PLUME_MEMORY_BUDGET_MB, $PLUME_WORK_BUDGET).
   */
  const std::string& GetLastError() const { return this->LastError; }

  /**
   * Voxel touches (Σ over splats of voxels in its box) above which AUTO uses
   * the GPU. Default: measured on this kind of machine (see Documentation/Splatting.md).
   */
  vtkSetMacro(AutoGPUThreshold, double);
  vtkGetMacro(AutoGPUThreshold, double);

  ///@{
  /**
   * Hand the GPU backend's result texture over with the output (VECTOR_SUM
   * only, and only when RenderWindow is set): the velocity array's
   * information then carries a vtkPlumeTextureHandOver, and a
   * vtkPlumeVelocityGlyphMapper rendering in that window binds the texture
   * instead of uploading the array (see GetHandOverCount() there). The array
   * is still read back, so every other consumer sees complete data; the
   * saving is the consumer's conversion and upload (measured in
   * Documentation/Splatting.md). The next GPU execution reuses the texture
   * and revokes the hand-over first, so arrays of earlier outputs still held
   * somewhere are uploaded from their own values. Default off.
   */
  vtkSetMacro(GPUHandOver, bool);
  vtkGetMacro(GPUHandOver, bool);
  vtkBooleanMacro(GPUHandOver, bool);
  ///@}

  /** Release the GPU backend's GL resources (before the window goes away). */
  void ReleaseGraphicsResources();

protected:
  vtkPlumeGaussianSplatter();
  ~vtkPlumeGaussianSplatter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  vtkMTimeType GetMTime() override;

  /**
   * Appends the position (x, y, z) of the first vertex of every open line
   * cell of lines that is splatted (not a ghost): where a line ending on the
   * same position continues.
   */
  static void CollectLineStarts(vtkPolyData* lines, std::vector<double>& starts);
  /**
   * Line starts held elsewhere (other ranks), x, y, z each, added to the
   * local ones for the continuation rule. Default empty; set by
   * vtkPlumePGaussianSplatter around an execution.
   */
  std::vector<double> LineContinuations;

  int Mode = VECTOR_SUM;
  int Backend = BACKEND_AUTO;
  int LastBackend = BACKEND_CPU;
  int Dimensions[3] = { 64, 64, 64 };
  double ModelBounds[6] = { 1, -1, 1, -1, 1, -1 };
  double Radius = 0.1;
  std::string RadiusArrayName;
  std::string VectorArrayName;
  std::string ScalarArrayName;
  double LineScaleFactor = 1.0;
  double CutoffFactor = 4.0;
  bool IntegrateOverVoxel = true;
  bool GPUHandOver = false;
  double AutoGPUThreshold;
  vtkIdType SplatCount = 0;
  vtkIdType CulledCount = 0;
  vtkIdType SkippedCount = 0;
  int ExecuteCount = 0;
  double LastSplatSeconds = 0;
  std::string LastError;

private:
  vtkPlumeGaussianSplatter(const vtkPlumeGaussianSplatter&) = delete;
  void operator=(const vtkPlumeGaussianSplatter&) = delete;

  class Internals; // reference image, render window, GPU backend state
  std::unique_ptr<Internals> Impl;
};

#endif
