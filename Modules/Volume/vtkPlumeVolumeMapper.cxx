#include "vtkPlumeVolumeMapper.h"

#include "vtkPlumeInputValidation.h"

#include "vtkPlumeGLMatrix.h"
#include "vtkPlumeCompositingPass.h"
#include "vtkPlumeImageFrame.h"
#include "vtkPlumeLatticeCellsDraw.h"
#include "vtkPlumeLatticeCellsVS.h"
#include "vtkPlumeLightVolume.h"
#include "vtkPlumeLookupTexture.h"
#include "vtkPlumeOpaqueDepthTexture.h"
#include "vtkPlumeParameterTable.h"
#include "vtkPlumePassProfiler.h"
#include "vtkPlumeScalarTexture3D.h"
#include "vtkPlumeShaderFeatures.h"
#include "vtkPlumeShaderProgramCache.h"
#include "vtkPlumeVolumeFS.h"
#include "vtkPlumeVolumeVS.h"
#include "vtkPlumeWindowChange.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTimeStamp.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <iomanip>
#include <set>
#include <sstream>
#include <unistd.h>
#include <vector>

vtkStandardNewMacro(vtkPlumeVolumeMapper);

namespace
{
constexpr int TableSize = 1024;
constexpr int MaxLights = 4;
// the light volume's sweep: a layer reads the last multiple of this before it
// (32^3 smoke, measured against a CPU march: bilinear interpolation from the
// previous layer blurred the shadows to max 0.17; bicubic from the last 8th
// layer: max 0.023, the image error as with a march per node)
constexpr int LightSweepStride = 8;
// an isosurface block is skipped only when its range misses the iso value by
// more than this (normalised units): filtered samples may round past a node value
constexpr float IsoMargin = 1e-6f;
// fewest transparent blocks (fraction) for which composite rays look blocks up
constexpr double MinSkipFraction = 0.1;

constexpr double Megabyte = 1024.0 * 1024.0;
// llvmpipe's tile height (pixels): the ray lattice's bands start at multiples of it
constexpr int TileRows = 64;

// megabytes for a message: whole numbers from 10 MB, else 3 significant digits
std::string MB(double mb)
{
  std::ostringstream out;
  if (mb >= 10)
  {
    out << std::llround(mb);
  }
  else
  {
    out << std::setprecision(3) << mb;
  }
  return out.str();
}

// Half the physical memory (software GL keeps textures in it; the plume command
// line uses the same default), capped at 3/4 of the video memory if the driver tells.
double AutomaticBudgetMB(vtkOpenGLRenderWindow* window)
{
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGE_SIZE);
  double mb = pages > 0 && pageSize > 0 ? 0.5 * double(pages) * double(pageSize) / Megabyte : 4096.0;
  window->MakeCurrent();
  GLint kb[4] = { 0, 0, 0, 0 };
  if (GLEW_NVX_gpu_memory_info)
  {
    glGetIntegerv(0x9048 /* GL_GPU_MEMORY_INFO_TOTAL_AVAILABLE_MEMORY_NVX */, kb);
  }
  else if (GLEW_ATI_meminfo)
  {
    glGetIntegerv(0x87FC /* GL_TEXTURE_FREE_MEMORY_ATI */, kb);
  }
  if (kb[0] > 0)
  {
    mb = std::min(mb, 0.75 * kb[0] / 1024.0);
  }
  return mb;
}

}

//------------------------------------------------------------------------------
class vtkPlumeVolumeMapper::Internals
{
public:
  vtkNew<vtkPlumeScalarTexture3D> Scalars;
  vtkNew<vtkPlumeOpaqueDepthTexture> Depth;
  vtkNew<vtkPlumeLookupTexture> Table; // colour + extinction per world unit over the scalar range
  vtkNew<vtkPlumeLookupTexture> Integral; // pre-integration: running integrals of (c sigma, sigma) over u
  vtkNew<vtkTextureObject> Occupancy;   // 1 byte per 8^3 block: 0 = transparent
  vtkNew<vtkTextureObject> BlockRanges; // RG32F per 8^3 block: min, max of u (MIP, isosurface)
  int RangesUpload = -1;     // data version of the block-range texture
  double RangesScaleBias[2] = { 0, 0 }; // and the mapping to u it was made with
  int OccupancyUpload = -1;
  int OccupancyTable = -1;
  size_t OccupiedBlocks = 0;
  double EmptyFraction = 0;    // of the blocks, in the occupancy texture
  double OccupiedMin[3] = { 0, 0, 0 }; // index-space bounds of the non-transparent blocks
  double OccupiedMax[3] = { 0, 0, 0 };
  vtkNew<vtkOpenGLVertexArrayObject> EmptyVAO;
  vtkNew<vtkTextureObject> Lattice; // RGBA32F: the lattice rays' premultiplied colour
  vtkNew<vtkTextureObject> Cells;   // R32F per lattice cell: 0 = interpolate, 1 = cast own rays
  vtkNew<vtkOpenGLFramebufferObject> LatticeFBO;
  vtkNew<vtkPlumeShaderProgramCache> Programs;
  vtkNew<vtkPlumeLightVolume> LightVolume; // smoke: transmittance towards each light per node
  vtkOpenGLRenderWindow* Window = nullptr;
  double AutomaticBudgetMB = 0; // of Window
  // ProfilePasses: the passes of the last render timed (enabled from
  // ProfilePasses at each render's start)
  vtkPlumePassProfiler Profiler;
  int FrameCount = 0; // frames drawn (animated jitter)
  double TableUnit = 0; // opacity unit distance of the table
  vtkTimeStamp TableUnitTime;

  // Everything one Render() call derives (the per-frame record the steps pass on).
  struct Frame
  {
    vtkRenderer* Renderer = nullptr;
    vtkVolume* Volume = nullptr;
    vtkOpenGLRenderWindow* Window = nullptr;
    vtkImageData* Image = nullptr;
    vtkDataArray* Scalars = nullptr;
    vtkDataArray* Mask = nullptr; // valid-point mask (one component) or null
    vtkVolumeProperty* Property = nullptr;
    bool Shade = false;           // shaded composite
    bool IsoDepth = false;        // the isosurface writes gl_FragDepth (ISO, lattice 1)
    bool PreInt = false;          // pre-integrated composite
    double Range[2] = { 0, 0 };   // the transfer functions' range (data units)
    double ScaleBias[2] = { 0, 0 }; // texel -> u over Range
    double InvUnit = 1.0;         // 1 / scalar opacity unit distance
    // empty-space skipping
    bool Skipping = false;        // composite: occupancy summary
    bool RangeSkipping = false;   // MIP / isosurface: block ranges
    bool SkipTransparent = false; // composite: per-block look-ups in the shader
    // opaque depth
    vtkPlumeOpaqueDepthTexture* Depth = nullptr;
    bool UseDepth = false;
    // index -> world -> clip, composed in double
    int Dims[3] = { 0, 0, 0 };
    double IndexToClip[16];
    double ClipToIndex[16];
    double Linear[9]; // linear part of index -> world
    double Normal[9]; // its inverse transpose
    double Det = 1.0;
    float BoxMin[3], BoxMax[3], FDims[3], DrawMin[3], DrawMax[3];
    // lights and mode
    std::vector<std::array<double, 3>> LightDirs, LightColors;
    std::string Mode; // shader feature: COMPOSITE, MIP, ISO or SMOKE
    bool Lit = false;
    int NLights = 0;
    std::vector<float> LightIndexDirs;      // smoke: unit directions towards the lights, index space
    std::vector<float> LightWorldPerIndex; // and the world length of one index unit along each
    bool LightCache = false;               // smoke: samples read the light volume
    std::vector<double> LightKey;          // what the light volume depends on
    vtkPlumeShaderFeatures LightFeatures;  // its slices' program
    vtkShaderProgram* LightProgram = nullptr;
    // ray lattice and programs
    int Viewport[4] = { 0, 0, 0, 0 }; // width, height, x, y
    int Lattice = 1;
    int LatticeSize[2] = { 0, 0 };
    int LatticeSplit = 0;   // rows split .. of the lattice stored from row TileRows on (0: one band)
    int LatticeRows = 0;    // the lattice texture's height
    vtkPlumeShaderFeatures Features;
    vtkPlumeShaderFeatures CoarseFeatures;
    vtkPlumeShaderFeatures ClassifyFeatures;
    vtkPlumeShaderFeatures RefineFeatures;
    vtkShaderProgram* Program = nullptr;
    vtkShaderProgram* Coarse = nullptr;   // lattice rays (Lattice > 1)
    vtkShaderProgram* Classify = nullptr; // lattice cells (Lattice > 1)
    vtkShaderProgram* Refine = nullptr;   // interpolated cells (Lattice > 1)
  };

  // The render steps, in order (Render() calls them); false: stop (an error
  // was reported, or there is nothing to draw).
  bool UpdateResources(vtkPlumeVolumeMapper* self, Frame& frame);
  bool UpdateBlocks(vtkPlumeVolumeMapper* self, Frame& frame);
  void AcquireDepth(vtkPlumeVolumeMapper* self, Frame& frame);
  bool ComputeFrame(vtkPlumeVolumeMapper* self, Frame& frame);
  void GatherLights(vtkPlumeVolumeMapper* self, Frame& frame);
  bool ReadyPrograms(vtkPlumeVolumeMapper* self, Frame& frame);
  bool UpdateLightVolume(vtkPlumeVolumeMapper* self, Frame& frame);
  void SetUniforms(vtkPlumeVolumeMapper* self, Frame& frame, vtkShaderProgram* program);
  void Draw(vtkPlumeVolumeMapper* self, Frame& frame);

  void ReleaseGraphicsResources(vtkWindow* window)
  {
    this->Scalars->ReleaseGraphicsResources(window);
    this->Depth->ReleaseGraphicsResources(window);
    this->Table->ReleaseGraphicsResources(window);
    this->Integral->ReleaseGraphicsResources(window);
    this->Occupancy->ReleaseGraphicsResources(window);
    this->OccupancyUpload = this->OccupancyTable = -1;
    this->BlockRanges->ReleaseGraphicsResources(window);
    this->RangesUpload = -1;
    this->EmptyVAO->ReleaseGraphicsResources();
    this->Lattice->ReleaseGraphicsResources(window);
    this->Cells->ReleaseGraphicsResources(window);
    this->LatticeFBO->ReleaseGraphicsResources(window);
    this->Programs->ReleaseGraphicsResources(window);
    this->LightVolume->ReleaseGraphicsResources(window);
    this->Window = nullptr;
    this->AutomaticBudgetMB = 0;
  }
};

//------------------------------------------------------------------------------
vtkPlumeVolumeMapper::vtkPlumeVolumeMapper()
  : IsoValue(std::numeric_limits<double>::quiet_NaN())
  , Impl(new Internals)
{
  GetParameterTable().ApplyDefaults(this);
}

