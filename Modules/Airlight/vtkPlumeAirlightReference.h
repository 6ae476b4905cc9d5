/**
 * @class   vtkPlumeAirlightReference
 * @brief   double-precision CPU reference for vtkPlumeAirlightPass: the single-scattering integral integrated adaptively along each view ray
 *
 * Shares no code with the pass's shader or table: for each ray and light it
 * integrates, per RGB channel,
 *   L = integral_0^ds  ks/(4 pi) * I0 * w(x) / d(x)^2 * exp(-kt (x + d(x))) dx
 * with adaptive Simpson quadrature (relative tolerance RelativeTolerance),
 * split at the light's foot point and at +-h, +-4h, +-16h around it (the peak's
 * width), at the spot cone's boundaries (found by sampling the inside test
 * and bisection, not by solving the cone's quadratic), and over [X, inf) by
 * the map x = X + s/(1-s) when the ray hits nothing. The lights follow the
 * pass's documented rules (positional, switched on, I0 = Intensity *
 * DiffuseColor * IntensityScale, divided by c2 for purely quadratic
 * attenuation, VTK's spot cone and exponent, a spot light's projected
 * image: vtkPlumeAirlightPass::LIGHT_TEXTURE), but are read in world
 * coordinates. A textured light's image is evaluated at every point of the
 * integral (the documented projection and bilinear rule, in double, written
 * here anew), so the reference has no sub-intervals.
 *
 * ComputeImage composes a whole frame the way the pass does:
 * C_surface * exp(-kt ds) + airlight, from a read-back of the scene rendered
 * without the pass (its colour and depth), unprojected in double precision
 * with the camera's matrices.
 */
#ifndef vtkPlumeAirlightReference_h
#define vtkPlumeAirlightReference_h

#include "PlumeAirlightModule.h" // For export macro
#include "vtkObject.h"

#include <array>  // For std::array
#include <memory> // For std::shared_ptr
#include <vector> // For std::vector

class vtkRenderer;

