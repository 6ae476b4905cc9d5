/**
 * @class   vtkPlumeAirlightPass
 * @brief   light scattered by a homogeneous participating medium (haze, smoke, fog) from positional and spot lights (seed 001)
 *
 * A vtkRenderPass that wraps the scene's own passes (its delegate, e.g. a
 * vtkRenderStepsPass), like VTK's vtkSSAOPass or vtkToneMappingPass: the
 * delegate renders into a private float colour + depth framebuffer, then one
 * full-screen pass writes, per pixel and RGB channel,
 *
 *   C = C_surface * exp(-kt * ds) + sum over lights of L_airlight,
 *   L_airlight = integral_0^ds  ks/(4 pi) * I0 * w(x) / d(x)^2 * exp(-kt (x + d(x))) dx,
 *
 * x the distance along the view ray, ds the distance to the opaque surface
 * (infinite where nothing was drawn: the medium fills space, so the
 * background colour is fully extinguished and only airlight remains), d(x)
 * the distance from the light, ks the scattering and ka the absorption
 * coefficient, kt = ks + ka, I0 the light's radiant intensity and w the spot
 * factor (1 for point lights). Isotropic phase function 1/(4 pi), or
 * Henyey-Greenstein (ScatteringAnisotropy g, exact: it moves into the
 * tables); single scattering; lights can be shadowed by opaque props
 * (below); the airlight can be computed at a lower resolution and upsampled
 * with error control (Downsampling).
 *
 * The integral in closed form (Sun et al. 2005, seed 001, derived afresh in
 * Documentation/Airlight.md): with h the distance from the light to the ray's
 * line and t = x - tc the position along the ray relative to the foot of the
 * perpendicular, the integrand is a total derivative of
 *   P_head(x) = ks I0/(2 pi) exp(-kt tc) H(m, tau) / (d - t)           (t <= 0)
 *   P_tail(x) = ks I0/(2 pi) exp(-kt (x + d)) G(m, eps) / (t + d)      (t >= 0)
 * with m = kt (t + d), tau = eps = h / (t + d) in [0, 1] and two smooth
 * bounded functions H, G tabulated once in double precision on the CPU
 * (GetScatteringTable) over the whole unbounded domain (m mapped to
 * sqrt(m / (1 + m))): this is Sun's F(u, v) split at the foot of the perpendicular
 * and normalised so that nothing overflows (no exp(+kt d)), nothing is
 * divided by h (exact limits for gamma -> 0 and pi) and no arctan is
 * evaluated. A point light costs two table look-ups per channel (four if
 * the ray segment crosses the foot; a grey medium, kt equal in R, G and B,
 * compiles a variant with one look-up for the three channels). A spot light's hard cone boundary is
 * exact (ray-cone interval); its exponent weight pow(cos, e) is applied per
 * sub-interval, up to SpotSteps * ceil(sqrt(e/2)) sub-intervals uniform in the
 * angle seen from the light (for a chord across the whole cone; fewer for a
 * shorter one, the same angular step; one when e = 0, then exact).
 *
 * Lights: every switched-on positional vtkLight of the renderer (after the
 * delegate has updated the light geometry, so head/camera lights work);
 * directional lights have no source point and add no airlight. I0 =
 * Intensity * DiffuseColor * IntensityScale, with inverse-square falloff
 * (the closed form needs it); a light whose AttenuationValues are purely
 * quadratic (0, 0, c2) is divided by c2, other attenuation polynomials are
 * ignored for the airlight (VTK's default (1, 0, 0) is no falloff, which a
 * point source in a medium cannot have). A cone angle below 90 degrees makes
 * a spot light with VTK's rule (inside the cone w = pow(cos angle, exponent),
 * outside 0). Any number of lights: one shader pass takes up to 8, further
 * lights are drawn in further passes of up to 8 (light groups), each adding
 * its airlight (additive blending); the surface is attenuated once.
 *
 * Skipped work: with ks = ka = 0 in every channel the delegate renders
 * directly (no framebuffer, no pass; textured spot lights still put their
 * images on the surfaces). The table is built once per process
 * and resolution and uploaded once per context.
 *
 * Volumetric shadows (Wyman & Ramsey 2008, seed 001): with Shadows on,
 * every spot light whose cone contains the bounds of some visible opaque prop
 * gets a depth map of the opaque props from its frustum, and every point
 * light with some opaque prop a cube map (six 90-degree frusta along the
 * world axes, drawn as tiles of one 3 x 2 atlas); maps are rebuilt only when
 * the light, a prop or the map size changes. A shadowed light's airlight is
 * a march along the view ray (inside the cone for a spot): ShadowSteps
 * sub-intervals uniform in the angle seen from the light, each adding
 * w * [Phi(x_k) - Phi(x_{k-1})] when a jittered point of it is lit, Phi the
 * closed-form running integral (so a fully lit ray with exponent 0 is the
 * unshadowed result; no arctan in the loop). Every light can be shadowed
 * (MaximumShadowedLights = 8 per light group, one sampler each).
 *
 * Textured spot lights (a gobo, a slide projector): a vtkImageData set on
 * a spot light (SetLightTexture, the LIGHT_TEXTURE() key of the light's
 * information) is projected by it and multiplies I0 per RGB channel by
 * direction, in the airlight and on the surfaces it falls on (the diffuse
 * and specular light of VTK's polydata mappers, see PreReplaceShaderValues);
 * see SetLightTexture for the projection. The closed form treats
 * the image like the exponent weight, per sub-interval at its middle
 * direction (two sub-intervals per texel the ray's image crosses); the
 * shader variant with this code is compiled only for a light group that has
 * a textured light.
 *
 * Translucent media (Plume's volumes and smoke sheets, VTK's volumes): when
 * the delegate is a vtkPlumeCompositingPass, its media step draws into a
 * layer of this pass (vtkPlumeCompositingPass::MEDIA_LAYER) instead of the
 * scene colour, giving their premultiplied colour Cv and opacity av per
 * pixel (and, when smoke sheets are among them, their RGB transmittance Tv
 * from a second draw over white; else Tv = 1 - av). The haze along the view ray is split at a depth xv on the ray's
 * chord through the media's bounds: C = A[0, xv] + exp(-kt xv) Cv +
 * (1 - av) (A[xv, ds] + exp(-kt ds) C_surface). xv is exact to first order
 * for a medium of uniform extinction along the chord (see
 * Documentation/Airlight.md); a medium that writes depth (an opaque
 * isosurface) is a surface, all the haze up to it in front.
 *
 * Limits: a light exactly on a view ray (the integral of 1/d^2 diverges)
 * gives a huge but finite value, clamped to 1e20.
 */