vtkPlumeVolumeMapper::~vtkPlumeVolumeMapper() = default;

int vtkPlumeVolumeMapper::GetUploadCount()
{
  return this->Impl->Scalars->GetUploadCount();
}

int vtkPlumeVolumeMapper::GetHandOverCount()
{
  return this->Impl->Scalars->GetHandOverCount();
}

int vtkPlumeVolumeMapper::GetLightVolumeUpdateCount()
{
  return this->Impl->LightVolume->GetUpdateCount();
}

vtkTextureObject* vtkPlumeVolumeMapper::GetLightVolumeTexture()
{
  return this->Impl->LightVolume->GetTextureObject();
}

int vtkPlumeVolumeMapper::GetNumberOfProfiledPasses()
{
  return this->Impl->Profiler.GetNumberOfPasses();
}

const char* vtkPlumeVolumeMapper::GetProfiledPassName(int pass)
{
  return this->Impl->Profiler.GetPassName(pass);
}

double vtkPlumeVolumeMapper::GetProfiledPassSeconds(int pass)
{
  return this->Impl->Profiler.GetPassSeconds(pass);
}

double vtkPlumeVolumeMapper::GetProfiledPassCPUSeconds(int pass)
{
  return this->Impl->Profiler.GetPassCPUSeconds(pass);
}

//------------------------------------------------------------------------------
std::string vtkPlumeVolumeMapper::CheckTextureBudget(
  const int dims[3], bool masked, bool shaded, double budgetMB)
{
  const double bytes = GetTextureBytes(dims, masked, shaded);
  if (bytes <= budgetMB * Megabyte)
  {
    return std::string();
  }
  std::ostringstream msg;
  msg << "volume " << dims[0] << "x" << dims[1] << "x" << dims[2] << " needs " << MB(bytes / Megabyte)
      << " MB of 3D texture (" << (shaded ? 16 : (masked ? 8 : 4))
      << " bytes per point), over the texture memory budget of " << MB(budgetMB)
      << " MB; resample the data to a coarser image";
  return msg.str();
}

void vtkPlumeVolumeMapper::SetRenderMode(int mode)
{
  mode = std::min(std::max(mode, static_cast<int>(RENDER_COMPOSITE)), static_cast<int>(RENDER_SMOKE));
  const int blend = mode == RENDER_MIP ? MAXIMUM_INTENSITY_BLEND
    : mode == RENDER_ISOSURFACE        ? ISOSURFACE_BLEND
                                       : COMPOSITE_BLEND;
  this->SetBlendMode(blend);
  this->SetSmoke(mode == RENDER_SMOKE);
}

int vtkPlumeVolumeMapper::GetRenderMode()
{
  if (this->BlendMode == MAXIMUM_INTENSITY_BLEND)
  {
    return RENDER_MIP;
  }
  if (this->BlendMode == ISOSURFACE_BLEND)
  {
    return RENDER_ISOSURFACE;
  }
  return this->Smoke ? RENDER_SMOKE : RENDER_COMPOSITE;
}

const vtkPlumeParameterTable& vtkPlumeVolumeMapper::GetParameterTable()
{
  static const vtkPlumeParameterTable table = [] {
    using T = vtkPlumeVolumeMapper;
    vtkPlumeParameterTable t("vtkPlumeVolumeMapper", "volume");
    t.Choice("mode", "RenderMode", "composite")
      .Choice("composite", RENDER_COMPOSITE, "emission-absorption with the transfer functions.")
      .Choice("mip", RENDER_MIP, "maximum intensity.")
      .Choice("isosurface", RENDER_ISOSURFACE, "first crossing of the iso value, Phong-lit.")
      .Choice("smoke", RENDER_SMOKE, "emission-absorption lit by the scene's lights with self-shadowing.")
      .Doc("How rays combine their samples.")
      .Bind(&T::SetRenderMode, &T::GetRenderMode);
    t.Real("iso_value", "IsoValue", 0.0)
      .OnlyWith("mode", { "isosurface" })
      .Automatic("the middle of the colour map's range; in C++ the volume property's first iso value if it holds anything but VTK's default (a single 0) or UsePropertyIsoValue is on")
      .Units("data units")
      .Panel("Isosurface")
      .Doc("Value whose first crossing the isosurface mode draws.")
      .Bind(&T::SetIsoValue, &T::GetIsoValue);
    t.Integer("component", "ScalarComponent", -1)
      .Between(-1, 1 << 20)
      .Doc("Component of a multi-component array; -1: the only one, or the magnitude.")
      .Bind(&T::SetScalarComponent, &T::GetScalarComponent);
    t.Real("sample_distance", "SampleDistance", 0.5)
      .Between(1e-3, 100.0)
      .Units("voxels")
      .Panel("Quality")
      .Doc("Step along rays.")
      .Bind(&T::SetSampleDistance, &T::GetSampleDistance);
    t.Integer("image_sample_distance", "ImageSampleDistance", 1)
      .Between(1, 16)
      .Units("pixels")
      .Panel("Quality")
      .Doc("Ray lattice: one ray every this many pixels, interpolated where neighbours agree, refined where not (1: every pixel).")
      .Bind(&T::SetImageSampleDistance, &T::GetImageSampleDistance);
    t.Integer("interactive_image_sample_distance", "InteractiveImageSampleDistance", 2)
      .Between(1, 16)
      .Units("pixels")
      .Panel("Quality")
      .Doc("The ray lattice while the camera moves (with auto_adjust_sample_distances).")
      .Bind(&T::SetInteractiveImageSampleDistance, &T::GetInteractiveImageSampleDistance);
    t.Boolean("auto_adjust_sample_distances", "AutoAdjustSampleDistances", true)
      .Panel("Quality")
      .Doc("Use the interactive ray lattice while the volume's allocated render time is below 1 s (VTK's interaction).")
      .Bind(&T::SetAutoAdjustSampleDistances, &T::GetAutoAdjustSampleDistances);
    t.Real("lattice_tolerance", "LatticeTolerance", 0.004)
      .Between(0.0, 1.0)
      .Panel("Quality")
      .Advanced()
      .Doc("Ray lattice: neighbouring rays that differ by more than this (any channel) make a pixel cast its own ray.")
      .Bind(&T::SetLatticeTolerance, &T::GetLatticeTolerance);
    t.Boolean("jitter", "Jitter", true)
      .Panel("Quality")
      .Doc("Per-pixel jitter of the first step (no wood-grain).")
      .Bind(&T::SetJitter, &T::GetJitter);
    t.Boolean("animated_jitter", "AnimatedJitter", false)
      .Panel("Quality")
      .Advanced()
      .Doc("A new jitter pattern every frame (else a fixed one).")
      .Bind(&T::SetAnimatedJitter, &T::GetAnimatedJitter);
    t.Real("termination_error", "TerminationError", 0.001)
      .Between(0.0, 0.5)
      .Panel("Quality")
      .Advanced()
      .Doc("Early ray termination: the most a stopped ray may change a pixel, of full scale (0: never stop).")
      .Bind(&T::SetTerminationError, &T::GetTerminationError);
    t.Real("opacity_unit_distance", "OpacityUnitDistance", 0.0)
      .Between(0.0, 1e30)
      .Units("world units")
      .Doc("Length over which a sample's opacity applies (opacity is corrected for the actual step); 0: the volume property's, which the command line and ParaView leave at 0: the mean voxel spacing.")
      .Bind(&T::SetOpacityUnitDistance, &T::GetOpacityUnitDistance);
    t.Real("shadow_sample_distance", "ShadowSampleDistance", 1.0)
      .OnlyWith("mode", { "smoke" })
      .Between(0.05, 100.0)
      .Units("voxels")
      .Panel("Quality")
      .Doc("Step of the smoke's shadow rays.")
      .Bind(&T::SetShadowSampleDistance, &T::GetShadowSampleDistance);
    t.Boolean("light_cache", "LightCache", true)
      .OnlyWith("mode", { "smoke" })
      .Panel("Quality")
      .Advanced()
      .Doc("Smoke: the transmittance towards each light kept per grid node and interpolated, recomputed only when the lights, data or transfer function change (off: a shadow ray per sample).")
      .Bind(&T::SetLightCache, &T::GetLightCache);
    t.Boolean("opaque_depth", "UseOpaqueDepth", true)
      .Panel("Compositing")
      .Doc("Rays stop at opaque geometry (surfaces, contours, spheres, glyphs).")
      .Bind(&T::SetUseOpaqueDepth, &T::GetUseOpaqueDepth);
    t.Boolean("empty_space_skipping", "EmptySpaceSkipping", true)
      .Panel("Quality")
      .Advanced()
      .Doc("Jump over 8^3 blocks that cannot change the result (same image).")
      .Bind(&T::SetEmptySpaceSkipping, &T::GetEmptySpaceSkipping);
    t.Boolean("pre_integration", "PreIntegration", false)
      .OnlyWith("mode", { "composite" })
      .Panel("Quality")
      .Doc("Composite mode: pre-integrated transfer functions (exact segment opacity for a value linear between samples), for sharp transfer functions at long steps.")
      .Bind(&T::SetPreIntegration, &T::GetPreIntegration);
    t.Boolean("mip_skipping", "MIPSkipping", false)
      .OnlyWith("mode", { "mip" })
      .Panel("Quality")
      .Advanced()
      .Doc("Empty-space skipping in MIP mode too (slower on llvmpipe, measured).")
      .Bind(&T::SetMIPSkipping, &T::GetMIPSkipping);
    t.Text("mask_array", "ValidMaskArrayName", "vtkValidPointMask")
      .Advanced()
      .Doc("Point array whose zeros mark nodes outside the data (resampled data); they draw nothing.")
      .Bind(&T::SetValidMaskArrayName, &T::GetValidMaskArrayName);
    t.Real("texture_memory_budget_mb", "TextureMemoryBudgetMB", 0.0)
      .Between(0.0, 1e12)
      .Units("MB")
      .Advanced()
      .Doc("Largest 3D texture; larger volumes are refused, never cropped (0: half the memory).")
      .Bind(&T::SetTextureMemoryBudgetMB, &T::GetTextureMemoryBudgetMB);
    return t;
  }();
  return table;
}

//------------------------------------------------------------------------------
double vtkPlumeVolumeMapper::GetAutomaticOpacityUnitDistance(vtkImageData* image)
{
  double spacing[3] = { 1, 1, 1 };
  if (image)
  {
    image->GetSpacing(spacing);
  }
  const double mean = (std::fabs(spacing[0]) + std::fabs(spacing[1]) + std::fabs(spacing[2])) / 3;
  return mean > 0 && std::isfinite(mean) ? mean : 1.0;
}

void vtkPlumeVolumeMapper::ApplyDefaultLighting(vtkVolumeProperty* property)
{
  if (!property)
  {
    return;
  }
  const bool smoke = this->GetRenderMode() == RENDER_SMOKE;
  property->SetAmbient(smoke ? 0.3 : 0.15);
  property->SetDiffuse(smoke ? 1.0 : 0.75);
  property->SetSpecular(0.3);
  property->SetSpecularPower(20.0);
}

