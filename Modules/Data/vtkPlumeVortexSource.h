/**
 * @class   vtkPlumeVortexSource
 * @brief   analytic Lamb–Oseen vortex sampled onto a vtkImageData
 *
 * Produces a uniform grid carrying a 3-component point array "velocity" (set
 * as the active vectors) and a scalar "speed" (|velocity|). The field is a
 * Lamb–Oseen vortex around an axis through Center along z, with an axial jet
 * in the core and a uniform drift, so images of it are not mirror-symmetric:
 *
 *   r      = distance of the point from the axis (in the x-y plane)
 *   v_θ(r) = Γ / (2π r) · (1 − exp(−r²/rc²))       (tangential, counter-clockwise about +z)
 *   w(r)   = W · exp(−r²/rc²)                        (along +z)
 *   v      = v_θ e_θ + w e_z + Drift
 *
 * The closed form is available through Evaluate() so tests and benchmarks can
 * compare rendered results with the exact field in double precision.
 */
#ifndef vtkPlumeVortexSource_h
#define vtkPlumeVortexSource_h

#include "PlumeDataModule.h" // For export macro
#include "vtkImageAlgorithm.h"

class PLUMEDATA_EXPORT vtkPlumeVortexSource : public vtkImageAlgorithm
{
public:
  static vtkPlumeVortexSource* New();
  vtkTypeMacro(vtkPlumeVortexSource, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Number of grid points along x, y, z. Default (32, 32, 32); each at least 1. */
  vtkSetVector3Macro(Dimensions, int);
  vtkGetVector3Macro(Dimensions, int);
  ///@}

  ///@{
  /** Physical bounds (xmin, xmax, ymin, ymax, zmin, zmax). Default [-1, 1]³. */
  vtkSetVector6Macro(Bounds, double);
  vtkGetVector6Macro(Bounds, double);
  ///@}

  ///@{
  /** Point on the vortex axis (the axis is parallel to z). Default (0, 0, 0). */
  vtkSetVector3Macro(Center, double);
  vtkGetVector3Macro(Center, double);
  ///@}

  ///@{
  /** Circulation Γ. Default 2 (peak tangential speed ≈ 0.48 at r ≈ 1.12 rc for rc = 0.4). */
  vtkSetMacro(Circulation, double);
  vtkGetMacro(Circulation, double);
  ///@}

  ///@{
  /** Core radius rc (> 0). Default 0.4. */
  vtkSetMacro(CoreRadius, double);
  vtkGetMacro(CoreRadius, double);
  ///@}

  ///@{
  /** Axial jet speed W on the axis. Default 0.3. */
  vtkSetMacro(AxialVelocity, double);
  vtkGetMacro(AxialVelocity, double);
  ///@}

  ///@{
  /** Uniform drift added everywhere. Default (0.1, 0, 0). */
  vtkSetVector3Macro(Drift, double);
  vtkGetVector3Macro(Drift, double);
  ///@}

  /** The exact velocity at world point x, in double precision. */
  void Evaluate(const double x[3], double v[3]) const;

protected:
  vtkPlumeVortexSource();
  ~vtkPlumeVortexSource() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  void ExecuteDataWithInformation(vtkDataObject* output, vtkInformation* outInfo) override;

  int Dimensions[3] = { 32, 32, 32 };
  double Bounds[6] = { -1, 1, -1, 1, -1, 1 };
  double Center[3] = { 0, 0, 0 };
  double Circulation = 2.0;
  double CoreRadius = 0.4;
  double AxialVelocity = 0.3;
  double Drift[3] = { 0.1, 0, 0 };

private:
  vtkPlumeVortexSource(const vtkPlumeVortexSource&) = delete;
  void operator=(const vtkPlumeVortexSource&) = delete;
};

#endif
