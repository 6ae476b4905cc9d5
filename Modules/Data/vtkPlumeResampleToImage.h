/**
 * @class   vtkPlumeResampleToImage
 * @brief   resamples any dataset (including composites) onto a uniform vtkImageData
 *
 * - A vtkImageData input with no explicit SamplingDimensions passes through (shallow copy).
 * - Anything else is resampled with VTK's vtkResampleToImage over the input bounds. The
 *   sampling dimensions are SamplingDimensions when all three are >= 1, otherwise automatic:
 *   the longest axis of the bounds gets MaximumDimension points, the others proportionally
 *   fewer (at least 2), and an axis along which the input is flat gets 1.
 * - Cell arrays of the input are first converted to point arrays (vtkCellDataToPointData) so
 *   cell-centred datasets (CGNS, OpenFOAM) resample with their arrays; a cell array whose
 *   name is already a point array is dropped in favour of the point array.
 * - The output keeps the valid-point mask `vtkValidPointMask` (unsigned char, 1 inside the
 *   source domain) and every other point array is 0 where the mask is 0. (vtkResampleToImage
 *   also adds the `vtkGhostType` blanking arrays; they are kept as they are.)
 * - A flat axis has spacing 1 in the output so the image stays valid.
 *
 * The input is brought up to date during RequestInformation so the whole extent announced
 * downstream is the real one.
 */
#ifndef vtkPlumeResampleToImage_h
#define vtkPlumeResampleToImage_h

#include "PlumeDataModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include <string> // For std::string

class PLUMEDATA_EXPORT vtkPlumeResampleToImage : public vtkImageAlgorithm
{
public:
  static vtkPlumeResampleToImage* New();
  vtkTypeMacro(vtkPlumeResampleToImage, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Explicit number of samples along x, y, z. Default (0, 0, 0) = automatic (from
   * MaximumDimension). Used only when all three are >= 1; then an image input is resampled too.
   */
  vtkSetVector3Macro(SamplingDimensions, int);
  vtkGetVector3Macro(SamplingDimensions, int);
  ///@}

  ///@{
  /**
   * Number of samples along the longest axis in automatic mode. Default 64; at least 2.
   */
  vtkSetClampMacro(MaximumDimension, int, 2, VTK_INT_MAX);
  vtkGetMacro(MaximumDimension, int);
  ///@}

  /** Name of the valid-point mask array in the output ("vtkValidPointMask"). */
  static const char* GetMaskArrayName() { return "vtkValidPointMask"; }

  /**
   * The dimensions automatic mode chooses for `bounds` and `maximumDimension` (exposed for
   * tests and tools).
   */
  static void ComputeAutomaticDimensions(
    const double bounds[6], int maximumDimension, int dimensions[3]);

  /**
   * Set every point array of `image` (except the mask and vtkGhostType) to 0 where the
   * point array named GetMaskArrayName() is 0 (done by RequestData; exposed for tests).
   */
  static void ZeroOutsideMask(vtkImageData* image);

  /**
   * Why the last update produced no image ("" after a successful one): an input whose cells
   * reference points that do not exist or whose arrays are shorter than it, or sampling
   * dimensions over the memory budget (vtkPlumeInputValidation). Such inputs are never read.
   */
  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkPlumeResampleToImage();
  ~vtkPlumeResampleToImage() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int SamplingDimensions[3] = { 0, 0, 0 };
  int MaximumDimension = 64;

private:
  vtkPlumeResampleToImage(const vtkPlumeResampleToImage&) = delete;
  void operator=(const vtkPlumeResampleToImage&) = delete;

  bool ExplicitDimensions() const;
  // Geometry decided in RequestInformation, used in RequestData.
  bool PassThrough = false;
  int Dimensions[3] = { 1, 1, 1 };
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
  std::string LastError;
};

#endif