double vtkPlumeVolumeMapper::GetAutomaticIsoValue(vtkVolumeProperty* property, const double range[2])
{
  // the middle of the colour map (what the user sees coloured), else of the range
  double r[2] = { 0, 0 };
  if (property && property->GetColorChannels(0) == 1 && property->GetGrayTransferFunction(0))
  {
    property->GetGrayTransferFunction(0)->GetRange(r);
  }
  else if (property && property->GetRGBTransferFunction(0))
  {
    property->GetRGBTransferFunction(0)->GetRange(r);
  }
  if (!(r[0] < r[1]) || !std::isfinite(r[1] - r[0]))
  {
    r[0] = range[0];
    r[1] = range[1];
  }
  return r[0] + 0.5 * (r[1] - r[0]);
}

//------------------------------------------------------------------------------
double vtkPlumeVolumeMapper::GetTextureBytes(const int dimensions[3], bool masked, bool shaded)
{
  // R32F scalars, RG32F with a valid-point mask, RGBA32F when shaded without
  // one (value and gradient; counted whenever shaded: an upper bound) + the
  // 8-bit block occupancy and RG32F block ranges (8³ blocks)
  const double nodes = double(std::max(dimensions[0], 1)) * std::max(dimensions[1], 1) * std::max(dimensions[2], 1);
  double blocks = 1;
  for (int a = 0; a < 3; ++a)
  {
    blocks *= std::max(1, (dimensions[a] - 1 + 7) / 8);
  }
  return (shaded ? 16.0 : (masked ? 8.0 : 4.0)) * nodes + 9.0 * blocks;
}

//------------------------------------------------------------------------------
double* vtkPlumeVolumeMapper::GetBounds()
{
  vtkImageData* image = vtkImageData::SafeDownCast(this->GetInput());
  if (!image)
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return this->Bounds;
  }
  if (this->GetNumberOfInputConnections(0) > 0)
  {
    this->GetInputAlgorithm()->Update();
    image = vtkImageData::SafeDownCast(this->GetInput());
  }
  int extent[6];
  image->GetExtent(extent);
  double lo[3], hi[3];
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = extent[2 * a];
    hi[a] = extent[2 * a + 1];
    if (hi[a] <= lo[a])
    {
      lo[a] -= 0.5;
      hi[a] = lo[a] + 1.0;
    }
  }
  // corners of the index box through the image's index -> physical map
  vtkMath::UninitializeBounds(this->Bounds);
  bool first = true;
  for (int c = 0; c < 8; ++c)
  {
    const double ijk[3] = { (c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1],
      (c & 4) ? hi[2] : lo[2] };
    double xyz[3];
    image->TransformContinuousIndexToPhysicalPoint(ijk, xyz);
    for (int a = 0; a < 3; ++a)
    {
      if (first || xyz[a] < this->Bounds[2 * a])
      {
        this->Bounds[2 * a] = xyz[a];
      }
      if (first || xyz[a] > this->Bounds[2 * a + 1])
      {
        this->Bounds[2 * a + 1] = xyz[a];
      }
    }
    first = false;
  }
  return this->Bounds;
}

//------------------------------------------------------------------------------
void vtkPlumeVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  Internals& impl = *this->Impl;
  if (ren->GetSelector())
  {
    return; // hardware selection is not supported
  }
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!renWin)
  {
    vtkErrorMacro(<< "an OpenGL render window is required");
    return;
  }
  if (this->GetNumberOfInputConnections(0) > 0)
  {
    this->GetInputAlgorithm()->Update();
  }
  vtkImageData* image = vtkImageData::SafeDownCast(this->GetInput());
  if (!image)
  {
    vtkErrorMacro(<< "no input image");
    return;
  }
  // arrays shorter than the grid would be read past their end by the upload
  const std::string invalid = vtkPlumeInputValidation::CheckArrays(image);
  if (!invalid.empty())
  {
    vtkErrorMacro(<< "invalid input image, not drawn: " << invalid);
    return;
  }
  int cellFlag = 0;
  vtkDataArray* scalars = this->GetScalars(
    image, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
  if (!scalars)
  {
    vtkErrorMacro(<< "the input image has no scalars to render"
                  << (this->ArrayAccessMode == VTK_GET_ARRAY_BY_NAME && this->ArrayName
                         ? std::string(" (no point array named '") + this->ArrayName + "')"
                         : std::string()));
    return;
  }
  if (cellFlag)
  {
    vtkErrorMacro(<< "cell scalars are not supported; use point data (e.g. vtkCellDataToPointData)");
    return;
  }
  plume::ReleaseOnWindowChange(impl, renWin);

  impl.Profiler.SetEnabled(this->ProfilePasses);
  impl.Profiler.Start();
  Internals::Frame frame;
  frame.Renderer = ren;
  frame.Volume = vol;
  frame.Window = renWin;
  frame.Image = image;
  frame.Scalars = scalars;
  if (!impl.UpdateResources(this, frame) || !impl.UpdateBlocks(this, frame))
  {
    return;
  }
  impl.Profiler.Mark("resources");
  impl.AcquireDepth(this, frame);
  impl.Profiler.Mark("depth");
  if (!impl.ComputeFrame(this, frame))
  {
    return;
  }
  impl.GatherLights(this, frame);
  if (!impl.ReadyPrograms(this, frame))
  {
    return;
  }
  if (!impl.UpdateLightVolume(this, frame))
  {
    return;
  }
  impl.Profiler.Mark("setup");
  impl.Draw(this, frame);
  ++impl.FrameCount;
}


//------------------------------------------------------------------------------
// Step 1: the scalars on the GPU (upload or hand-over, only when they changed;
// refused over the texture budget) and the transfer-function table over the
// transfer functions' range (only when the property or the range changed).
bool vtkPlumeVolumeMapper::Internals::UpdateResources(vtkPlumeVolumeMapper* self, Frame& frame)
{
  vtkImageData* image = frame.Image;
  vtkVolume* vol = frame.Volume;
  vtkOpenGLRenderWindow* renWin = frame.Window;
  // ---- texture-memory budget: refuse (never crop) what does not fit
  if (!(this->AutomaticBudgetMB > 0))
  {
    this->AutomaticBudgetMB = ::AutomaticBudgetMB(renWin); // once per window
  }
  self->EffectiveTextureMemoryBudgetMB =
    self->TextureMemoryBudgetMB > 0 ? self->TextureMemoryBudgetMB : this->AutomaticBudgetMB;
  // nodes outside the data (valid-point mask, one component): a (u w, w)
  // texture; shaded composite: the gradient comes with the value, one
  // look-up per sample (RGBA). See vtkPlumeScalarTexture3D.
  vtkDataArray* mask = self->ValidMaskArrayName.empty()
    ? nullptr
    : image->GetPointData()->GetArray(self->ValidMaskArrayName.c_str());
  if (mask && mask->GetNumberOfComponents() != 1)
  {
    mask = nullptr;
  }
  // (the composite mode also serves blend modes the mapper has no mode of its own for)
  frame.Mask = mask;
  const bool shade = self->BlendMode != MAXIMUM_INTENSITY_BLEND && self->BlendMode != ISOSURFACE_BLEND &&
    !self->Smoke && vol->GetProperty()->GetShade(0) != 0;
  {
    int dims[3];
    image->GetDimensions(dims);
    // masked: the mask's (cached) range includes 0
    const bool maybeMasked = mask && mask->GetRange(0)[0] <= 0.0 && mask->GetRange(0)[1] >= 0.0;
    const std::string over =
      CheckTextureBudget(dims, maybeMasked, shade, self->EffectiveTextureMemoryBudgetMB);
    if (!over.empty())
    {
      vtkErrorWithObjectMacro(self, << over << " (SetTextureMemoryBudgetMB)");
      return false;
    }
  }

  // ---- 3D texture (only when the data changed)
  this->Scalars->SetGradients(shade);
  frame.Shade = shade;
  if (!this->Scalars->Update(renWin, image, frame.Scalars, self->ScalarComponent, mask))
  {
    vtkErrorWithObjectMacro(self, << this->Scalars->GetLastError());
    return false;
  }
  // the transfer functions' range: the data's unless set; the texture's raw
  // values are mapped to it by a scale and bias (a range change uploads nothing)
  double* range = frame.Range;
  range[0] = this->Scalars->GetScalarRange()[0];
  range[1] = this->Scalars->GetScalarRange()[1];
  if (self->TransferFunctionRange[0] < self->TransferFunctionRange[1])
  {
    range[0] = self->TransferFunctionRange[0];
    range[1] = self->TransferFunctionRange[1];
  }
  this->Scalars->GetScaleBias(range, frame.ScaleBias);

  // ---- transfer-function table (only when the property or range changed)
  vtkVolumeProperty* property = vol->GetProperty();
  frame.Property = property;
  vtkColorTransferFunction* color = property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* gray =
    property->GetColorChannels(0) == 1 ? property->GetGrayTransferFunction(0) : nullptr;
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  // the opacity unit distance: ours if set, else the property's (VTK's
  // contract, its default 1 included: a user's 1 is a length like any other),
  // else, for a property at 0 (automatic), one voxel (the image's mean spacing)
  double unit = self->OpacityUnitDistance;
  if (!(unit > 0))
  {
    unit = property->GetScalarOpacityUnitDistance(0);
  }
  if (!(unit > 0) || !std::isfinite(unit))
  {
    unit = vtkPlumeVolumeMapper::GetAutomaticOpacityUnitDistance(image);
  }
  self->EffectiveOpacityUnitDistance = unit;
  if (unit != this->TableUnit)
  {
    this->TableUnit = unit; // the table's extinction depends on it
    this->TableUnitTime.Modified();
  }
  const vtkMTimeType tfTime = std::max({ property->GetMTime(), color->GetMTime(),
    opacity->GetMTime(), gray ? gray->GetMTime() : vtkMTimeType(0), this->TableUnitTime.GetMTime() });
  const double invUnit = unit > 0 ? 1.0 / unit : 1.0;
  frame.InvUnit = invUnit;
  const int uploads = this->Table->GetUploadCount();
  if (!this->Table->Update(renWin, property, tfTime, range, TableSize, [&](double v, float rgba[4]) {
        double rgb[3];
        if (gray)
        {
          rgb[0] = rgb[1] = rgb[2] = gray->GetValue(v);
        }
        else
        {
          color->GetColor(v, rgb);
        }
        for (int c = 0; c < 3; ++c)
        {
          rgba[c] = static_cast<float>(std::isfinite(rgb[c]) ? rgb[c] : 0.0);
        }
        // alpha channel: extinction per world unit (no log per sample in the shader)
        const double a = opacity->GetValue(v);
        const double alpha = std::isfinite(a) ? std::min(1.0 - 1e-6, std::max(0.0, a)) : 0.0;
        rgba[3] = static_cast<float>(-std::log(1.0 - alpha) * invUnit);
      }))
  {
    vtkErrorWithObjectMacro(self, << "could not create the transfer-function texture");
    return false;
  }
  if (this->Table->GetUploadCount() != uploads)
  {
    ++self->TableCount; // the occupancy summary depends on it
  }

  // ---- pre-integration: running integrals over u (0..1 across the table) of
  // c sigma and sigma, trapezoids of the linearly interpolated table (exact
  // for it), in double; re-made only with the table (same source and time)
  frame.PreInt = self->PreIntegration && self->BlendMode == COMPOSITE_BLEND && !self->Smoke && !shade &&
    !this->Scalars->GetMasked();
  self->LastPreIntegration = frame.PreInt;
  if (frame.PreInt)
  {
    const std::vector<float>& table = this->Table->GetTable();
    std::vector<double> running;
    const double h = 1.0 / (TableSize - 1);
    const auto integrate = [&] {
    running.assign(4 * TableSize, 0.0);
    for (int i = 1; i < TableSize; ++i)
    {
      const float* a = &table[4 * (i - 1)];
      const float* b = &table[4 * i];
      for (int c = 0; c < 3; ++c)
      {
        running[4 * i + c] = running[4 * (i - 1) + c] + 0.5 * h * (double(a[c]) * a[3] + double(b[c]) * b[3]);
      }
      running[4 * i + 3] = running[4 * (i - 1) + 3] + 0.5 * h * (double(a[3]) + b[3]);
    }
    };
    const double span = range[1] - range[0];
    if (!this->Integral->Update(renWin, property, tfTime, range, TableSize, [&](double v, float rgba[4]) {
          if (running.empty())
          {
            integrate(); // only when the texture is out of date
          }
          // the entries are asked for at the table's nodes
          const double x = span > 0 ? (v - range[0]) / span * (TableSize - 1) : 0.0;
          const int i = std::min(TableSize - 1, std::max(0, static_cast<int>(std::lround(x))));
          for (int c = 0; c < 4; ++c)
          {
            rgba[c] = static_cast<float>(running[4 * i + c]);
          }
        }))
    {
      vtkErrorWithObjectMacro(self, << "could not create the pre-integration texture");
      return false;
    }
  }

  return true;
}

