/**
 * @class   vtkPlumeDerivedGeometry
 * @brief   geometry derived from a flow dataset with VTK's own filters, for scenes
 *
 * One filter for the derived datasets of a scene (issue 15: a user should not
 * have to make contours or stream surfaces outside Plume first). Operation:
 *  - CONTOUR: isosurface(s) of a scalar array (vtkContourFilter); a vector
 *    array is contoured by its magnitude;
 *  - SLICE: the cut by a plane (vtkCutter);
 *  - STREAMLINES: vtkStreamTracer (RK4) from the seeds (a line, a plane, or
 *    the points of a seeds dataset);
 *  - STREAM_SURFACE: vtkStreamSurface from the seed line;
 *  - RIBBON: streamlines widened into ribbons (vtkRibbonFilter, oriented by the
 *    streamlines' vorticity);
 *  - THRESHOLD: the cells whose array lies in [lower, upper] (vtkThreshold;
 *    a cell array is thresholded as cell data, not interpolated, even when the
 *    reader also made a point array of the same name);
 *  - CLIP: the half of the data on the normal's side of a plane
 *    (vtkTableBasedClipDataSet).
 * Every result keeps the input's point arrays, interpolated (so a sheet can take
 * its density from a concentration on a stream surface). Arrays that exist
 * only as cell data (finite-volume results) are first interpolated to the
 * points where an operation needs point values (vtkCellDataToPointData).
 *
 * Positions (Origin, SeedPoint1, SeedPoint2) are fractions of the input's
 * bounds by default (Coordinates RELATIVE: 0 = minimum, 1 = maximum along each
 * axis), so the defaults — a plane and a seed line through the centre — show
 * something on any data; WORLD takes them as model coordinates.
 *
 * Values (contour iso values; threshold [lower, upper]) default to the median
 * of the array's valid values (finite, and not masked by vtkValidPointMask).
 *
 * Input port 0: the dataset (vtkDataSet). Optional input port 1: seeds (their
 * points seed streamlines and ribbons; for a stream surface they must be
 * ordered along the seed curve) instead of the seed line.
 *
 * Output: vtkPolyData (contour, slice, streamlines, stream surface, ribbon) or
 * vtkUnstructuredGrid (threshold, clip). A parameter that cannot work (unknown
 * array, zero normal, a seed outside the data) or an empty result fails the
 * update with GetLastError() naming the parameter's scene key and its value.
 *
 * Budgets (issue 12): the output size is estimated before the filter runs
 * where it can be (contour and slice: work of the input's cells times the
 * values; streamlines, stream surfaces and ribbons: seeds x maximum steps x
 * directions points against the memory budget and integration steps against
 * the work budget, vtkPlumeInputValidation::CheckMemory/CheckWork), and every
 * result is checked against the memory budget after the filter; either fails
 * the update with a message naming the count, the estimate and the budget.
 *
 * Parameters are declared once in GetParameterTable() (scene type "derived").
 */
#ifndef vtkPlumeDerivedGeometry_h
#define vtkPlumeDerivedGeometry_h

#include "PlumeDataModule.h" // For export macro
#include "vtkDataObjectAlgorithm.h"
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <string> // For std::string
#include <vector> // For std::vector

class vtkDataArray;
class vtkDataSet;
class vtkPlumeParameterTable;

class PLUMEDATA_EXPORT vtkPlumeDerivedGeometry : public vtkDataObjectAlgorithm
{
public:
  static vtkPlumeDerivedGeometry* New();
  vtkTypeMacro(vtkPlumeDerivedGeometry, vtkDataObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The one declaration of this class's parameters (scene keys, defaults, ranges, docs). */
  VTK_WRAPEXCLUDE static const vtkPlumeParameterTable& GetParameterTable();

  enum Operations
  {
    CONTOUR = 0,
    SLICE,
    STREAMLINES,
    STREAM_SURFACE,
    RIBBON,
    THRESHOLD,
    CLIP
  };
  enum CoordinateModes
  {
    RELATIVE = 0,
    WORLD
  };
  enum Directions
  {
    FORWARD = 0,
    BACKWARD,
    BOTH
  };

  ///@{
  /** What to derive (Operations). Default CONTOUR. */
  vtkSetClampMacro(Operation, int, CONTOUR, CLIP);
  vtkGetMacro(Operation, int);
  ///@}

  ///@{
  /**
   * Scalar array (point or cell) of contour and threshold; a multi-component
   * array is taken by magnitude. Default "": the active scalars, else the
   * first one-component point array, else the first cell array.
   */
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);
  ///@}

