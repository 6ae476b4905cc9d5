/**
 * @class   vtkPlumeVolumeReference
 * @brief   CPU reference raycaster for vtkPlumeVolumeMapper, in double precision
 *
 * Computes, for every pixel of a Width x Height image seen through the
 * renderer's active camera, what vtkPlumeVolumeMapper's model says the volume
 * contributes, with none of the mapper's code: exact trilinear interpolation
 * of the scalars (clamped to the grid), transfer functions evaluated in double
 * (tabulated with 65536 entries over the data range), rays unprojected from
 * pixel centres in double (nearest node instead when the property's
 * interpolation type is nearest), fine midpoint steps (Step voxels, default 1/8;
 * finer than the mapper's default 1/2), no jitter, no early termination.
 *
 * The model (documented in vtkPlumeVolumeMapper.h): extinction
 * σ(s) = -ln(1 - min(α(s), 1 - 1e-6)) / u (u = scalar opacity unit distance),
 * composite = ∫ c σ T dt (c Phong-lit at each sample when the property's
 * Shade is on); MIP = (c α, α) at the ray's maximum; isosurface =
 * first crossing of the iso value, refined by bisection to double precision,
 * central-difference normal (one voxel) and Phong lighting; smoke =
 * ∫ c (ka + kd Σ I_l T_l) σ T dt with T_l the transmittance towards light l
 * (ShadowStep voxels). NaN scalars count as the finite minimum, ±Inf as the
 * finite ends; a one-node axis is a slab one spacing thick. With a valid-point
 * mask (ValidMaskArrayName), values are interpolated over the valid nodes
 * only, extinction is scaled by their total trilinear weight w, and MIP and
 * isosurface use only samples with w > 0; the range covers valid nodes.
 *
 * Optionally the rays stop at an opaque depth image (window depth 0..1 per
 * pixel, as read back from the scene without the volume).
 *
 * Output: premultiplied RGBA floats, bottom row first (like
 * plume::test::ReadBack); CompositeOver() puts it over a background image.
 */
#ifndef vtkPlumeVolumeReference_h
#define vtkPlumeVolumeReference_h

#include "PlumeVolumeModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For members

#include <string> // For std::string
#include <vector> // For std::vector

class vtkImageData;
class vtkRenderer;
class vtkVolume;

class PLUMEVOLUME_EXPORT vtkPlumeVolumeReference : public vtkObject
{
public:
  static vtkPlumeVolumeReference* New();
  vtkTypeMacro(vtkPlumeVolumeReference, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    COMPOSITE = 0,
    MAXIMUM_INTENSITY = 1,
    ISOSURFACE = 2,
    SMOKE = 3
  };

  /** The image (point scalars). */
  void SetInputData(vtkImageData* image);
  /** Point array to use; empty (default) = the active scalars. */
  void SetArrayName(const std::string& name) { this->ArrayName = name; }
  /** Component; -1 (default) = the only component or the magnitude. */
  void SetScalarComponent(int c) { this->ScalarComponent = c; }
  /** Point array whose zeros mark nodes outside the data (as the mapper's); default "vtkValidPointMask", "" = none. */
  void SetValidMaskArrayName(const std::string& name) { this->ValidMaskArrayName = name; }
  /** The volume: its property (transfer functions, lighting) and transform. */
  void SetVolume(vtkVolume* volume);
  /** The renderer: active camera and lights. */
  void SetRenderer(vtkRenderer* renderer);
  /** COMPOSITE (default), MAXIMUM_INTENSITY, ISOSURFACE or SMOKE. */
  void SetMode(int mode) { this->Mode = mode; }
  /** Iso value (data units); NaN (default) = the property's first iso value, else mid-range. */
  void SetIsoValue(double v) { this->IsoValue = v; }
  /** Primary step in voxels. Default 0.125. */
  void SetStep(double step) { this->Step = step; }
  /** Shadow-ray step in voxels (SMOKE). Default 0.25. */
  void SetShadowStep(double step) { this->ShadowStep = step; }
  /**
   * Compute only the pixels (x, y) with x and y multiples of this (the others
   * stay 0), for spot checks of large volumes. Default 1 (every pixel).
   */
  void SetPixelStride(int stride) { this->PixelStride = stride > 1 ? stride : 1; }
  int GetPixelStride() const { return this->PixelStride; }
  /** Window depth (0..1) per pixel, bottom row first; empty (default) = nothing opaque. */
  void SetOpaqueDepth(const std::vector<float>& depth) { this->OpaqueDepth = depth; }

  /** Compute the Width x Height image. Returns false (see GetLastError) on bad input. */
  bool Compute(int width, int height);

  /** Premultiplied RGBA, Width*Height*4, bottom row first. */
  const std::vector<float>& GetImage() const { return this->Image; }

  /** rgb = volume + (1 - volume alpha) * background rgb; alpha = 1 - (1-a_v)(1-a_b). */
  std::vector<float> CompositeOver(const std::vector<float>& background) const;

  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkPlumeVolumeReference();
  ~vtkPlumeVolumeReference() override;

  vtkSmartPointer<vtkImageData> Input;
  vtkSmartPointer<vtkVolume> Volume;
  vtkSmartPointer<vtkRenderer> Renderer;
  std::string ArrayName;
  int ScalarComponent = -1;
  std::string ValidMaskArrayName = "vtkValidPointMask";
  int Mode = COMPOSITE;
  double IsoValue;
  double Step = 0.125;
  double ShadowStep = 0.25;
  int PixelStride = 1;
  std::vector<float> OpaqueDepth;
  std::vector<float> Image;
  std::string LastError;

private:
  vtkPlumeVolumeReference(const vtkPlumeVolumeReference&) = delete;
  void operator=(const vtkPlumeVolumeReference&) = delete;
};

#endif