//------------------------------------------------------------------------------
// Step 2: the empty-space summaries derived from the block ranges and the
// table (only when either changed): composite, the occupancy of each block and
// the box around the occupied ones; MIP and isosurface, the block ranges in u.
bool vtkPlumeVolumeMapper::Internals::UpdateBlocks(vtkPlumeVolumeMapper* self, Frame& frame)
{
  // ---- empty-space skipping: blocks whose value range has zero opacity everywhere
  vtkOpenGLRenderWindow* renWin = frame.Window;
  const double* scaleBias = frame.ScaleBias;
  // (pre-integrated segments are skipped only where they lie wholly in
  // transparent blocks: SKIP_PREINT)
  const bool skipping = self->EmptySpaceSkipping && self->BlendMode == COMPOSITE_BLEND;
  if (skipping && (this->OccupancyUpload != this->Scalars->GetDataVersion() ||
                    this->OccupancyTable != self->TableCount || !this->Occupancy->GetHandle()))
  {
    // prefix count of table entries with non-zero extinction
    std::vector<int> prefix(TableSize + 1, 0);
    for (int i = 0; i < TableSize; ++i)
    {
      prefix[i + 1] = prefix[i] + (this->Table->GetTable()[4 * i + 3] > 0.0f ? 1 : 0);
    }
    const int* bd = this->Scalars->GetBlockDimensions();
    const std::vector<float>& ranges = this->Scalars->GetBlockRanges();
    std::vector<unsigned char> occupied(ranges.size() / 2);
    size_t empty = 0;
    for (size_t b = 0; b < occupied.size(); ++b)
    {
      if (ranges[2 * b] > ranges[2 * b + 1])
      {
        occupied[b] = 0; // no valid node
        ++empty;
        continue;
      }
      // table entries touched by linear interpolation of u in [min, max]
      // (u beyond [0, 1] reads the end entries: the table is clamped)
      const double u0 = ranges[2 * b] * scaleBias[0] + scaleBias[1];
      const double u1 = ranges[2 * b + 1] * scaleBias[0] + scaleBias[1];
      const int i0 = static_cast<int>(std::min(double(TableSize - 1), std::max(0.0, std::floor(std::min(u0, u1) * (TableSize - 1)))));
      const int i1 = static_cast<int>(std::min(double(TableSize - 1), std::max(0.0, std::ceil(std::max(u0, u1) * (TableSize - 1)))));
      occupied[b] = prefix[i1 + 1] - prefix[i0] > 0 ? 255 : 0;
      empty += occupied[b] ? 0 : 1;
    }
    this->Occupancy->SetContext(renWin);
    this->Occupancy->SetWrapS(vtkTextureObject::ClampToEdge);
    this->Occupancy->SetWrapT(vtkTextureObject::ClampToEdge);
    this->Occupancy->SetWrapR(vtkTextureObject::ClampToEdge);
    this->Occupancy->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Occupancy->SetMagnificationFilter(vtkTextureObject::Nearest);
    if (occupied.empty() ||
      !this->Occupancy->Create3DFromRaw(bd[0], bd[1], bd[2], 1, VTK_UNSIGNED_CHAR, occupied.data()))
    {
      vtkErrorWithObjectMacro(self, << "could not create the empty-space texture");
      return false;
    }
    // index-space bounds of the non-transparent blocks
    this->OccupiedBlocks = occupied.size() - empty;
    int lo[3] = { bd[0], bd[1], bd[2] }, hi[3] = { -1, -1, -1 };
    for (int k = 0; k < bd[2]; ++k)
    {
      for (int j = 0; j < bd[1]; ++j)
      {
        for (int i = 0; i < bd[0]; ++i)
        {
          if (occupied[i + static_cast<size_t>(bd[0]) * (j + static_cast<size_t>(bd[1]) * k)])
          {
            const int ijk[3] = { i, j, k };
            for (int a = 0; a < 3; ++a)
            {
              lo[a] = std::min(lo[a], ijk[a]);
              hi[a] = std::max(hi[a], ijk[a]);
            }
          }
        }
      }
    }
    const double b = this->Scalars->GetBlockSize();
    for (int a = 0; a < 3; ++a)
    {
      this->OccupiedMin[a] = hi[a] >= 0 ? lo[a] * b : 0.0;
      this->OccupiedMax[a] = hi[a] >= 0 ? (hi[a] + 1) * b : 0.0;
    }
    this->OccupancyUpload = this->Scalars->GetDataVersion();
    this->OccupancyTable = self->TableCount;
    this->EmptyFraction = occupied.empty() ? 0.0 : double(empty) / occupied.size();
  }
  // MIP and isosurface skip by value range (decided per ray in the shader against
  // the running maximum or the iso value): upload the block ranges
  const bool rangeSkipping = self->EmptySpaceSkipping &&
    ((self->BlendMode == MAXIMUM_INTENSITY_BLEND && self->MIPSkipping) || self->BlendMode == ISOSURFACE_BLEND);
  if (rangeSkipping && (this->RangesUpload != this->Scalars->GetDataVersion() || !this->BlockRanges->GetHandle() ||
                         this->RangesScaleBias[0] != scaleBias[0] || this->RangesScaleBias[1] != scaleBias[1]))
  {
    const int* bd = this->Scalars->GetBlockDimensions();
    // in u, as the shader's samples are (a block with no valid node: (1, 0), never entered)
    std::vector<float> ranges = this->Scalars->GetBlockRanges();
    for (size_t b = 0; 2 * b + 1 < ranges.size(); ++b)
    {
      if (ranges[2 * b] > ranges[2 * b + 1])
      {
        ranges[2 * b] = 1.0f;
        ranges[2 * b + 1] = 0.0f;
        continue;
      }
      const float u0 = static_cast<float>(ranges[2 * b] * scaleBias[0] + scaleBias[1]);
      const float u1 = static_cast<float>(ranges[2 * b + 1] * scaleBias[0] + scaleBias[1]);
      ranges[2 * b] = std::min(u0, u1);
      ranges[2 * b + 1] = std::max(u0, u1);
    }
    this->BlockRanges->SetContext(renWin);
    this->BlockRanges->SetWrapS(vtkTextureObject::ClampToEdge);
    this->BlockRanges->SetWrapT(vtkTextureObject::ClampToEdge);
    this->BlockRanges->SetWrapR(vtkTextureObject::ClampToEdge);
    this->BlockRanges->SetMinificationFilter(vtkTextureObject::Nearest);
    this->BlockRanges->SetMagnificationFilter(vtkTextureObject::Nearest);
    if (ranges.empty() ||
      !this->BlockRanges->Create3DFromRaw(bd[0], bd[1], bd[2], 2, VTK_FLOAT, ranges.data()))
    {
      vtkErrorWithObjectMacro(self, << "could not create the block-range texture");
      return false;
    }
    this->RangesUpload = this->Scalars->GetDataVersion();
    this->RangesScaleBias[0] = scaleBias[0];
    this->RangesScaleBias[1] = scaleBias[1];
  }
  // MIP decides per ray (0 here); the isosurface's fraction is set with its iso value below
  self->EmptyBlockFraction = skipping ? this->EmptyFraction : 0.0;
  // (almost) no transparent block, a dense field: the in-shader look-up per block
  // costs more than it saves (measured on the bench's dense field, 0.1 % empty:
  // +25 % time; sparse smoke, 67 % empty: -40 %), so below 10 % the shader leaves
  // it out (only the box around the non-transparent blocks is drawn); same image
  const bool skipTransparent = skipping && this->EmptyFraction >= MinSkipFraction;
  frame.Skipping = skipping;
  frame.RangeSkipping = rangeSkipping;
  frame.SkipTransparent = skipTransparent;

  return true;
}

//------------------------------------------------------------------------------
// Step 3: the opaque scene's depth (the frame's shared copy under a
// vtkPlumeCompositingPass, else our own copy of the depth buffer).
void vtkPlumeVolumeMapper::Internals::AcquireDepth(vtkPlumeVolumeMapper* self, Frame& frame)
{
  // ---- opaque depth
  // (the frame's shared copy under a vtkPlumeCompositingPass, else our own).
  // With no other prop that may write depth it is the far plane everywhere
  // and is not read: the rays end where they would; the copy and the lattice
  // cells' per-pixel depth checks cost more than the lattice's rays, and the
  // far plane's points clamped to the box are not bilinear along the box's
  // silhouette, which refined cells there for nothing (lattice 8 at 512^2:
  // at least 12 481 rays, now 4 225 where the colours agree)
  const bool wanted =
    self->UseOpaqueDepth && vtkPlumeCompositingPass::HasOtherDepthWriters(frame.Renderer, frame.Volume);
  vtkPlumeOpaqueDepthTexture* depth =
    wanted ? vtkPlumeCompositingPass::AcquireDepth(frame.Renderer, this->Depth) : nullptr;
  const bool useDepth = depth != nullptr;
  frame.Depth = depth;
  frame.UseDepth = useDepth;
  self->LastOpaqueDepth = useDepth;
  if (wanted)
  {
    if (!useDepth)
    {
      vtkWarningWithObjectMacro(self, << "rays will not stop at opaque geometry: "
                      << (this->Depth->GetLastError().empty() ? std::string("the compositing pass has no depth")
                                                             : this->Depth->GetLastError()));
    }
  }

}

