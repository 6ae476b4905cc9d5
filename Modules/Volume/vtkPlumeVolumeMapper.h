/**
 * @class   vtkPlumeVolumeMapper
 * @brief   single-pass GPU raycasting of a vtkImageData scalar field (3D texture)
 *
 * A vtkVolumeMapper: put it on a vtkVolume in place of vtkGPUVolumeRayCastMapper.
 * Input: a vtkImageData with point scalars (the active scalars, or the array
 * chosen with SelectScalarArray / SetScalarModeToUsePointFieldData; one
 * component, the component chosen with SetScalarComponent, or the magnitude
 * of a vector). Origin, spacing, extent and the image direction matrix, and
 * the vtkVolume's transform, are honoured.
 *
 * How it draws (seed 004): the back faces of the volume's box (with
 * empty-space skipping: of the box around its non-transparent blocks) are rasterised
 * (depth clamp on, so the far plane never clips them); the fragment shader
 * builds the pixel's ray by unprojecting the near and far planes into the
 * volume's index space, intersects it with the box and marches it. Rays start
 * at the near plane when the camera is inside the volume. Before drawing, the
 * depth of the opaque scene is copied into a texture (vtkPlumeOpaqueDepthTexture)
 * and every ray stops at it, so the volume composites correctly in front of,
 * around and behind opaque VTK actors. Where a ray gathers nothing, nothing is
 * written. Output is premultiplied colour blended with (ONE, ONE_MINUS_SRC_ALPHA);
 * depth is neither tested nor written, except by an isosurface (ISOSURFACE_BLEND,
 * ImageSampleDistance 1), which is opaque and writes its hit's depth (z-tested
 * with GL_LEQUAL), so that what draws after it (e.g. vtkPlumeAirlightPass's
 * medium) stops at it as at opaque geometry.
 *
 * Sampling: samples sit at the midpoints of segments of SampleDistance voxels
 * (index-space length) along the ray; the first segment is shortened by a
 * per-pixel jitter (on by default), so the segments cover exactly the part of
 * the ray inside the volume and in front of opaque geometry. The scalar is
 * sampled trilinearly (clamped to the grid), or from the nearest node when the
 * property's interpolation type is nearest.
 *
 * Transfer functions (vtkVolumeProperty, component 0): colour c(s) from the
 * RGB transfer function, scalar opacity α(s) per unit distance u (world
 * units: OpacityUnitDistance if set, else the property's
 * ScalarOpacityUnitDistance if it is above 0, else the mean voxel spacing). They are tabulated with 1024 entries over the data's finite
 * range, or over TransferFunctionRange when it is set, and re-tabulated only
 * when the property or that range changes. The 3D texture holds the raw
 * values (vtkPlumeScalarTexture3D), mapped to the table by a scale and bias:
 * a range change re-tabulates 1024 entries and uploads no volume. The
 * extinction coefficient is σ(s) = -ln(1 - min(α(s), 1 - 1e-6)) / u, so the
 * opacity of a segment of world length L is 1 - exp(-σ L): the correction for
 * the actual step length.
 *
 * Modes (vtkVolumeMapper's BlendMode, plus Smoke):
 *  - COMPOSITE_BLEND (default): emission–absorption, front to back,
 *    colour c(s); converges to ∫ c σ T dt with T = exp(-∫σ). With the
 *    property's Shade on, each sample's colour is Phong-lit like the
 *    isosurface below (central-difference normal at the sample).
 *  - MAXIMUM_INTENSITY_BLEND: s_max along the ray, output (c α, α)(s_max).
 *  - ISOSURFACE_BLEND: the first crossing of the iso value (IsoValue if set,
 *    else the property's first IsoSurfaceValues entry if the property holds
 *    anything but VTK's default (a single 0) or UsePropertyIsoValue is on, else the middle of the colour transfer function's range, GetAutomaticIsoValue) between two
 *    samples, refined by 8 bisection steps; normal from central differences
 *    (one voxel) of the trilinear field, Phong lighting with the property's
 *    ambient/diffuse/specular/specular power and the renderer's lights; opaque.
 *  - Smoke (SmokeOn, composite blend only): emission–absorption with single
 *    scattering: radiance c(s)·(ka + kd Σ_l I_l T_l(x)), T_l the transmittance
 *    from x towards light l through the volume (shadow ray with
 *    ShadowSampleDistance-voxel midpoint steps, cached per grid node and
 *    interpolated unless LightCache is off), i.e. self-shadowing.
 * Lights: the renderer's switched-on lights (up to 4), each treated as
 * directional from its focal point towards its position; colour × intensity.
 *
 * Early ray termination once what the rest of the ray could add is below
 * TerminationError (see there);
 * empty-space skipping over 8³ blocks (see EmptySpaceSkipping).
 * Only the features in use are compiled (mode, jitter, depth, skipping,
 * shading: the shader's feature blocks picked by vtkPlumeShaderVariants).
 *
 * Numerical safety: NaN scalars count as the minimum of the finite range,
 * ±Inf as its ends (vtkPlumeScalarTexture3D); a grid one node thick along an
 * axis is a slab one spacing thick (index -0.5..0.5) along it; zero gradients
 * give the view direction as normal. Errors (no input, no or cell scalars,
 * grids larger than GL_MAX_3D_TEXTURE_SIZE or than the texture-memory budget)
 * are reported with vtkErrorMacro and nothing is drawn (never a silent crop).
 */
