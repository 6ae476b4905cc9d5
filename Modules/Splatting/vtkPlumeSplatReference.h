/**
 * @class   vtkPlumeSplatReference
 * @brief   the yardstick for vtkPlumeGaussianSplatter: exact sums in double precision, no cutoff
 *
 * Evaluates, at every grid point (or at one), the sum over *all* splats of
 * the exact splat function, in double precision, with no cutoff and no
 * culling: a slow O(voxels × splats) loop. It reads the inputs itself and
 * shares no code with the splatter's backends (only the documented
 * definitions): VECTOR_SUM / SCALAR_SUM give v·G_σ averaged over the voxel
 * (product of erf differences; IntegrateOverVoxel) or sampled at the voxel
 * centre; DISTANCE_MAX gives max(0, max over splats of s·(1 − r/R)).
 * Splats with non-finite data or a radius ≤ 0 are skipped, as by the splatter.
 */
#ifndef vtkPlumeSplatReference_h
#define vtkPlumeSplatReference_h

#include "PlumeSplattingModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For the returned image

#include <memory> // For std::unique_ptr

class vtkImageData;
class vtkPlumeGaussianSplatter;
class vtkPointSet;
class vtkPolyData;

class PLUMESPLATTING_EXPORT vtkPlumeSplatReference : public vtkObject
{
public:
  static vtkPlumeSplatReference* New();
  vtkTypeMacro(vtkPlumeSplatReference, vtkObject);

  /**
   * Take the splatter's settings and its inputs (port 0 points, port 1 lines,
   * as currently connected and updated) and the grid of its last output.
   * Call after splatter->Update().
   */
  void Configure(vtkPlumeGaussianSplatter* splatter);

  /** Number of splats found (after skipping non-finite ones). */
  size_t GetNumberOfSplats() const;

  /** The value at grid point (i, j, k): 3 components (VECTOR_SUM) or 1. */
  void Evaluate(int i, int j, int k, double value[3]) const;

  /** The whole grid (double array with the splatter's array name); slow. */
  vtkSmartPointer<vtkImageData> Compute() const;

protected:
  vtkPlumeSplatReference();
  ~vtkPlumeSplatReference() override;

private:
  vtkPlumeSplatReference(const vtkPlumeSplatReference&) = delete;
  void operator=(const vtkPlumeSplatReference&) = delete;

  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