//------------------------------------------------------------------------------
// Step 4: index -> data -> world -> clip in double (the image's direction
// matrix and the volume's transform honoured), the box and the part of it drawn.
bool vtkPlumeVolumeMapper::Internals::ComputeFrame(vtkPlumeVolumeMapper* self, Frame& frame)
{
  // ---- matrices, in double: index -> data -> world -> clip
  vtkImageData* image = frame.Image;
  vtkRenderer* ren = frame.Renderer;
  const bool skipping = frame.Skipping;
  int* dims = frame.Dims;
  int extent[6];
  image->GetDimensions(dims);
  image->GetExtent(extent);
  double indexToData[16];
  plume::IndexToPhysical(image, indexToData);
  double indexToWorld[16];
  vtkMatrix4x4::Multiply4x4(frame.Volume->GetMatrix()->GetData(), indexToData, indexToWorld);
  double aspect[2];
  const double tiledAspect = ren->GetTiledAspectRatio();
  aspect[0] = tiledAspect;
  aspect[1] = 1.0;
  vtkCamera* camera = ren->GetActiveCamera();
  double worldToClip[16];
  {
    vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(aspect[0], -1, 1);
    std::copy(m->GetData(), m->GetData() + 16, worldToClip);
  }
  double* indexToClip = frame.IndexToClip;
  double* clipToIndex = frame.ClipToIndex;
  vtkMatrix4x4::Multiply4x4(worldToClip, indexToWorld, indexToClip);
  vtkMatrix4x4::Invert(indexToClip, clipToIndex);
  for (int i = 0; i < 16; ++i)
  {
    if (!std::isfinite(clipToIndex[i]))
    {
      vtkErrorWithObjectMacro(self, << "degenerate volume or camera transform (not invertible)");
      return false;
    }
  }
  double* linear = frame.Linear;
  double* normal = frame.Normal;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      linear[3 * r + c] = indexToWorld[4 * r + c];
    }
  }
  frame.Det = vtkMatrix3x3::Determinant(linear);
  {
    double inv[9];
    vtkMatrix3x3::Invert(linear, inv);
    vtkMatrix3x3::Transpose(inv, normal);
  }
  float* boxMin = frame.BoxMin;
  float* boxMax = frame.BoxMax;
  float* fdims = frame.FDims;
  float* drawMin = frame.DrawMin;
  float* drawMax = frame.DrawMax;
  for (int a = 0; a < 3; ++a)
  {
    boxMin[a] = dims[a] > 1 ? 0.0f : -0.5f;
    boxMax[a] = dims[a] > 1 ? static_cast<float>(dims[a] - 1) : 0.5f;
    fdims[a] = static_cast<float>(dims[a]);
    // with skipping, only the bounds of the non-transparent blocks are drawn
    drawMin[a] = skipping ? std::max(boxMin[a], static_cast<float>(this->OccupiedMin[a])) : boxMin[a];
    drawMax[a] = skipping ? std::min(boxMax[a], static_cast<float>(this->OccupiedMax[a])) : boxMax[a];
    if (skipping && dims[a] == 1)
    {
      drawMin[a] = boxMin[a];
      drawMax[a] = boxMax[a];
    }
  }
  if (skipping && this->OccupiedBlocks == 0)
  {
    return false; // everything is transparent: nothing to draw
  }

  return true;
}

//------------------------------------------------------------------------------
// Step 5: the shader mode and the renderer's lights (up to MaxLights; lit
// modes with none switched on are lit from the camera).
void vtkPlumeVolumeMapper::Internals::GatherLights(vtkPlumeVolumeMapper* self, Frame& frame)
{
  // ---- lights (world directions towards the light)
  std::vector<std::array<double, 3>>& lightDirs = frame.LightDirs;
  std::vector<std::array<double, 3>>& lightColors = frame.LightColors;
  {
    vtkLightCollection* lights = frame.Renderer->GetLights();
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* light = lights->GetNextLight(it))
    {
      if (!light->GetSwitch() || static_cast<int>(lightDirs.size()) >= MaxLights)
      {
        continue;
      }
      double p[3], f[3];
      light->GetTransformedPosition(p);
      light->GetTransformedFocalPoint(f);
      std::array<double, 3> l = { p[0] - f[0], p[1] - f[1], p[2] - f[2] };
      const double n = vtkMath::Norm(l.data());
      if (!(n > 0) || !std::isfinite(n))
      {
        continue;
      }
      for (double& v : l)
      {
        v /= n;
      }
      double rgb[3];
      light->GetDiffuseColor(rgb);
      const double k = light->GetIntensity();
      lightDirs.push_back(l);
      lightColors.push_back({ rgb[0] * k, rgb[1] * k, rgb[2] * k });
    }
  }
  const int blend = self->BlendMode;
  std::string& mode = frame.Mode;
  mode = "COMPOSITE";
  if (blend == MAXIMUM_INTENSITY_BLEND)
  {
    mode = "MIP";
  }
  else if (blend == ISOSURFACE_BLEND)
  {
    mode = "ISO";
  }
  else if (self->Smoke)
  {
    mode = "SMOKE";
  }
  const bool lit = mode == "ISO" || mode == "SMOKE" || frame.Shade;
  frame.Lit = lit;
  if (lit && lightDirs.empty())
  {
    // no light switched on: light from the camera so lit modes are not black
    double p[3], f[3];
    frame.Renderer->GetActiveCamera()->GetPosition(p);
    frame.Renderer->GetActiveCamera()->GetFocalPoint(f);
    std::array<double, 3> l = { p[0] - f[0], p[1] - f[1], p[2] - f[2] };
    vtkMath::Normalize(l.data());
    lightDirs.push_back(l);
    lightColors.push_back({ 1, 1, 1 });
  }
  frame.NLights = lit ? static_cast<int>(lightDirs.size()) : 0;
  if (mode == "SMOKE")
  {
    // the smoke's shadow marches run in index space
    double inv[9];
    vtkMatrix3x3::Invert(frame.Linear, inv);
    for (int l = 0; l < frame.NLights; ++l)
    {
      double e[3];
      vtkMatrix3x3::MultiplyPoint(inv, lightDirs[l].data(), e);
      vtkMath::Normalize(e);
      double w[3];
      vtkMatrix3x3::MultiplyPoint(frame.Linear, e, w);
      for (int c = 0; c < 3; ++c)
      {
        frame.LightIndexDirs.push_back(static_cast<float>(e[c]));
      }
      frame.LightWorldPerIndex.push_back(static_cast<float>(vtkMath::Norm(w)));
    }
  }
}

