/**
 * @class   vtkPlumeSheetDensityGrid
 * @brief   the smoke of a sheet mesh sampled on a regular grid (vtkPlumeSheetMapper's grid mode)
 *
 * Computes, at the nodes of a vtkImageData, the sheet's smoke density
 *   density(x) = sum over triangles of the integral over the triangle of
 *                d(p) G(x - p) dA(p)
 * with the model of vtkPlumeSheetMapper (G the unit-mass anisotropic Gaussian
 * of the triangle's frame, d, sigma_b, sigma_t interpolated barycentrically).
 * The field does not depend on the view, so it is computed once per mesh or
 * parameter change and raycast every frame.
 *
 * The triangle integral is a quadrature, not a vertex splat: each triangle is
 * cut by longest-edge bisection into pieces no wider than SubTriangleSize x
 * its smallest sigma_b (slivers are cut along their length only), and each
 * piece contributes its three edge midpoints (degree-2 rule) as Gaussians with
 * the interpolated d and sigmas. Triangles no wider than SmallTriangleSize x
 * sigma_b are one Gaussian at their mass centroid, widened by their own
 * second moment. The points in each cubic cell of MergeCellSize grid spacings
 * are then merged into one Gaussian (total mass, mass centroid, total second
 * moment: a general anisotropic covariance), so the splat costs one Gaussian
 * per occupied cell however fine the mesh; the points are not stored, each
 * block of triangles sums their moments per cell as it makes them. Each
 * Gaussian is evaluated exactly at every node inside its sqrt(2) x Cutoff
 * ellipsoid without an exp per node or row (the value and its factors to
 * the next node in x and y advance by multiplications; two exps per plane).
 *
 * Spacing: the smallest sigma of the mesh (sigma_b, and sigma_t unless thin)
 * divided by SamplesPerSigma, isotropic; the grid covers the mesh padded by
 * Cutoff x the largest sigma. If that needs more than MaximumNodes nodes the
 * spacing grows until it fits. Sigmas below SamplesPerSigma x the spacing
 * (thin sheets, tiny or capped sigmas) are raised to it, so every Gaussian is
 * resolved by the grid (GetSigmaFloor()).
 *
 * Bad values: as the mapper (non-finite or negative densities and sigmas count
 * as zero, triangles with a non-finite corner or zero area are skipped).
 * Threads: vtkSMPTools over fixed blocks of triangles (each block sums its
 * points per merge cell in point order; the blocks' sums of a cell are added
 * in block order; unmerged points are joined in block order) and z-slabs
 * (each thread owns its planes): the result does not depend on the thread
 * count. Memory: merged, about 210 bytes per (block, occupied cell) pair and
 * 120 per merged Gaussian (the points are not stored); unmerged, 64 bytes
 * per quadrature point; plus the grid (4 bytes per node, written in place).
 */
#ifndef vtkPlumeSheetDensityGrid_h
#define vtkPlumeSheetDensityGrid_h

#include "PlumeSheetsModule.h" // For export macro
#include "vtkObject.h"
#include "vtkImageData.h"    // For vtkSmartPointer<vtkImageData>
#include "vtkPolyData.h"     // For vtkSmartPointer<vtkPolyData>
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <string> // For std::string