class PLUMEAIRLIGHT_EXPORT vtkPlumeAirlightReference : public vtkObject
{
public:
  static vtkPlumeAirlightReference* New();
  vtkTypeMacro(vtkPlumeAirlightReference, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Medium, as in vtkPlumeAirlightPass. Defaults (0, 0, 0), (0, 0, 0), 1. */
  vtkSetVector3Macro(Scattering, double);
  vtkGetVector3Macro(Scattering, double);
  vtkSetVector3Macro(Absorption, double);
  vtkGetVector3Macro(Absorption, double);
  vtkSetMacro(IntensityScale, double);
  vtkGetMacro(IntensityScale, double);
  ///@}

  ///@{
  /**
   * Henyey-Greenstein asymmetry g of the phase function, evaluated directly
   * at each point: p = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos a)^1.5), cos a =
   * the cosine between the light's travel direction (light -> point) and the
   * direction back to the eye. Default 0 (isotropic, 1/(4 pi)).
   */
  vtkSetMacro(ScatteringAnisotropy, double);
  vtkGetMacro(ScatteringAnisotropy, double);
  ///@}

  ///@{
  /** Relative tolerance of the adaptive quadrature. Default 1e-9. */
  vtkSetMacro(RelativeTolerance, double);
  vtkGetMacro(RelativeTolerance, double);
  ///@}

  /** Takes the renderer's switched-on positional lights (call after a render, so head/camera lights are placed). */
  void SetLights(vtkRenderer* renderer);

  /**
   * Takes the renderer's visible opaque actors' polygons (in world
   * coordinates, after a render) as occluders: spot and point lights are
   * then shadowed by exact ray casts (segment against every triangle, in
   * double, through a bounding-volume hierarchy) from the light to each
   * point of the view ray (shadow boundaries found by 256 samples per piece
   * and bisection). Call before SetLights. Without it (default) nothing
   * casts shadows.
   */
  void SetOccluders(vtkRenderer* renderer);

  /**
   * Adds an axis-aligned box of smoke (world bounds xmin, xmax, ymin, ymax,
   * zmin, zmax) of uniform grey extinction `extinction` (1/length) that emits
   * colour * extinction per unit length (unshaded emission-absorption: a
   * volume of colour c and opacity 1 - exp(-extinction L) over a chord L).
   * Along each view ray (ComputeRay, ComputeImage) the haze's in-scattering,
   * the smoke's emission and the surface are multiplied by the smoke's
   * transmittance from the eye, exp(-integral of the extinction), and the
   * emission by the haze's exp(-kt x) too; the integral is split at the
   * boxes' entries and exits. The smoke does not shadow the lights. Boxes
   * add up where they overlap. Default: no smoke.
   */
  void AddSmokeBox(const double bounds[6], double extinction, const double colour[3]);
  void RemoveAllSmokeBoxes() { this->Smoke.clear(); }

  /**
   * The smoke's emission (RGB) seen along the ray up to `distance`, with the
   * haze's and the smoke's extinction in front of it, and the smoke's
   * transmittance over [0, distance] (1 without smoke).
   */
  void ComputeSmoke(const double origin[3], const double direction[3], double distance, double emission[3],
    double* transmittance) const;

  /** Number of lights taken by SetLights. */
  int GetNumberOfLights() const { return static_cast<int>(this->Lights.size()); }

  /**
   * The image (RGB) that light `index` (in SetLights' order) projects in the
   * world direction `direction` from the light (any length), by the
   * reference's own projection and bilinear rule; (1, 1, 1) for a light with
   * no image. For checking the surfaces' lighting of textured spot lights.
   */
  void ComputeLightTexture(int index, const double direction[3], double rgb[3]) const;

  /**
   * Airlight (RGB) along the ray origin + x * direction (direction need not be
   * unit length; x in world units along the unit direction), 0 <= x <= distance;
   * distance may be +infinity.
   */
  void ComputeRay(const double origin[3], const double direction[3], double distance, double airlight[3]) const;

  /**
   * The expected frame: `rgba` and `depth` are the scene read back without the
   * pass (w x h, bottom row first, window depth in [0, 1]); `out` gets
   * RGB = rgb * exp(-kt ds) + airlight and A = 1 (w*h*4). Only every
   * `stride`-th pixel along x and y is computed (others are left NaN).
   * `airlight` (optional) gets the airlight alone (RGB, A = 1) of the same
   * rays, so a caller needing both does not trace the rays twice.
   */
  void ComputeImage(vtkRenderer* renderer, int w, int h, const float* rgba, const float* depth,
    std::vector<float>& out, int stride = 1, std::vector<float>* airlight = nullptr) const;

protected:
  vtkPlumeAirlightReference();
  ~vtkPlumeAirlightReference() override = default;

  struct Light
  {
    double Position[3];
    double Axis[3];
    double I0[3];
    bool Spot;
    double CosCone;
    double Exponent;
    bool Shadowed;
    // A projected image (TextureWidth 0: none): RGB per texel, row 0 at the
    // bottom; the image's axes in world coordinates divided by tan(cone).
    int TextureWidth = 0;
    int TextureHeight = 0;
    std::vector<double> Texels;
    double TextureRight[3];
    double TextureUp[3];
  };
  // The light's image (RGB) in the world direction v from the light.
  static void TextureAt(const Light& light, const double v[3], double rgb[3]);

  struct SmokeBox
  {
    double Bounds[6];
    double Extinction;
    double Colour[3];
  };
  std::vector<SmokeBox> Smoke;
  // The chords [enter, leave] of the ray (unit direction) through each smoke box (empty ones: enter > leave).
  std::vector<std::array<double, 2>> SmokeChords(const double o[3], const double r[3]) const;
  // The smoke's optical depth over [0, x] given the chords.
  double SmokeDepth(const std::vector<std::array<double, 2>>& chords, double x) const;

  // 1 if the segment from `light` to `point` crosses no occluder triangle.
  bool Visible(const double light[3], const double point[3]) const;

  // The occluders' triangles in a bounding-volume hierarchy (null: none).
  struct OccluderTree;
  std::shared_ptr<const OccluderTree> Tree;

  double Scattering[3] = { 0, 0, 0 };
  double Absorption[3] = { 0, 0, 0 };
  double IntensityScale = 1.0;
  double ScatteringAnisotropy = 0.0;
  double RelativeTolerance = 1e-9;
  std::vector<Light> Lights;

private:
  vtkPlumeAirlightReference(const vtkPlumeAirlightReference&) = delete;
  void operator=(const vtkPlumeAirlightReference&) = delete;
};

#endif