//------------------------------------------------------------------------------
// Step 6: the shader programs (only the features in use are compiled) and,
// with a ray lattice, its texture.
bool vtkPlumeVolumeMapper::Internals::ReadyPrograms(vtkPlumeVolumeMapper* self, Frame& frame)
{
  // ---- program (only the features in use are compiled: vtkPlumeShaderVariants keeps
  // the shader's //PLUME::IF blocks of the enabled features)
  vtkOpenGLRenderWindow* renWin = frame.Window;
  const std::string& mode = frame.Mode;
  const bool shade = frame.Shade;
  const bool skipTransparent = frame.SkipTransparent;
  const bool rangeSkipping = frame.RangeSkipping;
  vtkPlumeShaderFeatures& features = frame.Features;
  features.Enable(mode); // COMPOSITE, MIP, ISO or SMOKE
  features.Enable("JITTER", self->Jitter);
  features.Enable("DEPTH", frame.UseDepth);
  // masked data: blocks such as SMOKE+MASK combine the mode with the mask
  features.Enable(this->Scalars->GetMasked() ? "MASK" : "NOMASK");
  if (!this->Scalars->GetMasked() && !frame.PreInt)
  {
    features.Enable(this->Scalars->GetHasGradients() ? "GRADIENT" : "PLAIN");
  }
  // composite: point samples over their segment, or pre-integrated segments
  features.Enable(frame.PreInt ? "PREINT" : "POINT", mode == "COMPOSITE");
  features.Enable("SHADE_NOGRADIENT", shade && !this->Scalars->GetHasGradients());
  if (skipTransparent && frame.PreInt)
  {
    features.Enable("SKIP_PREINT");
  }
  else if (skipTransparent || rangeSkipping)
  {
    features.Enable("SKIP");
    features.Enable(skipTransparent ? "SKIP_TRANSPARENT" : (mode == "MIP" ? "SKIP_MIP" : "SKIP_ISO"));
  }
  if (rangeSkipping && mode == "ISO")
  {
    std::ostringstream margin;
    margin << IsoMargin;
    features.Define("PLUME_ISO_MARGIN", margin.str());
  }
  features.Enable("SHADE", shade);
  if (frame.Lit)
  {
    features.Define("PLUME_LIGHTS", frame.NLights);
  }
  // smoke: the transmittance towards each light cached per node (recomputed
  // when the lights, data or transfer function change), unless the cache
  // does not fit the texture budget beside the volume
  if (mode == "SMOKE")
  {
    const double bytes = GetTextureBytes(frame.Dims, this->Scalars->GetMasked(), false) +
      vtkPlumeLightVolume::GetTextureBytes(frame.Dims, frame.NLights, true);
    frame.LightCache = self->LightCache && bytes <= self->EffectiveTextureMemoryBudgetMB * Megabyte;
    vtkVolumeProperty* property = frame.Property;
    std::vector<double>& key = frame.LightKey;
    key = { double(this->Scalars->GetDataVersion()), double(self->TableCount), frame.ScaleBias[0],
      frame.ScaleBias[1], self->ShadowSampleDistance, double(property->GetInterpolationType()),
      this->Scalars->GetMasked() ? 1.0 : 0.0 };
    // (not the skipping: the sweep visits every node either way)
    key.insert(key.end(), frame.LightIndexDirs.begin(), frame.LightIndexDirs.end());
    key.insert(key.end(), frame.LightWorldPerIndex.begin(), frame.LightWorldPerIndex.end());
    // (remade in the frame its inputs change, even every frame while a light
    // moves: the sweep costs less than a frame of shadow rays, e.g. 12 s
    // against 20 s at 256^3 on llvmpipe)
    features.Enable(frame.LightCache ? "LIGHT_CACHE" : "SHADOW_RAYS");
    self->LastLightCache = frame.LightCache;
    if (frame.LightCache)
    {
      // the slices' program: one fragment per node (the full-viewport
      // triangle), every light's shadow march (SHADOW_RAYS: the shared code compiles)
      frame.LightFeatures = features;
      frame.LightFeatures.Enable("LIGHT_CACHE", false);
      frame.LightFeatures.Enable("SHADOW_RAYS");
      frame.LightFeatures.Enable("LIGHT_VOLUME");
      frame.LightProgram =
        this->Programs->Ready(renWin, vtkPlumeVolumeVS, nullptr, vtkPlumeVolumeFS, frame.LightFeatures);
      if (!frame.LightProgram)
      {
        vtkErrorWithObjectMacro(self, << "could not build the volume shader program (light volume)");
        return false;
      }
    }
  }
  else
  {
    self->LastLightCache = false;
  }

  // ---- ray lattice: one ray per lattice x lattice pixels first (into a small
  // texture), then every pixel interpolates its four nearest lattice rays where
  // they agree and casts its own ray where they do not (VTK's conventions: the
  // interactive lattice while the volume's allocated render time is below 1 s)
  int& vpWidth = frame.Viewport[0];
  int& vpHeight = frame.Viewport[1];
  frame.Renderer->GetTiledSizeAndOrigin(&vpWidth, &vpHeight, &frame.Viewport[2], &frame.Viewport[3]);
  const bool interactive = self->AutoAdjustSampleDistances && frame.Volume->GetAllocatedRenderTime() < 1.0;
  int& lattice = frame.Lattice;
  lattice = interactive ? self->InteractiveImageSampleDistance : self->ImageSampleDistance;
  lattice = std::max(1, std::min(lattice, std::min(vpWidth, vpHeight) / 2));
  self->LastImageSampleDistance = lattice;
  // lattice ray i is the ray through pixel i L: rays 0 .. (W - 1) / L + 1 put
  // one on either side of every pixel, and cell i (pixels i L .. i L + L - 1)
  // lines up with llvmpipe's 4 x 4 shading blocks for L = 2, 4, 8, 16, so a
  // block either interpolates or casts rays
  int* latticeSize = frame.LatticeSize;
  latticeSize[0] = (vpWidth - 1) / std::max(lattice, 1) + 2;
  latticeSize[1] = (vpHeight - 1) / std::max(lattice, 1) + 2;
  // llvmpipe rasterises a framebuffer in 64 x 64 tiles, one thread per tile:
  // a lattice within one tile (65 x 65 rays at lattice 8 on 512^2) would be
  // cast by one thread. Its rows are then stored in two bands, rows 0 .. s
  // in the first tile row and rows s .. (s repeated, so every cell's four
  // rays lie in one band) from row TileRows on: two tiles, two threads.
  frame.LatticeSplit = lattice > 1 && latticeSize[0] <= TileRows + 1 && latticeSize[1] <= TileRows + 1 &&
      latticeSize[1] >= 4
    ? latticeSize[1] / 2
    : 0;
  frame.LatticeRows = frame.LatticeSplit ? TileRows + latticeSize[1] - frame.LatticeSplit : latticeSize[1];
  if (lattice > 1)
  {
    for (vtkTextureObject* texture : { this->Lattice.Get(), this->Cells.Get() })
    {
      const int components = texture == this->Lattice ? 4 : 1;
      const int rows = texture == this->Lattice ? frame.LatticeRows : latticeSize[1];
      if (!texture->GetHandle() || texture->GetContext() != renWin)
      {
        texture->SetContext(renWin);
        // the lattice colour is interpolated by the texture unit (bilinear)
        const int filter = texture == this->Lattice ? vtkTextureObject::Linear : vtkTextureObject::Nearest;
        texture->SetMinificationFilter(filter);
        texture->SetMagnificationFilter(filter);
        texture->SetWrapS(vtkTextureObject::ClampToEdge);
        texture->SetWrapT(vtkTextureObject::ClampToEdge);
        texture->Allocate2D(latticeSize[0], rows, components, VTK_FLOAT);
      }
      else if (static_cast<int>(texture->GetWidth()) != latticeSize[0] ||
        static_cast<int>(texture->GetHeight()) != rows)
      {
        texture->Resize(latticeSize[0], rows);
      }
    }
    this->LatticeFBO->SetContext(renWin);
  }
  vtkPlumeShaderFeatures& coarseFeatures = frame.CoarseFeatures;
  coarseFeatures = features;
  coarseFeatures.Enable("COARSE");
  // the cell classification (returns before any ray code)
  vtkPlumeShaderFeatures& classifyFeatures = frame.ClassifyFeatures;
  classifyFeatures = features;
  classifyFeatures.Enable("CLASSIFY");
  // the interpolated cells; the ray program then draws the others' quads
  vtkPlumeShaderFeatures& refineFeatures = frame.RefineFeatures;
  refineFeatures = features;
  refineFeatures.Enable("REFINE");
  // An opaque isosurface writes its depth (as opaque geometry does), so what
  // draws after it, e.g. vtkPlumeAirlightPass's medium, stops there. Only
  // when every pixel casts its own ray: interpolated lattice pixels have no
  // depth of their own.
  frame.IsoDepth = frame.Mode == "ISO" && lattice == 1;
  features.Enable("ISO_DEPTH", frame.IsoDepth);
  vtkShaderProgram*& coarse = frame.Coarse;
  if (lattice > 1)
  {
    coarse = this->Programs->Ready(renWin, vtkPlumeVolumeVS, nullptr, vtkPlumeVolumeFS, coarseFeatures);
    if (!coarse)
    {
      vtkErrorWithObjectMacro(self, << "could not build the volume shader program (ray lattice)");
      return false;
    }
  }
  vtkShaderProgram*& classify = frame.Classify;
  vtkShaderProgram*& refine = frame.Refine;
  if (lattice > 1)
  {
    refine = this->Programs->Ready(renWin, vtkPlumeVolumeVS, nullptr, vtkPlumeVolumeFS, refineFeatures);
    if (!refine)
    {
      vtkErrorWithObjectMacro(self, << "could not build the volume shader program (lattice interpolation)");
      return false;
    }
    classify = this->Programs->Ready(renWin, vtkPlumeVolumeVS, nullptr, vtkPlumeVolumeFS, classifyFeatures);
    if (!classify)
    {
      vtkErrorWithObjectMacro(self, << "could not build the volume shader program (lattice cells)");
      return false;
    }
  }
  vtkShaderProgram*& program = frame.Program;
  // with the lattice the ray program draws the refined cells' quads (the
  // shared cells vertex shader), otherwise the box
  program = this->Programs->Ready(renWin, lattice > 1 ? vtkPlumeLatticeCellsVS : vtkPlumeVolumeVS, nullptr, vtkPlumeVolumeFS, features);
  if (!program)
  {
    vtkErrorWithObjectMacro(self, << "could not build the volume shader program");
    return false;
  }

  return true;
}