#ifndef vtkPlumeAirlightPass_h
#define vtkPlumeAirlightPass_h

#include "PlumeAirlightModule.h" // For export macro
#include "vtkImageProcessingPass.h"
#include "vtkNew.h"                      // For vtkNew
#include "vtkTimeStamp.h"                // For vtkTimeStamp
#include "vtkWeakPointer.h"              // For LatticeWindow
#include "vtkPlumePassProfiler.h"       // For Profiler
#include "vtkPlumeShaderProgramCache.h" // For Programs

#include <functional> // For std::function
#include <string>  // For std::string
#include <utility> // For std::pair
#include <vector>  // For std::vector

class vtkImageData;
class vtkInformationDoubleVectorKey;
class vtkInformationObjectBaseKey;
class vtkLight;
class vtkMatrix4x4;
class vtkOpenGLVertexArrayObject;
class vtkPlumeShaderFeatures;
class vtkShaderProgram;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkPlumeParameterTable;
class vtkRenderState;
class vtkTextureObject;

class PLUMEAIRLIGHT_EXPORT vtkPlumeAirlightPass : public vtkImageProcessingPass
{
public:
  static vtkPlumeAirlightPass* New();
  vtkTypeMacro(vtkPlumeAirlightPass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The declaration of the pass's parameters (scene key "medium"). */
  static const vtkPlumeParameterTable& GetParameterTable();

  void Render(const vtkRenderState* s) override;

  ///@{
  /**
   * Textured spot lights on surfaces: while the delegate draws, the pass puts
   * itself on the props' vtkOpenGLRenderPass::RenderPasses() key (as VTK's
   * vtkShadowMapPass does) and multiplies, in every vtkOpenGLPolyDataMapper's
   * fragment shader, the diffuse and specular light of each textured spot by
   * its image in the fragment's direction (the projection of SetLightTexture,
   * the same GLSL as the airlight's). Called by the mappers, not by users.
   */
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override;
  ///@}
  /**
   * Frees the pass's GL objects. The renderer calls it when its window goes;
   * as with VTK's own passes, call it before taking the pass out of a
   * renderer whose window stays, or the objects are never freed.
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /**
   * Scattering coefficient ks per RGB channel, per model unit of length,
   * each clamped to [0, 1e30] (NaN counts as 0). Default (0, 0, 0).
   */
  void SetScattering(double r, double g, double b);
  void SetScattering(const double rgb[3]) { this->SetScattering(rgb[0], rgb[1], rgb[2]); }
  vtkGetVector3Macro(Scattering, double);
  ///@}

  ///@{
  /**
   * Absorption coefficient ka per RGB channel, per model unit of length,
   * each clamped to [0, 1e30] (NaN counts as 0). Default (0, 0, 0).
   */
  void SetAbsorption(double r, double g, double b);
  void SetAbsorption(const double rgb[3]) { this->SetAbsorption(rgb[0], rgb[1], rgb[2]); }
  vtkGetVector3Macro(Absorption, double);
  ///@}

  ///@{
  /**
   * Henyey-Greenstein phase function's asymmetry g, clamped to [-0.95, 0.95]
   * (NaN counts as 0): p(a) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos a)^1.5), a
   * the scattering angle; g > 0 scatters forward (a glow around lights seen
   * through the medium), g < 0 backward, 0 is the isotropic 1/(4 pi). The
   * closed form stays exact: the phase depends only on the angle seen from
   * the light, its integration variable, so it moves into the table (one
   * table per g, built once per process on the CPU). Default 0.
   */
  void SetScatteringAnisotropy(double g);
  vtkGetMacro(ScatteringAnisotropy, double);
  ///@}

  ///@{
  /** Multiplies every light's intensity for the airlight only (surface shading stays VTK's). Default 1. */
  vtkSetClampMacro(IntensityScale, double, 0.0, 1e30);
  vtkGetMacro(IntensityScale, double);
  ///@}

  ///@{
  /**
   * Sub-intervals along a spot light's cone for its exponent weight, per unit
   * of sqrt(exponent / 2), for a view ray whose chord inside the cone spans
   * the cone's full angle as seen from the light; a shorter chord gets its
   * share (the same angular step), at least 1 (at most 256 in all; unused
   * when the exponent is 0). Default 8.
   */
  vtkSetClampMacro(SpotSteps, int, 1, 256);
  vtkGetMacro(SpotSteps, int);
  ///@}

  ///@{
  /**
   * The airlight lattice, one node every D pixels: 1 evaluates the airlight
   * at every pixel; D > 1 evaluates it first on the rays through pixels
   * (i D, j D) (the last row and column at the viewport's edge), then
   * classifies each cell of D x D pixels between four nodes. A cell is
   * interpolated bilinearly only if (1) the nodes' second differences at its
   * corners estimate the interpolation error, (|f_xx| + |f_yy|) D^2 / 8,
   * within UpsamplingTolerance of the frame's airlight range (the nodes'
   * max - min, at most 1) in every channel; (2) every pixel lies on the
   * surface its corners predict (window depth bilinear between them, exact
   * on a plane, within 0.1 % in eye depth; or all without a surface): no
   * silhouette, no object smaller than a cell; (3) no light projects into
   * the cell or its eight neighbours (a glow peaks between nodes), nor the
   * axis of a spot narrower than 10 degrees within 1.5 cells (its shaft can
   * pass between nodes); and (4)
   * no translucent medium covers one of its pixels. The other cells go to
   * the second lattice level (LatticeLevels), and every pixel of the cells
   * it refines (with one level: of the other cells) is evaluated exactly, in
   * a pass drawn over those cells only (vtkPlumeLatticeCellsVS). Lights that cast shadows or project an image
   * are always evaluated at every pixel: a shadow or a shaft narrower than a
   * cell could fall between the nodes. Clamped to 1..8. Default 8.
   */
  vtkSetClampMacro(Downsampling, int, 1, 8);
  vtkGetMacro(Downsampling, int);
  ///@}

  ///@{
  /**
   * Levels of the airlight lattice (with Downsampling > 1). Level 0 is the
   * lattice of Downsampling; level 1 (with an even Downsampling of at least
   * 4) halves the spacing inside the cells level 0 refined: their 3 x 3
   * nodes are known (the parent's four corners) or evaluated (the other
   * five, listed on the CPU from the parent's flags and evaluated densely),
   * their 2 x 2 cells classified by the same four rules at their own size
   * (the second differences from the parent's middle row and column) and
   * interpolated where they pass; only the last level's refined cells are
   * evaluated at every pixel. 1: one level. Clamped to 1..2. Default 1
   * (2 is no faster on llvmpipe and failed the error goal in
   * TestAirlightMedia, see Documentation/Airlight.md).
   */
  vtkSetClampMacro(LatticeLevels, int, 1, 2);
  vtkGetMacro(LatticeLevels, int);
  ///@}

  ///@{
  /**
   * With Downsampling > 1: the largest estimated interpolation error the
   * lattice accepts in a cell, as a fraction of the frame's airlight range
   * (clamped to 1, what an 8-bit window shows); 0 evaluates every pixel.
   * Default 0.005.
   */
  vtkSetClampMacro(UpsamplingTolerance, double, 0.0, 1.0);
  vtkGetMacro(UpsamplingTolerance, double);
  ///@}

  /**
   * The fraction of the airlight lattice's cells refined (evaluated at every
   * pixel) in the last frame's last light group on the lattice; 0 without a
   * lattice. A diagnostic, computed when asked: it reads the cell flags back
   * from the GPU (a wait for the frame, which the frames themselves no longer
   * pay); ReleaseGraphicsResources counts them before their textures go.
   */
  double GetLastRefinedCellFraction();

  /**
   * The fraction of the viewport's pixels evaluated exactly in the last
   * frame's last light group on the lattice (the last level's refined
   * cells); 0 without a lattice. Computed when asked, as
   * GetLastRefinedCellFraction.
   */
  double GetLastRefinedPixelFraction();

  ///@{
  /**
   * Time each pass of every frame (diagnostics for benchmarks: the GL work is
   * finished after each pass, so the frame is slower). Default off.
   */
  vtkSetMacro(ProfilePasses, bool);
  vtkGetMacro(ProfilePasses, bool);
  vtkBooleanMacro(ProfilePasses, bool);
  ///@}

  ///@{
  /**
   * The passes timed in the last frame with ProfilePasses on, in order:
   * "scene" (the delegate), then per light group either "pixels" (every
   * pixel) or the lattice's "nodes", "classify" (level 0), "nodes L",
   * "classify L" (finer level L), "resolve", "interpolate L" and "refine".
   * Seconds of wall time each (CPU and GL), and of the process's CPU time
   * (all its threads, llvmpipe's included: steadier on a loaded machine).
   * Out of range: nullptr and 0.
   */
  int GetNumberOfProfiledPasses() { return this->Profiler.GetNumberOfPasses(); }
  const char* GetProfiledPassName(int pass) { return this->Profiler.GetPassName(pass); }
  double GetProfiledPassSeconds(int pass) { return this->Profiler.GetPassSeconds(pass); }
  double GetProfiledPassCPUSeconds(int pass) { return this->Profiler.GetPassCPUSeconds(pass); }
  ///@}

  /** At most this many lattice levels (LatticeLevels). */
  static constexpr int MaximumLatticeLevels = 2;

  ///@{
  /**
   * For comparisons and benchmarks only: 0 uses the closed form; N > 0
   * replaces it by brute-force ray marching of the same integral (midpoint
   * rule, N samples per ray and light, rays that hit nothing stop where the
   * transmittance is 1e-6; with Shadows, each sample is tested in the same
   * shadow maps), what a user would write in a shader. Default 0.
   */
  vtkSetClampMacro(MarchSteps, int, 0, 65536);
  vtkGetMacro(MarchSteps, int);
  ///@}

  ///@{
  /**
   * Volumetric shadows of the opaque props (a shadow map per spot light whose
   * cone contains a prop's bounds, a cube map per point light). Default on.
   */
  vtkSetMacro(Shadows, bool);
  vtkGetMacro(Shadows, bool);
  vtkBooleanMacro(Shadows, bool);
  ///@}

  ///@{
  /**
   * March steps along a view ray for a shadowed light (sub-intervals
   * uniform in the angle seen from the light; at least the spot exponent's
   * own count). Default 64.
   */
  vtkSetClampMacro(ShadowSteps, int, 1, 1024);
  vtkGetMacro(ShadowSteps, int);
  ///@}

  ///@{
  /**
   * Width and height of each spot light's shadow map and of each face of a
   * point light's cube map (a 3 x 2 atlas of faces), texels. Default 1024.
   */
  vtkSetClampMacro(ShadowMapSize, int, 16, 8192);
  vtkGetMacro(ShadowMapSize, int);
  ///@}

  ///@{
  /**
   * Min-max mipmaps of the shadow maps (Chen et al. 2011): the march decides
   * each run of 8 steps from the nearest and farthest depth of the map under
   * the run's footprint, and evaluates a fully shadowed run (and a fully lit
   * run of an unweighted light) as one closed-form difference instead of
   * eight lit tests and look-ups. The result is the per-step march's (up to
   * float rounding). The pyramid is built on the CPU when a map is baked and
   * shares the map's texture; maps whose height is not a power of two get
   * none. Default true; false: every step is tested.
   */
  vtkSetMacro(ShadowMinMax, bool);
  vtkGetMacro(ShadowMinMax, bool);
  vtkBooleanMacro(ShadowMinMax, bool);
  ///@}

  ///@{
  /**
   * Diagnostic (for tests and tuning): the frame's colour becomes, per
   * pixel, (march runs decided by the min-max mipmaps, all march runs, 0),
   * summed over the pixel's shadowed lights; read it from a float target.
   * Default false.
   */
  vtkSetMacro(ShadowRunStatistics, bool);
  vtkGetMacro(ShadowRunStatistics, bool);
  ///@}

  /** How many shadow maps have been rendered so far (for tests: maps are rebuilt only on change). */
  vtkGetMacro(NumberOfShadowMapBakes, int);

  /** How many lights were shadowed in the last frame. */
  vtkGetMacro(NumberOfShadowedLights, int);

  /**
   * How many lights needed a shadow map in the last frame but were left
   * unshadowed (only on a driver with no texture unit left for a shadow map;
   * a warning names the numbers when this count changes to a value above 0).
   */
  vtkGetMacro(NumberOfUnshadowedLights, int);

  /**
   * Deprecated, always 0: no light is left out any more (lights beyond 8 are
   * drawn in further passes, see GetNumberOfLightGroups). Kept so that code
   * that checked it still compiles.
   */
  vtkGetMacro(NumberOfIgnoredLights, int);

  /**
   * How many full-screen passes the last frame's lights took: one shader takes
   * at most 8 positional lights (and at most MaximumShadowedLights shadowed
   * ones); further lights go into further groups, each a full-screen pass
   * that adds its airlight to the frame (additive blending; the surface
   * attenuation is applied once, by the first). 1 for up to 8 lights
   * (also for none).
   */
  vtkGetMacro(NumberOfLightGroups, int);

  /**
   * At most this many lights are shadowed per light group, i.e. per shader
   * pass (one shadow-map sampler each: GLSL 1.50 cannot index samplers
   * dynamically): 8, the number of lights a group holds, so every light can
   * be shadowed. A driver with fewer than 13 fragment texture units (GL 3.2
   * guarantees 16) lowers it to the units left after the pass's 5 others and
   * a shadowed light beyond it opens a new group; only a driver with no unit
   * left renders shadowed lights unshadowed, with a warning.
   */
  static constexpr int MaximumShadowedLights = 8;

  ///@{
  /**
   * Resolution N of the N x N scattering table (64: 0.2 s to compute once per
   * process, 256: 2.2 s on one core; the image error is the same, see
   * Documentation/Airlight.md). Default 64.
   */
  vtkSetClampMacro(TableResolution, int, 8, 2048);
  vtkGetMacro(TableResolution, int);
  ///@}

  /**
   * How many translucent media the delegate's compositing pass drew into
   * this pass's media layer in the last frame (0: none, or no compositing
   * pass in the delegate: the media then lie in the scene colour and are
   * treated as at the opaque depth behind them).
   */
  vtkGetMacro(NumberOfMediaInLayer, int);

  /** At most this many media bounding boxes go to the shader; further media share the last (their union). */
  static constexpr int MaximumMediaBoxes = 8;

  ///@{
  /**
   * Textured spot lights. LIGHT_TEXTURE() on a vtkLight's information holds
   * the vtkImageData it projects (none by default: an untextured light);
   * SetLightTexture(light, image) sets it (nullptr removes it). The image
   * is 2D in x and y (dimensions W x H x 1, W, H >= 1), its point scalars
   * (else its first point array) give the colour: 1 or 2 components grey
   * (the first), 3 or 4 RGB (alpha ignored); unsigned char and unsigned
   * short are divided by 255 and 65535, other types (float EXR images) are
   * taken as they are (HDR allowed); negative, NaN and infinite values count
   * as 0. Only spot lights (cone angle < 90) project a texture; on a point
   * light it is ignored. Changing the image (its MTime) re-uploads it.
   *
   * The projection, a slide projector at the light: a direction v from the
   * light, with the light's unit axis a (to its focal point), the image's
   * right axis x = normalize(a x U) and up axis y = x x a (U the up hint,
   * LIGHT_TEXTURE_UP(), default (0, 1, 0); if a is parallel to U, (0, 0, 1)
   * instead), meets the image at
   *   u = 1/2 + (v.x) / (2 (v.a) tan(cone)),  v' = 1/2 + (v.y) / (2 (v.a) tan(cone)),
   * so the image's square fills the cone's square and the cone's circle is
   * inscribed in it (the corners are outside the cone and never seen); a
   * light looking along -z with up (0, 1, 0) shows the image as a camera at
   * the light would (row 0 at the bottom, VTK's image order). Texel (i, j)
   * sits at ((i + 1/2)/W, (j + 1/2)/H), read bilinearly, clamped at the
   * borders.
   */
  static vtkInformationObjectBaseKey* LIGHT_TEXTURE();
  static vtkInformationDoubleVectorKey* LIGHT_TEXTURE_UP();
  static void SetLightTexture(vtkLight* light, vtkImageData* image);
  static vtkImageData* GetLightTexture(vtkLight* light);
  /** The up hint U of the light's image (world coordinates). Default (0, 1, 0). */
  static void SetLightTextureUp(vtkLight* light, double x, double y, double z);
  ///@}

  /** How many lights projected a texture in the last frame. */
  vtkGetMacro(NumberOfTexturedLights, int);

  /** True if the medium scatters or absorbs in some channel (else the pass only runs its delegate). */
  bool HasMedium() const;

  /**
   * The scattering table for resolution n and Henyey-Greenstein g (computed
   * once per (n, g) in double precision; shared, thread-safe): n*n pairs
   * (H, G) row-major, row j: u = j/(n-1), column i: p = i/(n-1),
   * m' = p^2/(1-p^2), storing
   *   (1+m') (1 + wH tau) H(m, tau),  m = m' (1 + kH tau),  tau = u / (1 + rH (1 - u)),
   *   (1+m') (1 + wG eps) G(m, eps),  m = m' / (1 + kG eps), eps = u / (1 + rG (1 - u)),
   *   H(m, tau) = integral_0^1 exp(-m q) P(tau q) / (1 + tau^2 q^2) dq,
   *   G(m, eps) = integral_0^inf exp(-m y) P((1+y)/eps) / (eps^2 + (1+y)^2) dy,
   * P(s) = 4 pi p_HG at cos a = (1 - s^2)/(1 + s^2), i.e.
   * P(s) = (1-g^2) (1+s^2)^1.5 / ((1+g)^2 s^2 + (1-g)^2)^1.5 (1 for g = 0);
   * kH = 2g/(1-g) for g > 0 (else 0) and kG = 2|g|/(1-|g|) for g < 0 (else
   * 0) follow the phase's peak (width (1-|g|)/(1+|g|) in tau or eps); the
   * row warp r = sqrt(1 + k) - 1 and the row weight w = k^3/64 of the same
   * function keep a segment that misses the peak (a small difference of two
   * large values) exact (GetTableCoordinates; Documentation/Airlight.md).
   * Each value to an absolute accuracy of about 1e-10 times its row weight
   * (adaptive Simpson).
   * Column p = 1 holds the limits m = inf.
   */
  static const std::vector<double>& GetScatteringTable(int n, double g = 0.0);

  /**
   * The scattering table's coordinates for Henyey-Greenstein g, as the
   * table and the shader use them: (kH, kG, rH, rG, wH, wG) of
   * GetScatteringTable (all 0 for g = 0).
   */
  static void GetTableCoordinates(double g, double coordinates[6]);

protected:
  vtkPlumeAirlightPass();
  ~vtkPlumeAirlightPass() override;

  bool UpdateResources(vtkOpenGLRenderWindow* renWin, int w, int h);

  double Scattering[3];
  double Absorption[3];
  double IntensityScale = 1.0;
  double ScatteringAnisotropy = 0.0;
  int SpotSteps = 8;
  int Downsampling = 8;
  int LatticeLevels = 1;
  double UpsamplingTolerance = 0.005;
  int TableResolution = 64;
  int MarchSteps = 0;
  bool Shadows = true;
  int ShadowSteps = 64;
  int ShadowMapSize = 1024;
  bool ShadowMinMax = true;
  bool ShadowRunStatistics = false;
  int NumberOfShadowMapBakes = 0;
  int NumberOfShadowedLights = 0;
  int NumberOfUnshadowedLights = 0;
  int ReportedUnshadowed = 0;
  int NumberOfIgnoredLights = 0; // always 0 (kept for compatibility)
  int NumberOfLightGroups = 0;
  int NumberOfMediaInLayer = 0;
  int NumberOfTexturedLights = 0;
  // The textured lights' images stacked in one RGBA32F atlas, rebuilt when an
  // image or the set of textured lights changes (key: image pointers and MTimes).
  vtkTextureObject* TextureAtlas = nullptr;
  std::vector<std::pair<vtkImageData*, vtkMTimeType>> TextureAtlasKey;
  // This frame's textured lights: the light, its index among the renderer's
  // switched-on lights (the polydata shaders' lightColorN), its rectangle in
  // the atlas (x0, y0, width, height) and, in eye coordinates, its position,
  // unit axis and the image's axes divided by tan(cone).
  struct LightTexture
  {
    vtkLight* Light = nullptr;
    int Index = 0;
    float Rect[4];
    float Frame[4][3]; // position, axis, right, up
  };
  std::vector<LightTexture> LightTextures;
  vtkTimeStamp LightTextureShaderTime; // the set of textured indices changed (the surface shaders' code)
  std::vector<int> LightTextureIndices;
  // Collects the frame's textured lights and uploads the atlas if an image
  // changed; returns true if some light projects an image.
  bool UpdateLightTextures(vtkRenderer* r, vtkOpenGLRenderWindow* renWin);
  // The delegate's render, with the textured lights' images on the surfaces.
  void RenderDelegate(const vtkRenderState* s, bool textured);

  struct ShadowMap;
  std::vector<ShadowMap*> ShadowMaps;
  // Reads a freshly baked map back and uploads its min-max mip chain (m->MinMax).
  void BuildMinMax(ShadowMap* m, vtkOpenGLRenderWindow* renWin, int w, int h);
  // Bakes the depth map of light `index` if its key changed; returns false on failure.
  bool BakeShadowMap(const vtkRenderState* s, int index, const std::vector<double>& key,
    const double position[3], const double focal[3], double coneAngle, const double bounds[6], bool point);

  vtkOpenGLFramebufferObject* FrameBuffer = nullptr;
  vtkTextureObject* ColorTexture = nullptr;
  vtkTextureObject* DepthTexture = nullptr;
  vtkTextureObject* TableTexture = nullptr;
  vtkOpenGLFramebufferObject* LowFrameBuffer = nullptr; // Downsampling > 1
  // Per lattice level: the nodes' airlight (RGBA32F) and per cell 1 refined,
  // 0 interpolated (R32F; a finer level's cells outside its parent's refined
  // cells are 0).
  vtkTextureObject* LatticeNodes[MaximumLatticeLevels] = {};
  vtkTextureObject* LatticeCells[MaximumLatticeLevels] = {};
  // Level 1: per node its texel index in LatticeNodes[1] or -1 (R32F), and
  // per texel of LatticeNodes[1] its node (RG32F), uploaded every frame.
  vtkTextureObject* LatticeNodeMap = nullptr;
  vtkTextureObject* LatticeNodeList = nullptr;
  // Level 0's nodes and cells are drawn folded, the upper half of the rows
  // beside the lower (RGBA32F, 2 n x ceil(n / 2) for n x n nodes), then
  // copied to LatticeNodes[0] / LatticeCells[0]: llvmpipe's threads split a
  // pass by 64 x 64 tiles, and a 64 x 64 target (512^2 at D 8) is one tile,
  // one thread.
  vtkTextureObject* LatticeFolded = nullptr;
  vtkNew<vtkOpenGLVertexArrayObject> EmptyVAO; // the refined cells' quads come from gl_VertexID
  double LastRefinedCellFraction = 0.0;
  double LastRefinedPixelFraction = 0.0;
  // The last lattice frame's flags are in LatticeCells, not yet counted
  // (CountLatticeFlags reads them back on LatticeWindow): the lattice that
  // frame drew (its levels, viewport width and height, each level's node
  // spacing and cells per row and column).
  bool LatticeFlagsPending = false;
  struct LatticeFrameGeometry
  {
    int Levels = 0;
    int Size[2] = { 0, 0 };
    int Spacing[MaximumLatticeLevels] = {};
    int Cells[MaximumLatticeLevels][2] = {};
  };
  LatticeFrameGeometry LatticeFrame;
  vtkWeakPointer<vtkOpenGLRenderWindow> LatticeWindow;
  void CountLatticeFlags();
  // Reads level 0's cell flags back (their target bound), lists the level-1
  // nodes to evaluate into LatticeNodeMap/LatticeNodeList (activated) and
  // returns the rows of LatticeNodes[1] they fill.
  int ListLatticeNodes(const int cells[][2]);
  // ProfilePasses: the passes of the last frame timed (enabled from
  // ProfilePasses at each frame's start)
  bool ProfilePasses = false;
  vtkPlumePassProfiler Profiler;
  // One light group's airlight on the lattice (Downsampling > 1): nodes, cell
  // classification, the frame with the interpolated airlight, the refined
  // cells' exact airlight. `lights`, `axes`, `cosCones`: the group's eye
  // positions, spot axes and cos(cone) (-2: a point light). False if a
  // program does not build.
  bool RenderLattice(vtkOpenGLRenderWindow* renWin, const vtkPlumeShaderFeatures& base,
    const std::function<void(vtkShaderProgram*)>& setUniforms, const std::function<void()>& blendGroup,
    int x, int y, int w, int h, vtkMatrix4x4* projection, const float* lights,
    const float* axes, const float* cosCones, int count);
  vtkTextureObject* MediaTexture = nullptr; // translucent media's premultiplied layer
  vtkTextureObject* MediaTransmittanceTexture = nullptr; // the media over 1: minus the layer, their RGB transmittance
  int UploadedTableResolution = 0;
  double UploadedTableAnisotropy = 0.0;
  // One full-screen program per variant (lights, spots, shadows of a group):
  // a frame with several light groups switches between them.
  vtkNew<vtkPlumeShaderProgramCache> Programs;

private:
  vtkPlumeAirlightPass(const vtkPlumeAirlightPass&) = delete;
  void operator=(const vtkPlumeAirlightPass&) = delete;
};

#endif