  ///@{
  /** Vector array of streamlines, stream surfaces and ribbons. Default "": the active vectors, else the first 3-component array. */
  vtkSetStringMacro(VectorArrayName);
  vtkGetStringMacro(VectorArrayName);
  ///@}

  ///@{
  /** How Origin and the seed points are given (CoordinateModes). Default RELATIVE. */
  vtkSetClampMacro(Coordinates, int, RELATIVE, WORLD);
  vtkGetMacro(Coordinates, int);
  ///@}

  ///@{
  /** A point of the slice/clip plane. Default (0.5, 0.5, 0.5): the centre (relative coordinates). */
  vtkSetVector3Macro(Origin, double);
  vtkGetVector3Macro(Origin, double);
  ///@}

  ///@{
  /** Normal of the slice/clip plane (need not be unit length; not zero). Default (1, 0, 0). */
  vtkSetVector3Macro(Normal, double);
  vtkGetVector3Macro(Normal, double);
  ///@}

  ///@{
  /** Ends of the seed line. Defaults (0.5, 0.1, 0.5) and (0.5, 0.9, 0.5): across the centre along y. */
  vtkSetVector3Macro(SeedPoint1, double);
  vtkGetVector3Macro(SeedPoint1, double);
  vtkSetVector3Macro(SeedPoint2, double);
  vtkGetVector3Macro(SeedPoint2, double);
  ///@}

  ///@{
  /** Segments of the seed line (its seeds: one more). Default 20, in [1, 100000]. */
  vtkSetClampMacro(SeedResolution, int, 1, 100000);
  vtkGetMacro(SeedResolution, int);
  ///@}

  enum SeedTypes
  {
    SEED_LINE = 0, ///< seeds along SeedPoint1-SeedPoint2
    SEED_PLANE     ///< a lattice on the parallelogram SeedPoint1, SeedPoint2, SeedPoint3
  };

  ///@{
  /**
   * Where the built-in seeds lie (SeedTypes; without `seeds` on port 1).
   * SEED_PLANE: a (SeedResolution + 1) x (SeedResolution2 + 1) lattice on the
   * parallelogram with corner SeedPoint1 and sides to SeedPoint2 and
   * SeedPoint3 (streamlines and ribbons; a stream surface needs a line).
   * Default SEED_LINE.
   */
  vtkSetClampMacro(SeedType, int, SEED_LINE, SEED_PLANE);
  vtkGetMacro(SeedType, int);
  ///@}

  ///@{
  /** Plane seeds: end of the second side from SeedPoint1. Default (0.5, 0.1, 0.9) (relative coordinates). */
  vtkSetVector3Macro(SeedPoint3, double);
  vtkGetVector3Macro(SeedPoint3, double);
  ///@}

  ///@{
  /** Plane seeds: segments along the second side. Default 10, in [1, 100000]. */
  vtkSetClampMacro(SeedResolution2, int, 1, 100000);
  vtkGetMacro(SeedResolution2, int);
  ///@}

  ///@{
  /** Integration direction (Directions). Default BOTH. */
  vtkSetClampMacro(IntegrationDirection, int, FORWARD, BOTH);
  vtkGetMacro(IntegrationDirection, int);
  ///@}

  ///@{
  /** Longest streamline, model units; 0 = the diagonal of the input's bounds. Default 0. */
  vtkSetClampMacro(MaximumLength, double, 0.0, 1e30);
  vtkGetMacro(MaximumLength, double);
  ///@}

  ///@{
  /** Integration step, in cell lengths. Default 0.25, in [0.001, 100]. */
  vtkSetClampMacro(StepLength, double, 0.001, 100.0);
  vtkGetMacro(StepLength, double);
  ///@}