//------------------------------------------------------------------------------
// Step 7: a program's uniforms and textures (the lattice and the full-resolution
// programs get the same ones).
void vtkPlumeVolumeMapper::Internals::SetUniforms(
  vtkPlumeVolumeMapper* self, Frame& frame, vtkShaderProgram* program)
{
  const double* indexToClip = frame.IndexToClip;
  const double* clipToIndex = frame.ClipToIndex;
  const double* linear = frame.Linear;
  const double* normal = frame.Normal;
  const float* boxMin = frame.BoxMin;
  const float* boxMax = frame.BoxMax;
  const float* drawMin = frame.DrawMin;
  const float* drawMax = frame.DrawMax;
  const float* fdims = frame.FDims;
  const int* dims = frame.Dims;
  const double* range = frame.Range;
  const double* scaleBias = frame.ScaleBias;
  const double invUnit = frame.InvUnit;
  const std::string& mode = frame.Mode;
  const bool shade = frame.Shade;
  const bool lit = frame.Lit;
  const int nLights = frame.NLights;
  const auto& lightDirs = frame.LightDirs;
  const auto& lightColors = frame.LightColors;
  vtkVolumeProperty* property = frame.Property;
  const bool rangeSkipping = frame.RangeSkipping;
  const bool skipTransparent = frame.SkipTransparent;
  plume::SetUniformMatrix4x4(program, "IndexToClip", indexToClip);
  plume::SetUniformMatrix4x4(program, "ClipToIndex", clipToIndex);
  program->SetUniform3f("BoxMin", boxMin);
  program->SetUniform3f("BoxMax", boxMax);
  program->SetUniform3f("DrawMin", drawMin);
  program->SetUniform3f("DrawMax", drawMax);
  program->SetUniform3f("Dims", fdims);
  plume::SetUniformMatrix3x3(program, "IndexToWorld", linear);
  const float vpOrigin[2] = { float(frame.Viewport[2]), float(frame.Viewport[3]) };
  const float vpSize[2] = { float(frame.Viewport[0]), float(frame.Viewport[1]) };
  program->SetUniform2f("ViewportOrigin", vpOrigin);
  program->SetUniform2f("ViewportSize", vpSize);
  program->SetUniformf("StepIndex", static_cast<float>(self->SampleDistance));
  // enough steps to cross the box diagonal at the requested distance, capped
  const double diagonal = std::sqrt(double(dims[0]) * dims[0] + double(dims[1]) * dims[1] +
                            double(dims[2]) * dims[2]) + 2.0;
  const int maxSteps = static_cast<int>(std::min(16384.0, std::ceil(diagonal / self->SampleDistance) + 2));
  program->SetUniformi("MaxSteps", maxSteps);
  program->SetUniformf("UnitDistance", static_cast<float>(1.0 / invUnit));
  // early termination from the error budget: what the rest of a ray with
  // transmittance T adds is T (L - a B), L <= R a its radiance, a its opacity
  // and B <= 1 what lies behind, so |error| <= T max(R, 1)
  self->EffectiveOpacityThreshold = 1.0;
  if (self->TerminationError > 0 && (mode == "COMPOSITE" || mode == "SMOKE"))
  {
    double brightest = 0; // of the table entries with extinction
    const std::vector<float>& table = this->Table->GetTable();
    for (size_t i = 0; 4 * i + 3 < table.size(); ++i)
    {
      if (table[4 * i + 3] > 0.0f)
      {
        brightest = std::max({ brightest, double(table[4 * i]), double(table[4 * i + 1]), double(table[4 * i + 2]) });
      }
    }
    double lights = 0; // brightest channel of the lights, summed
    for (int l = 0; l < nLights; ++l)
    {
      lights += std::max({ lightColors[l][0], lightColors[l][1], lightColors[l][2], 0.0 });
    }
    double radiance = brightest;
    if (mode == "SMOKE")
    {
      radiance = brightest * (std::abs(property->GetAmbient(0)) + std::abs(property->GetDiffuse(0)) * lights);
    }
    else if (shade)
    {
      radiance = brightest * (std::abs(property->GetAmbient(0)) + std::abs(property->GetDiffuse(0)) * lights) +
        std::abs(property->GetSpecular(0)) * lights;
    }
    const double bound = std::isfinite(radiance) ? std::max(radiance, 1.0) : VTK_DOUBLE_MAX;
    self->EffectiveOpacityThreshold = std::max(0.0, 1.0 - self->TerminationError / bound);
  }
  // (a float just below 1 would round to 1: 1 - 2^-24 is the largest below it)
  program->SetUniformf("OpacityThreshold",
    self->EffectiveOpacityThreshold >= 1.0 ? 2.0f : std::min(static_cast<float>(self->EffectiveOpacityThreshold), 1.0f - 6e-8f));
  program->SetUniformf("TFSize", static_cast<float>(TableSize));
  if (self->Jitter)
  {
    program->SetUniformi("JitterSeed", self->AnimatedJitter ? self->JitterSeed + this->FrameCount : self->JitterSeed);
  }
  const double span = range[1] - range[0];
  if (mode == "ISO")
  {
    double iso = self->IsoValue;
    vtkContourValues* values = property->GetIsoSurfaceValues();
    // the property's when asked for, or when it holds anything but VTK's
    // default (one value, 0, which cannot be told from a 0 set on purpose):
    // VTK's own mappers read it, so code written for them keeps its value
    const bool propertyDefault = values && values->GetNumberOfContours() == 1 && values->GetValue(0) == 0.0;
    if (!std::isfinite(iso) && values && values->GetNumberOfContours() > 0 &&
      (self->UsePropertyIsoValue || !propertyDefault))
    {
      iso = values->GetValue(0);
    }
    if (!std::isfinite(iso))
    {
      iso = vtkPlumeVolumeMapper::GetAutomaticIsoValue(property, range);
    }
    self->EffectiveIsoValue = iso;
    // a value the data never reaches draws nothing: say so, once per value
    const double* data = this->Scalars->GetScalarRange();
    if ((iso < data[0] || iso > data[1]) && !(iso == self->LastWarnedIsoValue))
    {
      self->LastWarnedIsoValue = iso;
      vtkWarningWithObjectMacro(self, << "'iso_value' " << iso << " is outside the data range [" << data[0]
                                      << ", " << data[1] << "]: no surface will show");
    }
    const double u = span > 0 ? (iso - range[0]) / span : (iso > range[0] ? 2.0 : -1.0);
    const float isoU = static_cast<float>(std::min(2.0, std::max(-1.0, u)));
    program->SetUniformf("IsoValue", isoU);
    if (rangeSkipping)
    {
      // blocks whose range does not contain the iso value (as the shader tests them, in u)
      const std::vector<float>& ranges = this->Scalars->GetBlockRanges();
      size_t outside = 0;
      for (size_t b = 0; 2 * b + 1 < ranges.size(); ++b)
      {
        const float u0 = static_cast<float>(ranges[2 * b] * scaleBias[0] + scaleBias[1]);
        const float u1 = static_cast<float>(ranges[2 * b + 1] * scaleBias[0] + scaleBias[1]);
        outside += ranges[2 * b] > ranges[2 * b + 1] || std::max(u0, u1) < isoU - IsoMargin ||
            std::min(u0, u1) > isoU + IsoMargin
          ? 1
          : 0;
      }
      self->EmptyBlockFraction = ranges.empty() ? 0.0 : double(outside) / (ranges.size() / 2);
    }
  }
  if (mode == "ISO" || shade)
  {
    plume::SetUniformMatrix3x3(program, "NormalToWorld", normal);
    program->SetUniformf("Specular", static_cast<float>(property->GetSpecular(0)));
    program->SetUniformf("SpecularPower", static_cast<float>(property->GetSpecularPower(0)));
  }
  if (lit)
  {
    program->SetUniformf("Ambient", static_cast<float>(property->GetAmbient(0)));
    program->SetUniformf("Diffuse", static_cast<float>(property->GetDiffuse(0)));
    std::vector<float> dirs, cols;
    for (int l = 0; l < nLights; ++l)
    {
      for (int c = 0; c < 3; ++c)
      {
        dirs.push_back(static_cast<float>(lightDirs[l][c]));
        cols.push_back(static_cast<float>(lightColors[l][c]));
      }
    }
    program->SetUniform3fv("LightDirection", nLights, reinterpret_cast<float(*)[3]>(dirs.data()));
    program->SetUniform3fv("LightColor", nLights, reinterpret_cast<float(*)[3]>(cols.data()));
  }
  if (mode == "SMOKE")
  {
    program->SetUniformf("ShadowStepIndex", static_cast<float>(self->ShadowSampleDistance));
    program->SetUniform3fv("LightIndexDir", nLights, reinterpret_cast<const float(*)[3]>(frame.LightIndexDirs.data()));
    program->SetUniform1fv("LightWorldPerIndex", nLights, frame.LightWorldPerIndex.data());
    if (frame.LightCache && program != frame.LightProgram)
    {
      // (never bound while its slices are the target)
      this->LightVolume->GetTextureObject()->Activate();
      program->SetUniformi("LightVolume", this->LightVolume->GetTextureObject()->GetTextureUnit());
    }
  }
  // the property's interpolation type (parameters are sent when the texture is bound)
  const int filter = property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION
    ? vtkTextureObject::Nearest
    : vtkTextureObject::Linear;
  this->Scalars->GetTextureObject()->SetMinificationFilter(filter);
  this->Scalars->GetTextureObject()->SetMagnificationFilter(filter);
  this->Scalars->GetTextureObject()->Activate();
  program->SetUniformi("Volume", this->Scalars->GetTextureObject()->GetTextureUnit());
  const float fScaleBias[2] = { static_cast<float>(scaleBias[0]), static_cast<float>(scaleBias[1]) };
  program->SetUniform2f("ValueScaleBias", fScaleBias);
  this->Table->GetTextureObject()->Activate();
  program->SetUniformi("TransferFunction", this->Table->GetTextureObject()->GetTextureUnit());
  if (frame.PreInt)
  {
    this->Integral->GetTextureObject()->Activate();
    program->SetUniformi("TransferIntegral", this->Integral->GetTextureObject()->GetTextureUnit());
  }
  if (frame.UseDepth)
  {
    frame.Depth->GetTextureObject()->Activate();
    program->SetUniformi("OpaqueDepth", frame.Depth->GetTextureObject()->GetTextureUnit());
  }
  if (skipTransparent || rangeSkipping)
  {
    vtkTextureObject* blocks = skipTransparent ? this->Occupancy.GetPointer() : this->BlockRanges.GetPointer();
    blocks->Activate();
    program->SetUniformi(skipTransparent ? "Occupancy" : "BlockRanges", blocks->GetTextureUnit());
    program->SetUniformf("BlockSize", static_cast<float>(this->Scalars->GetBlockSize()));
    const int* bd = this->Scalars->GetBlockDimensions();
    const float fbd[3] = { float(bd[0]), float(bd[1]), float(bd[2]) };
    program->SetUniform3f("BlockDims", fbd);
  }
}

//------------------------------------------------------------------------------
// Step 8 (smoke): the light volume, recomputed only when what it depends on changed.
bool vtkPlumeVolumeMapper::Internals::UpdateLightVolume(vtkPlumeVolumeMapper* self, Frame& frame)
{
  if (!frame.LightCache)
  {
    return true;
  }
  const std::vector<double>& key = frame.LightKey;
  vtkShaderProgram* program = frame.LightProgram;
  bool bound = false;
  const auto bind = [&]() {
    if (!bound)
    {
      this->Programs->Ready(frame.Window, vtkPlumeVolumeVS, nullptr, vtkPlumeVolumeFS, frame.LightFeatures);
      this->SetUniforms(self, frame, program);
      this->EmptyVAO->Bind();
      bound = true;
    }
  };
  int light = -1; // whose sweep the uniforms hold
  const auto sweep = [&](int l, int pass) {
    bind();
    program->SetUniformi("LightPass", pass);
    if (l != light)
    {
      light = l;
      int axis;
      bool flip;
      vtkPlumeLightVolume::GetSweep(frame.LightIndexDirs.data() + 3 * l, axis, flip);
      program->SetUniformi("SweepLight", l);
      program->SetUniformi("SweepAxis", axis);
      program->SetUniformi("SweepFlip", flip ? 1 : 0);
      vtkTextureObject* layers = this->LightVolume->GetSweepTexture();
      layers->Activate();
      program->SetUniformi("LightSweep", layers->GetTextureUnit());
    }
  };
  const bool ok = this->LightVolume->Update(
    frame.Window, frame.Dims, frame.NLights, frame.LightIndexDirs.data(), key,
    [&](int l, int layer) {
      sweep(l, 0);
      program->SetUniformi("SweepLayer", layer);
      program->SetUniformi("SweepStride", LightSweepStride);
      glDrawArrays(GL_TRIANGLES, 0, 3);
    },
    [&](int l, int slice) {
      sweep(l, 1);
      program->SetUniformi("LightSlice", slice);
      glDrawArrays(GL_TRIANGLES, 0, 3);
    });
  if (bound)
  {
    this->EmptyVAO->Release();
    this->Scalars->GetTextureObject()->Deactivate();
    this->Table->GetTextureObject()->Deactivate();
  }
  if (!ok)
  {
    vtkErrorWithObjectMacro(self, << "could not make the smoke's light volume");
  }
  return ok;
}

//------------------------------------------------------------------------------
// The lattice texture's bands (see ReadyPrograms) for a program that reads it.
static void SetLatticeBands(vtkShaderProgram* program, int split, int rows)
{
  program->SetUniformf("LatticeSplit", split ? static_cast<float>(split) : 1e9f);
  program->SetUniformf("LatticeBandShift", static_cast<float>(TileRows - split));
  program->SetUniformf("LatticeRows", static_cast<float>(rows));
}