class PLUMESHEETS_EXPORT vtkPlumeSheetDensityGrid : public vtkObject
{
public:
  static vtkPlumeSheetDensityGrid* New();
  vtkTypeMacro(vtkPlumeSheetDensityGrid, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The sheet mesh (model coordinates). */
  void SetInputData(vtkPolyData* mesh);

  ///@{
  /** Same meaning and defaults as vtkPlumeSheetMapper's. */
  vtkSetStdStringFromCharMacro(DensityArrayName);
  vtkSetMacro(Density, double);
  vtkSetMacro(DensityScale, double);
  vtkSetStdStringFromCharMacro(BlurArrayName);
  vtkSetMacro(BlurRadius, double);
  vtkSetStdStringFromCharMacro(ThicknessArrayName);
  vtkSetMacro(Thickness, double);
  vtkSetMacro(ThinSheet, bool);
  vtkSetMacro(Cutoff, double);
  ///@}

  ///@{
  /** Grid nodes per smallest sigma. Default 2. Clamped to 0.25..16. */
  vtkSetClampMacro(SamplesPerSigma, double, 0.25, 16.0);
  vtkGetMacro(SamplesPerSigma, double);
  ///@}

  ///@{
  /** Largest number of grid nodes (4 bytes each). Default 2^25 (128 MB). */
  vtkSetClampMacro(MaximumNodes, double, 8.0, 1e12);
  vtkGetMacro(MaximumNodes, double);
  ///@}

  ///@{
  /** Largest sub-triangle of the quadrature, in units of the triangle's smallest sigma_b. Default 1. */
  vtkSetClampMacro(SubTriangleSize, double, 0.05, 10.0);
  vtkGetMacro(SubTriangleSize, double);
  ///@}

  ///@{
  /**
   * Triangles whose longest edge is at most this times their smallest sigma_b
   * are one Gaussian at their mass centroid, their own spread added to its
   * in-plane variance (mass, centroid and isotropic second moment kept).
   * Default 0.5. 0: every triangle takes the three-point rule. Clamped to 0..2.
   */
  vtkSetClampMacro(SmallTriangleSize, double, 0.0, 2.0);
  vtkGetMacro(SmallTriangleSize, double);
  ///@}

  ///@{
  /**
   * Merge the quadrature points of each cubic cell of this many grid spacings
   * into one Gaussian (their mass, mass centroid and total second moment:
   * each point's covariance plus their spread) before splatting. 0: every
   * point is splatted exactly. Default 2. Clamped to 0..4.
   */
  vtkSetClampMacro(MergeCellSize, double, 0.0, 4.0);
  vtkGetMacro(MergeCellSize, double);
  ///@}

  /**
   * Compute the grid. Returns false (with an error, also in GetLastError()) if
   * the input is unusable or its quadrature would exceed the memory budget or
   * the work budget (vtkPlumeInputValidation: PLUME_MEMORY_BUDGET_MB,
   * PLUME_WORK_BUDGET): the message names the triangle count, the estimate and
   * the budget.
   */
  bool Compute();

  /**
   * The budget check of Compute() alone (the triangles are collected, nothing
   * is splatted): "" if Compute() would fit the budgets, else its message.
   */
  std::string CheckBudget();

  /** The reason the last Compute() failed on a budget, "" otherwise. */
  const std::string& GetLastError() const { return this->LastError; }

  /** The grid: point array "density" (float, optical depth per unit length, model units). */
  vtkImageData* GetOutput() { return this->Output; }

  /** Sigmas below this were raised to it (SamplesPerSigma x the spacing). */
  vtkGetMacro(SigmaFloor, double);
  /** Quadrature points splatted by the last Compute. */
  vtkGetMacro(PointCount, vtkIdType);
  /** Gaussians splatted by the last Compute (PointCount without merging). */
  vtkGetMacro(GaussianCount, vtkIdType);
  /** Seconds the last Compute took, and its parts: the quadrature points, their merging, the splat. */
  vtkGetMacro(ComputeSeconds, double);
  vtkGetMacro(QuadratureSeconds, double);
  vtkGetMacro(MergeSeconds, double);
  vtkGetMacro(SplatSeconds, double);

protected:
  vtkPlumeSheetDensityGrid();
  ~vtkPlumeSheetDensityGrid() override;

  bool Run(bool budgetOnly);

  vtkSmartPointer<vtkPolyData> Mesh;
  vtkSmartPointer<vtkImageData> Output;
  std::string DensityArrayName;
  std::string BlurArrayName;
  std::string ThicknessArrayName;
  double Density = 1.0;
  double DensityScale = 1.0;
  double BlurRadius = 0.05;
  double Thickness = 0.05;
  bool ThinSheet = false;
  double Cutoff = 3.5;
  double SamplesPerSigma = 2.0;
  double MaximumNodes = 33554432.0;
  std::string LastError;
  double SubTriangleSize = 1.0;
  double SmallTriangleSize = 0.5;
  double SigmaFloor = 0.0;
  vtkIdType PointCount = 0;
  double MergeCellSize = 2.0;
  vtkIdType GaussianCount = 0;
  double ComputeSeconds = 0.0;
  double QuadratureSeconds = 0.0;
  double MergeSeconds = 0.0;
  double SplatSeconds = 0.0;

private:
  vtkPlumeSheetDensityGrid(const vtkPlumeSheetDensityGrid&) = delete;
  void operator=(const vtkPlumeSheetDensityGrid&) = delete;
};

#endif
