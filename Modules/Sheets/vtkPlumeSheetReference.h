/**
 * @class   vtkPlumeSheetReference
 * @brief   double-precision CPU reference for vtkPlumeSheetMapper: transmittance per pixel
 *
 * Computes, for each pixel of a renderer's viewport, the optical depth
 *   tau_c = integral along the exact view ray of density_c(x) dt,
 *   density_c(x) = sum over triangles of the integral over the triangle of
 *                  d(p) absorption_c(p) G(x - p) dA(p),
 * G the unit-mass anisotropic Gaussian of the triangle's frame (sigma_b in the
 * plane, sigma_t along the normal; sigma_t = 0 is a surface layer), with d,
 * sigma_b, sigma_t, absorption interpolated barycentrically, and returns
 * T_c = exp(-tau_c). It shares no code with the shader path: the view rays
 * come from the camera's composite projection (inverted in double), the
 * Gaussian is integrated *numerically* along the ray (adaptive Gauss-Kronrod
 * 7/15 with break points at the plane crossing), and the triangle integral by
 * adaptive subdivision with a degree-5 7-point rule; Gaussians are not cut
 * off (parts farther than 6 standard deviations from the ray are skipped), so the mapper's Cutoff error
 * counts against it. The ray runs from the near plane to the opaque depth
 * given (BoundedByDepth on, the default) or over the whole line.
 *
 * The model's conventions are re-implemented here, from the mapper's
 * documentation: per-corner lower bound of MinimumSigmaPixels pixels on both
 * sigmas (the pixel size measured by unprojecting a one-pixel offset at the
 * corner's depth); densities/sigmas that are NaN, Inf or negative count as
 * zero; triangles with a non-finite corner are skipped. The mesh is in model
 * coordinates, placed in the world by ModelMatrix (the actor's matrix) as the
 * mapper does.
 *
 * Cost: a few seconds for 64x64 pixels of a few thousand overlapping
 * triangles on 2 threads (vtkSMPTools); PixelStride computes a sparse subset.
 */
#ifndef vtkPlumeSheetReference_h
#define vtkPlumeSheetReference_h

#include "PlumeSheetsModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <string> // For std::string
#include <vector> // For std::vector

class vtkMatrix4x4;
class vtkPolyData;
class vtkRenderer;

class PLUMESHEETS_EXPORT vtkPlumeSheetReference : public vtkObject
{
public:
  static vtkPlumeSheetReference* New();
  vtkTypeMacro(vtkPlumeSheetReference, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The sheet mesh (polygons fanned, strips; world coordinates). */
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
  vtkSetStdStringFromCharMacro(AbsorptionArrayName);
  vtkSetMacro(ThinSheet, bool);
  vtkSetMacro(BoundedByDepth, bool);
  vtkSetMacro(MinimumSigmaPixels, double);
  ///@}

  ///@{
  /**
   * Model-to-world matrix of the actor that draws the mesh (vtkProp3D::GetMatrix()),
   * copied; nullptr restores the default, identity. As in vtkPlumeSheetMapper,
   * positions are transformed by it, sigma_b and sigma_t (model lengths) are
   * multiplied by its length scale cbrt(|det|) (exact for uniform scales), and
   * densities stay per unit of world area.
   */
  void SetModelMatrix(vtkMatrix4x4* matrix);
  const double* GetModelMatrix() const { return this->ModelMatrix; }
  ///@}

  ///@{
  /** Absolute tolerance on each pixel's optical depth. Default 1e-4 (a 20th of an 8-bit step). */
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /** Compute only pixels whose x and y are multiples of PixelStride (others are NaN). Default 1. */
  vtkSetClampMacro(PixelStride, int, 1, 1024);
  vtkGetMacro(PixelStride, int);
  /**
   * With PixelStride: compute the pixels whose x and y are this plus a
   * multiple of PixelStride instead (e.g. off the rays of a renderer's ray
   * lattice, whose rays go through multiples of its spacing). Default 0.
   * Clamped to 0..1023 (taken modulo PixelStride).
   */
  vtkSetClampMacro(PixelOffset, int, 0, 1023);
  vtkGetMacro(PixelOffset, int);
  ///@}

  /**
   * Compute the transmittance for the renderer's camera and viewport size.
   * `depth`: the opaque window depth (0..1) of the viewport, bottom row first,
   * width*height values, or nullptr for no opaque geometry. Returns false
   * (with an error) if the input or the camera is unusable.
   */
  bool Compute(vtkRenderer* renderer, const float* depth);

  int GetWidth() const { return this->Width; }
  int GetHeight() const { return this->Height; }
  /** RGB transmittance, width*height*3, bottom row first (NaN where not computed). */
  const std::vector<double>& GetTransmittance() const { return this->Transmittance; }

protected:
  vtkPlumeSheetReference();
  ~vtkPlumeSheetReference() override;

  vtkSmartPointer<vtkPolyData> Mesh;
  std::string DensityArrayName;
  std::string BlurArrayName;
  std::string ThicknessArrayName;
  std::string AbsorptionArrayName;
  double Density = 1.0;
  double DensityScale = 1.0;
  double BlurRadius = 0.05;
  double Thickness = 0.05;
  bool ThinSheet = false;
  bool BoundedByDepth = true;
  double MinimumSigmaPixels = 1.0 / 3.0;
  double Tolerance = 1e-4;
  double ModelMatrix[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  int PixelStride = 1;
  int PixelOffset = 0;
  int Width = 0;
  int Height = 0;
  std::vector<double> Transmittance;

private:
  vtkPlumeSheetReference(const vtkPlumeSheetReference&) = delete;
  void operator=(const vtkPlumeSheetReference&) = delete;
};

#endif