//------------------------------------------------------------------------------
// Step 9: draw the box's back faces (the lattice rays first, into their
// texture), under premultiplied blending, no depth test or write.
void vtkPlumeVolumeMapper::Internals::Draw(vtkPlumeVolumeMapper* self, Frame& frame)
{
  // ---- state: back faces only (front faces if the transform mirrors), no depth test/write,
  // premultiplied blending, depth clamp so the far plane never clips the box
  vtkOpenGLRenderWindow* renWin = frame.Window;
  const int lattice = frame.Lattice;
  const int* latticeSize = frame.LatticeSize;
  const int vpWidth = frame.Viewport[0];
  const int vpHeight = frame.Viewport[1];
  vtkShaderProgram* coarse = frame.Coarse;
  vtkShaderProgram* program = frame.Program;
  vtkOpenGLState* state = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
  if (frame.IsoDepth)
  {
    // the hit's depth, z-tested (a nearer surface already drawn wins); depth
    // writes need the test enabled
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_LEQUAL);
    state->vtkglDepthMask(GL_TRUE);
  }
  else
  {
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
  }
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  state->vtkglEnable(GL_CULL_FACE);
  state->vtkglCullFace(frame.Det < 0 ? GL_BACK : GL_FRONT);
  const bool depthClampWasOn = glIsEnabled(GL_DEPTH_CLAMP) == GL_TRUE;
  glEnable(GL_DEPTH_CLAMP);

  this->EmptyVAO->Bind();
  if (lattice > 1)
  {
    // the lattice rays into their texture: premultiplied colour, no blending;
    // the box's clip coordinates mapped so texel i is drawn where pixel i L is
    // (texel position x' = (x - 1/2) / L + 1/2 for viewport position x)
    this->Programs->Ready(renWin, vtkPlumeVolumeVS, nullptr, vtkPlumeVolumeFS, frame.CoarseFeatures);
    this->SetUniforms(self, frame, coarse);
    coarse->SetUniformf("Lattice", static_cast<float>(lattice));
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    state->PushFramebufferBindings();
    this->LatticeFBO->Bind();
    this->LatticeFBO->AddColorAttachment(0, this->Lattice);
    this->LatticeFBO->ActivateDrawBuffers(1);
    {
      vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
      vtkOpenGLState::ScopedglClearColor clearSaver(state);
      state->vtkglDisable(GL_SCISSOR_TEST);
      state->vtkglClearColor(0, 0, 0, 0);
      state->vtkglClear(GL_COLOR_BUFFER_BIT);
      state->vtkglDisable(GL_BLEND);
      // each band: lattice rows r0 .. r0 + n - 1 drawn at texture rows y0 ..
      const int split = frame.LatticeSplit;
      const int bands[2][3] = { { 0, split ? split + 1 : latticeSize[1], 0 },
        { split, latticeSize[1] - split, TileRows } };
      for (int b = 0; b < (split ? 2 : 1); ++b)
      {
        const int r0 = bands[b][0], rows = bands[b][1], y0 = bands[b][2];
        float clipScale[2], clipOffset[2];
        for (int k = 0; k < 2; ++k)
        {
          const double n = k == 0 ? latticeSize[0] : rows;
          const double first = k == 0 ? 0 : r0;
          const double scale = double(frame.Viewport[k]) / (lattice * n);
          clipScale[k] = static_cast<float>(scale);
          clipOffset[k] = static_cast<float>(scale + (1.0 - 1.0 / lattice - 2.0 * first) / n - 1.0);
        }
        coarse->SetUniform2f("ClipScale", clipScale);
        coarse->SetUniform2f("ClipOffset", clipOffset);
        coarse->SetUniformf("LatticeRowOffset", static_cast<float>(r0 - y0));
        state->vtkglViewport(0, y0, latticeSize[0], rows);
        glDrawArrays(GL_TRIANGLES, 0, 36);
      }
      this->Profiler.Mark("lattice_rays");
      state->vtkglViewport(0, 0, latticeSize[0], latticeSize[1]);

      // then classify every cell (one triangle over the whole texture)
      this->LatticeFBO->RemoveColorAttachment(0);
      this->LatticeFBO->AddColorAttachment(0, this->Cells);
      this->LatticeFBO->ActivateDrawBuffers(1);
      vtkShaderProgram* classify = frame.Classify;
      this->Programs->Ready(renWin, vtkPlumeVolumeVS, nullptr, vtkPlumeVolumeFS, frame.ClassifyFeatures);
      this->SetUniforms(self, frame, classify);
      this->Lattice->Activate();
      classify->SetUniformi("LatticeColor", this->Lattice->GetTextureUnit());
      classify->SetUniformf("Lattice", static_cast<float>(lattice));
      const float latticeDims[2] = { float(latticeSize[0]), float(latticeSize[1]) };
      classify->SetUniform2f("LatticeSize", latticeDims);
      SetLatticeBands(classify, frame.LatticeSplit, frame.LatticeRows);
      classify->SetUniformf("LatticeTolerance", static_cast<float>(self->LatticeTolerance));
      state->vtkglDisable(GL_CULL_FACE);
      glDrawArrays(GL_TRIANGLES, 0, 3);
      state->vtkglEnable(GL_CULL_FACE);
      this->Lattice->Deactivate();
      this->Profiler.Mark("classify");
      if (self->CountRays)
      {
        // the lattice's rays, plus every pixel of the viewport in a cell that casts its own
        std::vector<float> cells(static_cast<size_t>(latticeSize[0]) * latticeSize[1]);
        glReadPixels(0, 0, latticeSize[0], latticeSize[1], GL_RED, GL_FLOAT, cells.data());
        double rays = double(latticeSize[0]) * latticeSize[1];
        for (int j = 0; j * lattice < vpHeight; ++j)
        {
          for (int i = 0; i * lattice < vpWidth; ++i)
          {
            if (cells[static_cast<size_t>(j) * latticeSize[0] + i] != 0.0f)
            {
              rays += double(std::min(lattice, vpWidth - i * lattice)) * std::min(lattice, vpHeight - j * lattice);
            }
          }
        }
        self->LastRayCount = rays;
      }
      state->vtkglEnable(GL_BLEND);
    }
    this->LatticeFBO->RemoveColorAttachment(0);
    state->PopFramebufferBindings();
    state->vtkglViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  }
  else if (self->CountRays)
  {
    self->LastRayCount = double(vpWidth) * vpHeight;
  }
  const float unitScale[2] = { 1.0f, 1.0f };
  const float noOffset[2] = { 0.0f, 0.0f };
  const float latticeDims[2] = { float(latticeSize[0]), float(latticeSize[1]) };
  if (lattice > 1)
  {
    // the interpolated cells: every pixel of the box in a cell classified 0
    // (the others are discarded after one look-up)
    vtkShaderProgram* refine = frame.Refine;
    this->Programs->Ready(renWin, vtkPlumeVolumeVS, nullptr, vtkPlumeVolumeFS, frame.RefineFeatures);
    this->SetUniforms(self, frame, refine);
    this->Lattice->Activate();
    this->Cells->Activate();
    refine->SetUniformi("LatticeColor", this->Lattice->GetTextureUnit());
    refine->SetUniformi("CellRefine", this->Cells->GetTextureUnit());
    refine->SetUniformf("Lattice", static_cast<float>(lattice));
    refine->SetUniform2f("LatticeSize", latticeDims);
    SetLatticeBands(refine, frame.LatticeSplit, frame.LatticeRows);
    refine->SetUniform2f("ClipScale", unitScale);
    refine->SetUniform2f("ClipOffset", noOffset);
    glDrawArrays(GL_TRIANGLES, 0, 36);
    this->Profiler.Mark("interpolation");
  }
  this->Programs->Ready(renWin, lattice > 1 ? vtkPlumeLatticeCellsVS : vtkPlumeVolumeVS, nullptr, vtkPlumeVolumeFS, frame.Features);
  this->SetUniforms(self, frame, program);
  program->SetUniform2f("ClipScale", unitScale);
  program->SetUniform2f("ClipOffset", noOffset);
  if (lattice > 1)
  {
    // each pixel of the other cells casts its own ray: the refined cells drawn
    // by plume::DrawLatticeCells, those of interpolated cells moved out of view
    // in the vertex shader, so their pixels never run the ray program
    // (llvmpipe would run its set-up for them)
    const int target[2] = { vpWidth, vpHeight };
    state->vtkglDisable(GL_CULL_FACE);
    plume::DrawLatticeCells(program, this->Cells->GetTextureUnit(), lattice, latticeSize, target);
    state->vtkglEnable(GL_CULL_FACE);
  }
  else
  {
    glDrawArrays(GL_TRIANGLES, 0, 36);
  }
  this->Profiler.Mark("rays");
  this->EmptyVAO->Release();
  if (lattice > 1)
  {
    this->Lattice->Deactivate();
    this->Cells->Deactivate();
  }

  if (!depthClampWasOn)
  {
    glDisable(GL_DEPTH_CLAMP);
  }
  state->vtkglCullFace(GL_BACK);
  this->Scalars->GetTextureObject()->Deactivate();
  this->Table->GetTextureObject()->Deactivate();
  if (frame.PreInt)
  {
    this->Integral->GetTextureObject()->Deactivate();
  }
  if (frame.UseDepth)
  {
    frame.Depth->GetTextureObject()->Deactivate();
  }
  if (frame.LightCache)
  {
    this->LightVolume->GetTextureObject()->Deactivate();
  }
  if (frame.SkipTransparent)
  {
    this->Occupancy->Deactivate();
  }
  if (frame.RangeSkipping)
  {
    this->BlockRanges->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkPlumeVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Impl->ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkPlumeVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ScalarComponent: " << this->ScalarComponent << "\n";
  os << indent << "SampleDistance: " << this->SampleDistance << "\n";
  os << indent << "Jitter: " << this->Jitter << " (animated " << this->AnimatedJitter
     << ", seed " << this->JitterSeed << ")\n";
  os << indent << "TerminationError: " << this->TerminationError << "\n";
  os << indent << "ImageSampleDistance: " << this->ImageSampleDistance << "\n";
  os << indent << "InteractiveImageSampleDistance: " << this->InteractiveImageSampleDistance << "\n";
  os << indent << "AutoAdjustSampleDistances: " << this->AutoAdjustSampleDistances << "\n";
  os << indent << "LatticeTolerance: " << this->LatticeTolerance << "\n";
  os << indent << "EffectiveOpacityThreshold: " << this->EffectiveOpacityThreshold << "\n";
  os << indent << "IsoValue: " << this->IsoValue << " (in effect " << this->EffectiveIsoValue << ")\n";
  os << indent << "UsePropertyIsoValue: " << this->UsePropertyIsoValue << "\n";
  os << indent << "OpacityUnitDistance: " << this->OpacityUnitDistance << " (in effect "
     << this->EffectiveOpacityUnitDistance << ")\n";
  os << indent << "TransferFunctionRange: " << this->TransferFunctionRange[0] << " "
     << this->TransferFunctionRange[1] << "\n";
  os << indent << "ValidMaskArrayName: " << this->ValidMaskArrayName << "\n";
  os << indent << "Smoke: " << this->Smoke << "\n";
  os << indent << "ShadowSampleDistance: " << this->ShadowSampleDistance << "\n";
  os << indent << "LightCache: " << this->LightCache << "\n";
  os << indent << "UseOpaqueDepth: " << this->UseOpaqueDepth << "\n";
  os << indent << "EmptySpaceSkipping: " << this->EmptySpaceSkipping << " (MIP: " << this->MIPSkipping << ")\n";
  os << indent << "TextureMemoryBudgetMB: " << this->TextureMemoryBudgetMB << " (in effect "
     << this->EffectiveTextureMemoryBudgetMB << ")\n";
}