  ///@{
  /** Streamlines stop below this speed. Default 1e-12. */
  vtkSetClampMacro(TerminalSpeed, double, 0.0, 1e30);
  vtkGetMacro(TerminalSpeed, double);
  ///@}

  ///@{
  /** Full width of ribbons, model units; 0 = 1 % of the diagonal of the input's bounds. Default 0. */
  vtkSetClampMacro(RibbonWidth, double, 0.0, 1e30);
  vtkGetMacro(RibbonWidth, double);
  ///@}

  ///@{
  /**
   * vtkStreamSurface's iterative seeding (adds seeds where the surface spreads; slower). Its work grows
   * with steps^2 and its front may double every step: seeds x steps^2 is checked against the work
   * budget before tracing, and tracing stops with an error once the next step would pass the memory
   * or work budget. Default false.
   */
  vtkSetMacro(IterativeSeeding, bool);
  vtkGetMacro(IterativeSeeding, bool);
  ///@}

  ///@{
  /** Clip: keep the other half (against the normal). Default false. */
  vtkSetMacro(InsideOut, bool);
  vtkGetMacro(InsideOut, bool);
  ///@}

  ///@{
  /**
   * Contour iso values, or threshold [lower, upper] (one value: lower only).
   * None (the default): the median of the array's valid values.
   */
  VTK_WRAPEXCLUDE void SetValues(const std::vector<double>& values);
  VTK_WRAPEXCLUDE const std::vector<double>& GetValues() const { return this->Values; }
  ///@}

  /** Values used by the last update (the median when none were given). */
  VTK_WRAPEXCLUDE const std::vector<double>& GetUsedValues() const { return this->UsedValues; }
  /** Name of the array the last update used (scalars or vectors), as the data names it. */
  VTK_WRAPEXCLUDE const std::string& GetUsedArrayName() const { return this->UsedArrayName; }

  /** Whether the array the last update used was cell data (threshold of a cell array). */
  bool GetUsedCellData() const { return this->UsedCellData; }

  /** Why the last update failed ("" after a successful one); names the scene key and its value. */
  VTK_WRAPEXCLUDE const std::string& GetLastError() const { return this->LastError; }

  /** Median of the valid values (finite, not masked; -1 component: magnitude) of `array`. */
  static double Median(vtkDataArray* array, vtkDataArray* mask = nullptr);

  /**
   * "" if contouring `cells` cells at `values` iso values (each cell visited
   * once per value) fits the work budget, else "the contour of N cells at M
   * values needs about ... operations, over the work budget of ...
   * (PLUME_WORK_BUDGET)". Also used by `plume`'s contour representation.
   */
  VTK_WRAPEXCLUDE static std::string CheckContourWork(vtkIdType cells, size_t values);

protected:
  vtkPlumeDerivedGeometry();
  ~vtkPlumeDerivedGeometry() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Operation = CONTOUR;
  char* ArrayName = nullptr;
  char* VectorArrayName = nullptr;
  int Coordinates = RELATIVE;
  double Origin[3] = { 0.5, 0.5, 0.5 };
  double Normal[3] = { 1, 0, 0 };
  double SeedPoint1[3] = { 0.5, 0.1, 0.5 };
  double SeedPoint2[3] = { 0.5, 0.9, 0.5 };
  int SeedResolution = 20;
  int SeedType = SEED_LINE;
  double SeedPoint3[3] = { 0.5, 0.1, 0.9 };
  int SeedResolution2 = 10;
  int IntegrationDirection = BOTH;
  double MaximumLength = 0;
  double StepLength = 0.25;
  double TerminalSpeed = 1e-12;
  double RibbonWidth = 0;
  bool IterativeSeeding = false;
  bool InsideOut = false;
  std::vector<double> Values;

private:
  vtkPlumeDerivedGeometry(const vtkPlumeDerivedGeometry&) = delete;
  void operator=(const vtkPlumeDerivedGeometry&) = delete;

  bool Derive(vtkDataSet* input, vtkDataSet* seeds, vtkDataObject* output);

  std::vector<double> UsedValues;
  std::string UsedArrayName;
  bool UsedCellData = false;
  std::string LastError;
  // The output size Derive predicted before running the filter, for the
  // post-filter budget message ("" when it could not predict one).
  std::string Estimate;
};

#endif