#ifndef vtkPlumeVolumeMapper_h
#define vtkPlumeVolumeMapper_h

#include "PlumeVolumeModule.h" // For export macro
#include "vtkVolumeMapper.h"

#include <limits> // For std::numeric_limits
#include <memory> // For std::unique_ptr
#include <string> // For std::string

class vtkImageData;
class vtkVolumeProperty;
class vtkPlumeParameterTable;
class vtkTextureObject;

class PLUMEVOLUME_EXPORT vtkPlumeVolumeMapper : public vtkVolumeMapper
{
public:
  static vtkPlumeVolumeMapper* New();
  vtkTypeMacro(vtkPlumeVolumeMapper, vtkVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

#ifndef __VTK_WRAP__
  /**
   * The one declaration of the volume's user parameters (scene keys, defaults,
   * ranges, documentation) that the scene reader, Documentation/SceneFormat.md
   * and the ParaView XML are made from; the constructor applies its defaults.
   */
  static const vtkPlumeParameterTable& GetParameterTable();
#endif

  enum RenderModes
  {
    RENDER_COMPOSITE = 0, ///< emission-absorption with the transfer functions (COMPOSITE_BLEND)
    RENDER_MIP = 1,       ///< maximum intensity (MAXIMUM_INTENSITY_BLEND)
    RENDER_ISOSURFACE = 2, ///< first crossing of IsoValue, Phong-lit (ISOSURFACE_BLEND)
    RENDER_SMOKE = 3      ///< emission-absorption lit by the scene's lights, self-shadowed (Smoke on)
  };
  ///@{
  /**
   * The four modes in one property (what scenes and ParaView set): the blend
   * mode and Smoke together. Default RENDER_COMPOSITE. GetRenderMode reads
   * them back (a blend mode with no mode of its own reads as composite).
   */
  void SetRenderMode(int mode);
  int GetRenderMode();
  ///@}

  ///@{
  /** Component of a multi-component array to render; -1 (default) = the only one or the magnitude. */
  vtkSetClampMacro(ScalarComponent, int, -1, VTK_INT_MAX);
  vtkGetMacro(ScalarComponent, int);
  ///@}

  ///@{
  /**
   * Point array whose zeros mark nodes outside the data (vtkResampleToImage
   * writes one when it resamples unstructured data). Those nodes draw nothing
   * and are left out of the scalar range: a sample's value is interpolated
   * over the valid nodes around it only, and its extinction is scaled by their
   * total trilinear weight, so the data fades out over its last voxel without
   * blending in the values outside it. MIP and isosurface use samples with
   * valid nodes around; an isosurface is left open where the data ends (a
   * crossing needs two such samples). Ignored when the input has no such
   * array. Default "vtkValidPointMask". Costs a second texture channel.
   */
  vtkSetStdStringFromCharMacro(ValidMaskArrayName);
  vtkGetCharFromStdStringMacro(ValidMaskArrayName);
  ///@}

  ///@{
  /** Distance between samples in voxels (index-space length). Default 0.5. Clamped to 1e-3..100. */
  vtkSetClampMacro(SampleDistance, double, 1e-3, 100.0);
  vtkGetMacro(SampleDistance, double);
  ///@}

  ///@{
  /**
   * Pre-integrated transfer functions (Engel et al. 2001, with the 1D
   * integral-function approximation), composite mode only (not shaded, not
   * smoke, not masked data: there the setting is ignored). Each step is a
   * segment between two samples at its ends, the value taken as linear along
   * it; its opacity is 1 - exp(-L (I_σ(u_b) - I_σ(u_f)) / (u_b - u_f)),
   * exact for that linear value (I_σ the integral of the extinction over the
   * value, tabulated once per transfer function and unit distance, 1024
   * entries), and its colour the extinction-weighted mean colour of the
   * values crossed (I_cσ / I_σ differences; self-attenuation inside the
   * segment is neglected). Sharp transfer functions then stay right at long
   * steps (thin opacity peaks that plain sampling steps over). With
   * EmptySpaceSkipping, segments that lie wholly inside transparent blocks
   * are jumped over (the blocks' value ranges share their boundary nodes, so
   * every value between such a segment's ends is transparent too). Default off.
   */
  vtkSetMacro(PreIntegration, bool);
  vtkGetMacro(PreIntegration, bool);
  vtkBooleanMacro(PreIntegration, bool);
  ///@}

  /** Whether the last render used pre-integration (PreIntegration on and applicable). */
  vtkGetMacro(LastPreIntegration, bool);

  ///@{
  /**
   * Ray lattice (VTK's ImageSampleDistance, made error-controlled): with a
   * value L > 1, rays are first cast on a lattice one every L pixels (the ray
   * through pixel i L, into a small texture); then each cell of L x L pixels
   * between four lattice rays is classified: where the lattice rays around it
   * agree within LatticeTolerance and (when rays stop at opaque geometry)
   * every pixel's opaque depth is what the corner rays predict within half a
   * voxel, its pixels interpolate them bilinearly; in every other cell (edges,
   * opaque-depth discontinuities, silhouettes) each pixel casts its own ray.
   * Features narrower than L pixels that no lattice ray sees can be missed,
   * as with the peers' ImageSampleDistance. Default 1 (one ray per pixel).
   * Clamped to 1..16.
   */
  vtkSetClampMacro(ImageSampleDistance, int, 1, 16);
  vtkGetMacro(ImageSampleDistance, int);
  ///@}

  ///@{
  /**
   * The lattice while the user interacts, when AutoAdjustSampleDistances is on:
   * VTK's convention, the volume's allocated render time below 1 s (the
   * interactor sets the window's DesiredUpdateRate, 15 frames/s by default,
   * while the camera moves, and its still rate, 0.0001, afterwards: the still
   * frame is then drawn at ImageSampleDistance). Default 2. Clamped to 1..16.
   */
  vtkSetClampMacro(InteractiveImageSampleDistance, int, 1, 16);
  vtkGetMacro(InteractiveImageSampleDistance, int);
  vtkSetMacro(AutoAdjustSampleDistances, bool);
  vtkGetMacro(AutoAdjustSampleDistances, bool);
  vtkBooleanMacro(AutoAdjustSampleDistances, bool);
  ///@}

  ///@{
  /**
   * Ray lattice: the largest difference (any premultiplied RGBA channel, 0..1)
   * between the four lattice rays around a pixel for which it interpolates
   * them instead of casting its own ray. Default 0.004 (about one 8-bit step).
   * Clamped to 0..1 (0: only where they are equal).
   */
  vtkSetClampMacro(LatticeTolerance, double, 0.0, 1.0);
  vtkGetMacro(LatticeTolerance, double);
  ///@}

  /** The ray lattice used at the last render (1: one ray per pixel). */
  vtkGetMacro(LastImageSampleDistance, int);

  ///@{
  /**
   * Count the rays of each render (diagnostics for tests and benchmarks: it
   * reads the cell classification back, a GPU round trip). Default off.
   */
  vtkSetMacro(CountRays, bool);
  vtkGetMacro(CountRays, bool);
  vtkBooleanMacro(CountRays, bool);
  ///@}

  /**
   * Rays cast at the last render with CountRays on (else the last counted):
   * with a lattice, every lattice ray plus every viewport pixel of the cells
   * that cast their own (where the box does not cover a pixel, its ray is not
   * cast: an upper bound); with one ray per pixel, the viewport's pixels.
   */
  vtkGetMacro(LastRayCount, double);

  ///@{
  /**
   * Time each pass of every render (diagnostics for benchmarks: the GL work
   * is finished after each pass, so passes that would overlap run one after
   * the other and the frame is slower). Default off.
   */
  vtkSetMacro(ProfilePasses, bool);
  vtkGetMacro(ProfilePasses, bool);
  vtkBooleanMacro(ProfilePasses, bool);
  ///@}

  ///@{
  /**
   * The passes timed at the last render with ProfilePasses on, in order:
   * "resources" (uploads, block summaries), "depth" (the opaque depth),
   * "setup" (matrices, lights, programs, the light volume), then with a ray
   * lattice "lattice_rays", "classify", "interpolation", and "rays" (the
   * rays cast per pixel). Seconds of wall time each (CPU and GL), and of the
   * process's CPU time (all its threads, llvmpipe's included: steadier on a
   * loaded machine). Out of range: nullptr and 0.
   */
  int GetNumberOfProfiledPasses();
  const char* GetProfiledPassName(int pass);
  double GetProfiledPassSeconds(int pass);
  double GetProfiledPassCPUSeconds(int pass);
  ///@}

  ///@{
  /** Per-pixel jitter of the first sample (against wood-grain). Default on. */
  vtkSetMacro(Jitter, bool);
  vtkGetMacro(Jitter, bool);
  vtkBooleanMacro(Jitter, bool);
  ///@}

  ///@{
  /** Change the jitter pattern every frame (else a fixed pattern given by JitterSeed). Default off. */
  vtkSetMacro(AnimatedJitter, bool);
  vtkGetMacro(AnimatedJitter, bool);
  vtkBooleanMacro(AnimatedJitter, bool);
  vtkSetMacro(JitterSeed, int);
  vtkGetMacro(JitterSeed, int);
  ///@}

  ///@{
  /**
   * Early ray termination's error budget: the most a terminated ray may change
   * a pixel, in full-scale colour units (0..1). A ray stops once its
   * transmittance T is at most TerminationError / max(R, 1), R the largest
   * radiance a sample can emit per unit opacity (the brightest colour of the
   * transfer function where it has opacity, times the lighting: ambient +
   * (diffuse + specular) × the lights' colours when shaded, ambient + diffuse
   * × the lights' in smoke mode). What the rest of the ray would have added
   * is T × (its radiance − its opacity × what lies behind), which is at most
   * T × max(R, 1) for anything behind of at most full scale. Default 0.001
   * (a quarter of an 8-bit step; the former fixed threshold 0.995 left up to
   * 0.35 % on a dense blob). Clamped to 0..0.5; 0 = never terminate.
   */
  vtkSetClampMacro(TerminationError, double, 0.0, 0.5);
  vtkGetMacro(TerminationError, double);
  ///@}

  /** The opacity at which rays stopped at the last render (1 = never), derived from TerminationError. */
  vtkGetMacro(EffectiveOpacityThreshold, double);

  ///@{
  /**
   * The scalar range (data units) the transfer functions are tabulated over:
   * values below it read the table's first entry, above it its last. Unset
   * (default {0, 0}, or any range with min >= max): the data's finite range
   * (of the valid nodes). A change re-tabulates the table and uploads no
   * volume (the texture's raw values are mapped by a scale and bias).
   */
  vtkSetVector2Macro(TransferFunctionRange, double);
  vtkGetVector2Macro(TransferFunctionRange, double);
  ///@}

  ///@{
  /**
   * Iso value (data units) for ISOSURFACE_BLEND; any finite value, 0
   * included, is used as set. Default NaN (not set) = the volume property's
   * first iso value if the property holds anything but VTK's default (a
   * single 0) or UsePropertyIsoValue is on, else GetAutomaticIsoValue
   * (the middle of the colour transfer function's range). Rendering with a
   * value outside the data's range warns (once per value): no surface shows.
   * Scene key `iso_value`.
   */
  vtkSetMacro(IsoValue, double);
  vtkGetMacro(IsoValue, double);
  ///@}

  ///@{
  /**
   * Whether an IsoValue left at NaN takes the volume property's first iso
   * value (GetIsoSurfaceValues()->GetValue(0)) even when it is 0. A
   * vtkVolumeProperty always holds one value, and VTK's default is a single
   * 0, the same state as a 0 set on purpose: any other state (a non-zero
   * value, several values) is taken whatever this switch says (as VTK's own
   * mappers read it), a single 0 only with it on. Default false: a property
   * left at VTK's default gives the automatic value.
   */
  vtkSetMacro(UsePropertyIsoValue, bool);
  vtkGetMacro(UsePropertyIsoValue, bool);
  vtkBooleanMacro(UsePropertyIsoValue, bool);
  ///@}

  /** The iso value used at the last isosurface render (data units). */
  vtkGetMacro(EffectiveIsoValue, double);

  /**
   * The automatic iso value: the middle of the property's colour (or grey)
   * transfer function's range, the part of the data the user sees coloured;
   * the middle of `range` if that function has no extent.
   */
  static double GetAutomaticIsoValue(vtkVolumeProperty* property, const double range[2]);

  ///@{
  /**
   * World length over which the transfer function's opacity applies (the
   * opacity of a step of another length is corrected for it). 0 (default):
   * the vtkVolumeProperty's ScalarOpacityUnitDistance, as VTK's own mappers
   * read it (VTK's default 1 is one world unit, and a user's 1 too); a
   * property set to 0 means automatic: GetAutomaticOpacityUnitDistance (one
   * voxel: the same look on a fine and a coarse grid of the same data),
   * which the plume command line and the ParaView representation use.
   * > 0: this value, whatever the property says. Scene key
   * opacity_unit_distance.
   */
  vtkSetClampMacro(OpacityUnitDistance, double, 0.0, 1e30);
  vtkGetMacro(OpacityUnitDistance, double);
  ///@}

  /** The opacity unit distance used at the last render (world units). */
  vtkGetMacro(EffectiveOpacityUnitDistance, double);

  /** The automatic opacity unit distance: the image's mean absolute spacing (1 if it has none). */
  static double GetAutomaticOpacityUnitDistance(vtkImageData* image);

  /**
   * Plume's lighting for the vtkVolumeProperty that goes with this mapper, in
   * its current render mode (VTK's own defaults, ambient 0.1, diffuse 0.7,
   * specular 0.2, specular power 10, are made for surfaces): RENDER_SMOKE is
   * lit more evenly, ambient 0.3 and diffuse 1.0 (the scattering's ka and
   * kd); the other modes' shading ambient 0.15 and diffuse 0.75; specular 0.3
   * and specular power 20 in every mode. Sets them on `property` (call it
   * after choosing the mode); the `plume` command line starts every volume
   * from them (scene keys ambient, diffuse, specular, specular_power).
   */
  void ApplyDefaultLighting(vtkVolumeProperty* property);

  ///@{
  /** Smoke: emission–absorption with single-scattered, self-shadowed light. Default off. */
  vtkSetMacro(Smoke, bool);
  vtkGetMacro(Smoke, bool);
  vtkBooleanMacro(Smoke, bool);
  ///@}

  ///@{
  /** Step of the smoke's shadow rays, in voxels. Default 1. Clamped to 0.05..100. */
  vtkSetClampMacro(ShadowSampleDistance, double, 0.05, 100.0);
  vtkGetMacro(ShadowSampleDistance, double);
  ///@}

  ///@{
  /**
   * Smoke: cache the lighting. The transmittance from every grid node towards
   * each light is kept in a 3D texture (2 bytes per node and light, 4
   * channels for 3 lights; within TextureMemoryBudgetMB beside the volume,
   * with 4 more bytes per node while it is made, else shadow rays are used)
   * and interpolated at each sample. It is made by a sweep along each light
   * (vtkPlumeLightVolume: layer by layer, each node's transmittance from an
   * earlier layer's, bicubic, times its own segment's, marched with
   * ShadowSampleDistance steps), and remade in the frame a light's direction
   * relative to the volume, the data, the transfer function or
   * ShadowSampleDistance changes. Off: a shadow ray per sample. Default on.
   */
  vtkSetMacro(LightCache, bool);
  vtkGetMacro(LightCache, bool);
  vtkBooleanMacro(LightCache, bool);
  ///@}

  /** Whether the last render used the light cache (smoke, within the budget). */
  vtkGetMacro(LastLightCache, bool);

  /** How often the smoke's light volume has been computed (tests: no stale lighting, no needless work). */
  int GetLightVolumeUpdateCount();

  /**
   * The smoke's light volume: a 3D texture of the grid's size, the
   * transmittance towards light l in channel l (16-bit normalised); null
   * before the first frame that used it (tests read it back).
   */
  vtkTextureObject* GetLightVolumeTexture();

  ///@{
  /**
   * Stop rays at the depth of the opaque scene. Default on. Under a
   * vtkPlumeCompositingPass that is the frame's shared depth (opaque actors
   * and glyphs), and the volume is sorted back to front with the other media;
   * in a plain renderer the depth buffer as it is when the volume renders.
   */
  vtkSetMacro(UseOpaqueDepth, bool);
  vtkGetMacro(UseOpaqueDepth, bool);
  vtkBooleanMacro(UseOpaqueDepth, bool);
  ///@}

  /**
   * Whether the last render read the opaque depth: UseOpaqueDepth, and
   * another visible prop may have written depth
   * (vtkPlumeCompositingPass::HasOtherDepthWriters). Without one the depth
   * is the far plane everywhere and reading it would change nothing.
   */
  vtkGetMacro(LastOpaqueDepth, bool);

  ///@{
  /**
   * Empty-space skipping over blocks of 8³ voxels. Composite and smoke: blocks
   * whose value range maps to zero opacity are jumped over (the block summary
   * is rebuilt when the data or the transfer functions change), and only the
   * box around the others is drawn; with fewer than 10 % transparent blocks
   * only the box is (the per-block look-ups would cost more than they save).
   * Isosurface: a block whose range misses the iso value on the side the ray
   * is on. MIP: only with MIPSkipping on. The result is the same as without
   * skipping (a skipped sample could not have changed it; float rounding
   * aside). Default on.
   */
  vtkSetMacro(EmptySpaceSkipping, bool);
  vtkGetMacro(EmptySpaceSkipping, bool);
  vtkBooleanMacro(EmptySpaceSkipping, bool);
  ///@}

  ///@{
  /**
   * MIP empty-space skipping (with EmptySpaceSkipping on): a block whose
   * maximum is not above the ray's running maximum is jumped over; same image.
   * Default off: on llvmpipe it was slower (0.8x on the benchmark's sparse
   * smoke, 1.0x on its dense field: the block look-ups cost more than the
   * few, ray-dependent skips save).
   */
  vtkSetMacro(MIPSkipping, bool);
  vtkGetMacro(MIPSkipping, bool);
  vtkBooleanMacro(MIPSkipping, bool);
  ///@}

  /**
   * Fraction of the 8³ blocks skipped wholesale at the last render (0 when
   * skipping is off): composite and smoke, blocks whose values are all
   * transparent; isosurface, blocks whose value range does not contain the iso
   * value. MIP decides per ray (a block whose maximum is not above the ray's
   * running maximum is jumped over), so this is 0 there.
   */
  vtkGetMacro(EmptyBlockFraction, double);

  ///@{
  /**
   * Texture-memory budget in MB (2^20 bytes). A volume whose 3D texture would
   * need more (4 bytes per node, R32F, plus the 8³ block summary) is refused
   * with one error naming its size and the budget; nothing is cropped and
   * nothing drawn (there is no bricking). 0 (default) = automatic: half of the
   * physical memory (on software GL such as llvmpipe textures live in system
   * memory, and it is also the plume command line's default budget), capped at
   * three quarters of the video memory when the driver reports it
   * (GL_NVX_gpu_memory_info / GL_ATI_meminfo). Uploading also needs about
   * three times the texture size in transient host memory.
   */
  vtkSetClampMacro(TextureMemoryBudgetMB, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(TextureMemoryBudgetMB, double);
  ///@}

  /** The budget that applied at the last render, MB (the automatic value when TextureMemoryBudgetMB is 0). */
  vtkGetMacro(EffectiveTextureMemoryBudgetMB, double);

  /**
   * Bytes of GPU texture memory the mapper needs for an image of these point
   * dimensions: 4 per point, 8 with a valid-point mask (masked), 16 for shaded
   * composite (shaded: the gradient is stored with the value; counted even
   * with a mask, which stores none: an upper bound).
   */
  static double GetTextureBytes(const int dimensions[3], bool masked = false, bool shaded = false);

  /**
   * "" when a volume of these point dimensions fits a texture budget of
   * `budgetMB`, else the one-line reason naming the dimensions, the bytes
   * needed and the budget. Render() refuses with it; front doors (the plume
   * command line) call it to refuse before loading and rendering.
   */
  static std::string CheckTextureBudget(const int dimensions[3], bool masked, bool shaded, double budgetMB);

  /** Number of 3D-texture uploads so far (tests check re-renders do not upload). */
  int GetUploadCount();

  /** Number of data versions bound from a producer's hand-over (vtkPlumeTextureHandOver) instead of uploaded. */
  int GetHandOverCount();

  /** Number of transfer-function tabulations so far. */
  vtkGetMacro(TableCount, int);

  void Render(vtkRenderer* ren, vtkVolume* vol) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /** Bounds of the volume in its own coordinates (a 1-node axis is one spacing thick). */
  double* GetBounds() override;
  void GetBounds(double bounds[6]) override { this->vtkVolumeMapper::GetBounds(bounds); }

protected:
  vtkPlumeVolumeMapper();
  ~vtkPlumeVolumeMapper() override;

  int ScalarComponent = -1;
  std::string ValidMaskArrayName = "vtkValidPointMask";
  double SampleDistance = 0.5;
  bool Jitter = true;
  bool AnimatedJitter = false;
  int JitterSeed = 0;
  double TerminationError = 0.001;
  int ImageSampleDistance = 1;
  int InteractiveImageSampleDistance = 2;
  bool AutoAdjustSampleDistances = true;
  double LatticeTolerance = 0.004;
  int LastImageSampleDistance = 1;
  bool CountRays = false;
  bool ProfilePasses = false;
  double LastRayCount = 0.0;
  double EffectiveOpacityThreshold = 1.0;
  double IsoValue;
  bool UsePropertyIsoValue = false;
  bool Smoke = false;
  double ShadowSampleDistance = 1.0;
  bool LightCache = true;
  bool LastLightCache = false;
  bool UseOpaqueDepth = true;
  bool LastOpaqueDepth = false;
  bool EmptySpaceSkipping = true;
  bool PreIntegration = false;
  bool LastPreIntegration = false;
  bool MIPSkipping = false;
  double EmptyBlockFraction = 0.0;
  double TextureMemoryBudgetMB = 0.0;
  double EffectiveTextureMemoryBudgetMB = 0.0;
  int TableCount = 0;
  double TransferFunctionRange[2] = { 0.0, 0.0 };
  double OpacityUnitDistance = 0.0;
  double EffectiveOpacityUnitDistance = 1.0;
  double EffectiveIsoValue = 0.0;
  double LastWarnedIsoValue = std::numeric_limits<double>::quiet_NaN(); // warned about once

private:
  vtkPlumeVolumeMapper(const vtkPlumeVolumeMapper&) = delete;
  void operator=(const vtkPlumeVolumeMapper&) = delete;

  class Internals; // GL state lives here
  std::unique_ptr<Internals> Impl;
};

#endif
