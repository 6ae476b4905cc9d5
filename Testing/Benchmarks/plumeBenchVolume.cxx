// `plume bench volume`: raycasting 128³ and 256³ scalar volumes into 512x512
// with vtkPlumeVolumeMapper against VTK's own vtkGPUVolumeRayCastMapper and
// vtkFixedPointVolumeRayCastMapper (the faster one on software GL): same
// volume, transfer functions and camera, several sample distances each, and
// every image's error against vtkPlumeVolumeReference (computed once per
// field and size in its own job and passed to the render jobs through a
// temporary file; at 256³ on every 4th pixel along x and y only, which is
// where the errors are measured then).
// Two fields: "smoke" (three Gaussian puffs, mostly empty space) and "dense"
// (a low-opacity field that fills the box), each unshaded and shaded (the
// property's Shade on, headlight; note the peers' shading models differ from
// ours in detail, so part of their shaded error is model, not sampling); and
// "smoke+geometry": the unshaded smoke with an opaque polygonal sphere through
// two of its puffs, which every mapper composites against (rays stop at its
// depth: depth edges inside the smoke); its reference job renders the sphere
// alone, gives the reference that depth and composites it over the sphere's
// colours, so the errors are of the whole picture.
// Settings: ours at one ray per pixel and with the error-controlled ray
// lattice (ImageSampleDistance 2, 4, 8; at 4 and 8 also with looser
// LatticeTolerance), steps up to 64 voxels and the 100-voxel floor; our jobs
// report the rays they cast ("rays", counted in one extra frame); "ours-base" is the state before issue 18's work (one ray per pixel,
// termination at 0.995); the peers at every step with ImageSampleDistance 1,
// and in their interactive modes (ImageSampleDistance 2 and 4 at steps 1/4/16,
// AutoAdjustSampleDistances at DesiredUpdateRate 15). Headline lines
// (headline: true) pair every peer setting with our fastest setting whose
// error is not above its error; "before" lines do the same for ours-base.
// PLUME_BENCH_VOLUME_GRIDS=128 (or 256) runs one grid size;
// PLUME_BENCH_VOLUME_RUN=name lets single jobs run by hand share the reference
// job's file (`PLUME_BENCH_VOLUME_RUN=a plume bench volume --job
// reference:smoke+geometry:128`, then the render jobs with the same name);
// PLUME_BENCH_VOLUME_FRAMES=n measures n frames per job.
// PLUME_BENCH_VOLUME_SET=interactive runs only the references, the peers'
// interactive settings and InteractiveOurs, and reports their headlines.
// Sparsity report: ours at step 1 with empty-space skipping and/or early ray
// termination switched off, on the sparse smoke, the dense field and an
// "opaque" one (the dense field with the smoke's opacity, where rays saturate
// early), composite at both sizes, MIP and isosurface at 128³. Per-ray floor:
// see FloorStep. Pre-integration: "ours-preint" (PreIntegration on) at steps
// 4, 8, 16 (--quick: 8) on the unshaded fields vs ours plain at the same step.
// Cached lighting (smoke mode, LightCache; no peer has a self-shadowed mode):
// "smoke+lit", the smoke field in smoke mode under a fixed scene light from
// the side, its reference with shadow rays (1/4-voxel steps, every 4th pixel
// along x and y); "ours" (light volume, computed in the warm-up and reused:
// a still light) vs "ours-shadowrays" (LightCache off: a shadow ray per
// sample) vs "ours-relight" (the light moves by 1e-3 every frame: a moving
// or camera-following light, whose frames remake the light volume) vs
// "ours-remake" (the frame after the light moved, which remakes the light
// volume; timed alone), at
// steps 1 and 4 (--quick: 4); lightcache lines, ratio = shadow-ray s / ours s.
// --quick: 32³ only
// (errors on every 2nd pixel), sparsity for the smoke composite and isosurface.
#include "plumeBenchFloorMapper.h"
#include "plumeBenchmarks.h"

#include "vtkPlumeVolumeMapper.h"
#include "vtkPlumeFrameReadBack.h"
#include "vtkPlumeVolumeReference.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFixedPointVolumeRayCastMapper.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <unistd.h>

namespace plume
{
namespace bench
{
namespace
{
// the samples per pixel of the framebuffer the window draws into (GL_SAMPLES
// with it bound: what the frames really paid, whatever was asked for)
int RenderFramebufferSamples(vtkRenderWindow* window)
{
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!gl || !gl->GetRenderFramebuffer())
  {
    return -1;
  }
  gl->MakeCurrent();
  gl->GetState()->PushFramebufferBindings();
  gl->GetRenderFramebuffer()->Bind();
  GLint samples = -1;
  glGetIntegerv(GL_SAMPLES, &samples);
  gl->GetState()->PopFramebufferBindings();
  return samples;
}

int Size(bool quick)
{
  return quick ? 128 : 512;
}

// grid sizes (quick: one small stand-in that runs the same code paths)
// (PLUME_BENCH_VOLUME_GRIDS=128 or =256 runs one size only: a full run takes
// over an hour on a loaded machine)
std::vector<int> Grids(bool quick)
{
  if (quick)
  {
    return { 32 };
  }
  const char* only = std::getenv("PLUME_BENCH_VOLUME_GRIDS");
  if (only && (std::string(only) == "128" || std::string(only) == "256"))
  {
    return { std::stoi(only) };
  }
  return { 128, 256 };
}

std::vector<double> Steps(bool quick, int n)
{
  if (quick)
  {
    return { 1.0 };
  }
  // up to 16 voxels: on smooth fields our jittered midpoint steps keep their
  // error at long steps (dense field, step 16: 0.13 %), the peers' grows
  return n >= 256 ? std::vector<double>{ 1.0, 2.0, 4.0, 8.0, 16.0 }
                  : std::vector<double>{ 0.5, 1.0, 2.0, 4.0, 8.0, 16.0 };
}

// Per-ray floor: ours at 100-voxel steps (the longest SampleDistance; a few
// samples per ray: up to 3 at 128³, 4 at 256³ with this camera) costs what every ray costs before sampling (set-up, box
// and block clipping, the first look-ups). A peer time divided by it bounds
// the ratio any saving in samples could reach.
const double FloorStep = 100.0;

// the reference at every stride-th pixel along x and y (a full 512² reference at 256³ is too slow)
int Stride(bool quick, int n)
{
  return quick ? 2 : (n >= 256 ? 4 : 1); // quick: the sub-sampled path, on its small grid
}

// smoke mode under a side light (cached lighting vs shadow rays: see the top)
bool Lit(const std::string& variant)
{
  return variant.find("+lit") != std::string::npos;
}

const char* const LitKinds[] = { "ours", "ours-shadowrays", "ours-relight", "ours-remake" };

std::vector<double> LitSteps(bool quick)
{
  return quick ? std::vector<double>{ 4.0 } : std::vector<double>{ 1.0, 4.0 };
}

// the scene light of the lit variant (fixed relative to the volume)
const double LitLightPosition[3] = { 1.6, 1.3, 0.1 };

vtkSmartPointer<vtkLight> AddLitLight(vtkRenderer* renderer)
{
  renderer->RemoveAllLights(); // (a first render made a headlight)
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->SetPosition(LitLightPosition[0], LitLightPosition[1], LitLightPosition[2]);
  light->SetFocalPoint(0.5, 0.5, 0.5);
  light->SetPositional(false);
  renderer->AddLight(light);
  renderer->AutomaticLightCreationOff();
  return light;
}

int MeasuredFrames(bool quick, int n)
{
  return quick ? 2 : (n >= 256 ? 3 : 5);
}

std::string StepText(double step)
{
  char s[32];
  std::snprintf(s, sizeof(s), "%g", step);
  return s;
}

// sparsity report: our configurations (switch, what is off)
const char* const SparsityConfigs[][2] = { { "ours-noskip", "empty-space skipping off" },
  { "ours-noert", "early ray termination off" }, { "ours-plain", "skipping and early termination off" } };

// a variant is a field, optionally shaded (property Shade on, same lighting for all)
const char* Fields[] = { "smoke", "dense", "smoke+shaded", "dense+shaded", "smoke+geometry" };

std::string FieldOf(const std::string& variant)
{
  return variant.substr(0, variant.find('+'));
}

// composite (default), "mip" or "iso" (sparsity jobs only)
std::string ModeOf(const std::string& variant)
{
  return variant.find("+mip") != std::string::npos ? "mip"
                                                     : (variant.find("+iso") != std::string::npos ? "iso" : "composite");
}

bool Shaded(const std::string& variant)
{
  return variant.find("+shaded") != std::string::npos;
}

// an opaque polygonal sphere in the volume (depth edges inside the smoke)
bool WithGeometry(const std::string& variant)
{
  return variant.find("+geometry") != std::string::npos;
}

std::string Describe(const std::string& variant)
{
  return FieldOf(variant) + (Shaded(variant) ? ", shaded" : ", unshaded") +
    (WithGeometry(variant) ? ", opaque sphere" : "");
}

// the opaque geometry: a sphere of 48 x 48 facets through the first two puffs,
// off-centre (its silhouette and the smoke's depth edges cross the image)
void AddGeometry(vtkRenderer* renderer)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.5, 0.48, 0.45);
  sphere->SetRadius(0.16);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.75, 0.6);
  renderer->AddActor(actor);
}

// Peer settings: kind = "gpu" or "fixed", optionally with a suffix for the
// peers' interactive modes, which a user would pick for speed: "-isd2"/"-isd4"
// cast one ray per 2x2 / 4x4 pixels (ImageSampleDistance, the image
// interpolated up), "-auto" lets the mapper adapt (AutoAdjustSampleDistances
// with the render window's DesiredUpdateRate at 15 frames/s, VTK's
// interactive rate: FixedPoint then raises ImageSampleDistance up to 10 until
// a frame fits 1/15 s; the GPU mapper also picks its own step along the ray,
// so its "-auto" job ignores the step and runs once).
const char* const PeerKinds[] = { "gpu", "gpu-isd2", "gpu-isd4", "gpu-auto", "fixed", "fixed-isd2", "fixed-isd4",
  "fixed-auto" };

bool IsGPU(const std::string& kind)
{
  return kind.compare(0, 3, "gpu") == 0;
}

double PeerImageSampleDistance(const std::string& kind)
{
  return kind.find("-isd4") != std::string::npos ? 4.0 : (kind.find("-isd2") != std::string::npos ? 2.0 : 1.0);
}

bool PeerAuto(const std::string& kind)
{
  return kind.find("-auto") != std::string::npos;
}

std::string PeerName(const std::string& kind)
{
  std::string name = IsGPU(kind) ? "vtkGPUVolumeRayCastMapper" : "vtkFixedPointVolumeRayCastMapper";
  if (PeerAuto(kind))
  {
    name += ", AutoAdjustSampleDistances at DesiredUpdateRate 15";
  }
  else if (PeerImageSampleDistance(kind) > 1)
  {
    name += ", ImageSampleDistance " + StepText(PeerImageSampleDistance(kind));
  }
  return name;
}

// the steps a peer setting runs at (interactive settings: fewer; gpu-auto picks its own)
std::vector<double> PeerSteps(const std::string& kind, bool quick, int n)
{
  const std::vector<double> all = Steps(quick, n);
  if (quick || kind == "gpu" || kind == "fixed")
  {
    return all;
  }
  if (kind == "gpu-auto")
  {
    return { 1.0 };
  }
  return { 1.0, 4.0, 16.0 };
}

// our settings: one ray per pixel, and the error-controlled ray lattice
// (ImageSampleDistance 2 and 4, refined where neighbouring rays disagree)
// (ImageSampleDistance 2, 4 and 8, refined where neighbouring rays disagree),
// at the default LatticeTolerance and at looser ones ("-tol0.016": tolerance
// 0.016), the refinement criterion for the larger errors of the peers'
// interactive settings
const char* const OurKinds[] = { "ours", "ours-isd2", "ours-isd4", "ours-isd8", "ours-isd4-tol0.016",
  "ours-isd8-tol0.016", "ours-isd8-tol0.064" };
// "before": one ray per pixel and the former early-termination threshold 0.995
// (termination budget 0.005: the same threshold wherever R <= 1, i.e. unshaded)
const char* const BeforeKind = "ours-base";

// --quick: the code paths (a lattice, a tolerance) in fewer jobs
std::vector<std::string> OurKindList(bool quick)
{
  if (quick)
  {
    return { "ours", "ours-isd4", "ours-isd8-tol0.064" };
  }
  return std::vector<std::string>(std::begin(OurKinds), std::end(OurKinds));
}

// The peers' interactive settings (ImageSampleDistance 4 at steps 1/4/16,
// AutoAdjustSampleDistances) against our settings for the same purpose:
// the lattice of 8 pixels with the refinement tolerance loosened towards the
// error a user accepts there (0.25: jitter noise at 32-64-voxel steps no longer
// refines cells), at long steps (one ray per pixel and lattices of 16 never
// won at 128^3; probably because a 33 x 33 lattice is one 64 x 64 llvmpipe tile,
// cast by one thread). These (kind, step)
// pairs run in the full run too; PLUME_BENCH_VOLUME_SET=interactive runs only
// them, the references and the peers' interactive settings (see InteractiveSet).
const std::pair<const char*, double> InteractiveOurs[] = { { "ours-isd4", 4 }, { "ours-isd8-tol0.016", 4 },
  { "ours-isd8-tol0.064", 8 }, { "ours-isd8-tol0.064", 16 }, { "ours-isd8-tol0.064", 32 },
  { "ours-isd8-tol0.25", 32 }, { "ours-isd8-tol0.25", 64 } };

// PLUME_BENCH_VOLUME_SET=interactive: the comparison against the peers'
// interactive settings alone (a few minutes instead of over an hour)
bool InteractiveSet()
{
  const char* set = std::getenv("PLUME_BENCH_VOLUME_SET");
  return set && std::string(set) == "interactive";
}

bool InteractivePeer(const std::string& kind)
{
  return kind.find("-isd4") != std::string::npos || PeerAuto(kind);
}

// the LatticeTolerance of one of OurKinds (0: the default)
double OurLatticeTolerance(const std::string& kind)
{
  const size_t t = kind.find("-tol");
  return t == std::string::npos ? 0.0 : std::stod(kind.substr(t + 4));
}

int OurImageSampleDistance(const std::string& kind)
{
  const size_t i = kind.find("-isd");
  if (kind.compare(0, 4, "ours") == 0 && i != std::string::npos)
  {
    return std::stoi(kind.substr(i + 4));
  }
  return 1;
}

// our steps: the peers' plus longer ones (our error grows slowly with the step;
// the peers' interactive settings have large errors)
std::vector<double> OurSteps(bool quick, int n)
{
  std::vector<double> steps = Steps(quick, n);
  if (!quick)
  {
    steps.push_back(32.0);
    steps.push_back(64.0);
  }
  return steps;
}

// the window's frame without a volume (clear, the geometry if any, the
// multisample resolve): what every renderer pays, so peer time / this time
// bounds the ratio any volume renderer could reach against that peer setting
const char* const WindowKind = "window";

// The floors of a frame that draws anything (plumeBenchFloorMapper, same
// window and frame loop): "floor-quad" one screen-filling quad of a constant
// colour, blended; "floor-latN" an N x N texture filled by a trivial shader,
// then drawn over the screen rectangle of the volume's bounds by one
// bilinearly filtered quad, blended (the
// cheapest conceivable lattice frame: what the fixed-point mapper's
// ImageSampleDistance > 1 adds to its rays), 8-bit channels as the fixed-point
// mapper's, "-f16" / "-f32" float channels. Run on the smoke only (they draw
// no volume).
const char* const FloorKinds[] = { "floor-quad", "floor-lat64", "floor-lat128", "floor-lat64-f16", "floor-lat64-f32" };

bool IsFloor(const std::string& kind)
{
  return kind.compare(0, 6, "floor-") == 0;
}

// PLUME_BENCH_VOLUME_PROFILE=1: our jobs time each of the mapper's passes
// (vtkPlumeVolumeMapper::ProfilePasses: the GL work finished after each, so
// the frames are slower) and report the medians in "pass_ms" (wall) and
// "pass_cpu_ms" (the process's CPU time)
bool ProfilePasses()
{
  const char* profile = std::getenv("PLUME_BENCH_VOLUME_PROFILE");
  return profile && std::string(profile) == "1";
}

// every setting of ours that the headlines choose from, (kind, step): every
// kind at every step, the 100-voxel floor, and InteractiveOurs (full run); only
// InteractiveOurs with PLUME_BENCH_VOLUME_SET=interactive
std::vector<std::pair<std::string, double>> OurSettings(bool quick, int n)
{
  std::vector<std::pair<std::string, double>> settings;
  if (quick || !InteractiveSet())
  {
    for (const std::string& kind : OurKindList(quick))
    {
      for (double step : OurSteps(quick, n))
      {
        settings.emplace_back(kind, step);
      }
    }
    settings.emplace_back("ours", FloorStep);
  }
  if (!quick)
  {
    for (const auto& s : InteractiveOurs)
    {
      const std::pair<std::string, double> setting(s.first, s.second);
      if (std::find(settings.begin(), settings.end(), setting) == settings.end())
      {
        settings.push_back(setting);
      }
    }
  }
  return settings;
}

// Pre-integration (PreIntegration, composite unshaded only): "ours-preint" at
// long steps against ours plain at the same step (time and error)
const char* const PreIntKind = "ours-preint";
std::vector<double> PreIntSteps(bool quick)
{
  return quick ? std::vector<double>{ 8.0 } : std::vector<double>{ 4.0, 8.0, 16.0 };
}

vtkSmartPointer<vtkImageData> Field(const std::string& name, int n)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetSpacing(1.0 / (n - 1), 1.0 / (n - 1), 1.0 / (n - 1));
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  const double puffs[3][4] = { { 0.35, 0.4, 0.45, 0.14 }, { 0.68, 0.6, 0.5, 0.1 }, { 0.5, 0.25, 0.7, 0.07 } };
  vtkIdType id = 0;
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i, ++id)
      {
        const double x = double(i) / (n - 1), y = double(j) / (n - 1), z = double(k) / (n - 1);
        double v = 0;
        if (name == "smoke")
        {
          for (const auto& g : puffs)
          {
            v += std::exp(-((x - g[0]) * (x - g[0]) + (y - g[1]) * (y - g[1]) + (z - g[2]) * (z - g[2])) /
              (2 * g[3] * g[3]));
          }
          v = std::min(v, 1.0);
        }
        else
        {
          v = 0.5 + 0.25 * std::sin(7 * x + 1) * std::cos(5 * y) + 0.25 * std::sin(6 * z + 3 * x);
        }
        values->SetValue(id, static_cast<float>(v));
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

void Configure(vtkVolumeProperty* property, const std::string& variant)
{
  const std::string field = FieldOf(variant);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.1, 0.2, 0.8);
  color->AddRGBPoint(0.5, 0.9, 0.9, 0.8);
  color->AddRGBPoint(1.0, 1.0, 0.5, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(0.05, 0.0);
  const bool thick = field != "dense"; // "opaque" is the dense field with the smoke's opacity
  opacity->AddPoint(1.0, thick ? 0.8 : 0.15);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(thick ? 0.05 : 0.2);
  property->SetInterpolationTypeToLinear();
  property->SetShade(Shaded(variant) ? 1 : 0);
  property->SetAmbient(0.2);
  property->SetDiffuse(0.7);
  property->SetSpecular(0.3);
  property->SetSpecularPower(15);
}

void SetCamera(vtkRenderer* renderer)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.5, 0.5, 0.5);
  camera->SetPosition(0.5 + 0.9, 0.5 - 1.2, 0.5 + 1.9);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  camera->SetClippingRange(0.5, 6.0);
}

// `run` is the pid of the `plume bench` process: getppid() in a job, getpid() in
// Report; PLUME_BENCH_VOLUME_RUN=name replaces it, so that single jobs run by
// hand (`plume bench volume --job ...`, each with its own parent) share the
// reference job's file
std::string ReferencePath(const std::string& field, int n, bool quick, long run)
{
  const char* named = std::getenv("PLUME_BENCH_VOLUME_RUN");
  if (named && *named)
  {
    return "/tmp/plume-bench-volume-" + std::string(named) + "-" + field + "-" + std::to_string(n) +
      (quick ? "-quick" : "") + ".f32";
  }
  return "/tmp/plume-bench-volume-" + std::to_string(run) + "-" + field + "-" + std::to_string(n) +
    (quick ? "-quick" : "") + ".f32";
}

// job = kind:variant:n[:step]   (kind: reference, ours, gpu, fixed, or a sparsity configuration)
std::string JobId(const std::string& kind, const std::string& variant, int n, double step = 0)
{
  return kind + ":" + variant + ":" + std::to_string(n) + (kind == "reference" ? "" : ":" + StepText(step));
}

nlohmann::json RunJob(const Context& context, const std::string& job)
{
  const size_t a = job.find(':'), b = job.find(':', a + 1), c = job.find(':', b + 1);
  const std::string kind = job.substr(0, a);
  const std::string variant = job.substr(a + 1, b - a - 1);
  const std::string field = FieldOf(variant);
  const int n = std::stoi(job.substr(b + 1, c == std::string::npos ? std::string::npos : c - b - 1));
  const double step = c == std::string::npos ? 0.0 : std::stod(job.substr(c + 1));
  const bool quick = context.Quick;
  const int size = Size(quick);
  // (PLUME_BENCH_VOLUME_FRAMES=n measures n frames: a job's CPU time at two
  // frame counts gives the CPU time per frame, steadier than wall time on a
  // loaded machine)
  const char* framesText = std::getenv("PLUME_BENCH_VOLUME_FRAMES");
  const int frames = framesText && std::atoi(framesText) > 0 ? std::atoi(framesText) : MeasuredFrames(quick, n);
  // (the lit reference's shadow rays: every 4th pixel along x and y)
  const int stride = Lit(variant) && !quick ? std::max(4, Stride(quick, n)) : Stride(quick, n);
  auto image = Field(field == "opaque" ? "dense" : field, n);

  vtkNew<vtkVolume> volume;
  Configure(volume->GetProperty(), variant);
  if (kind == "reference")
  {
    // a window-less renderer: the camera, and the headlight VTK would create;
    // with geometry, the window the render jobs draw in, showing the geometry
    // alone: its depth stops the reference's rays, its colours lie behind them
    vtkSmartPointer<vtkRenderWindow> window;
    vtkNew<vtkRenderer> renderer;
    plume::FloatImage background;
    if (WithGeometry(variant))
    {
      window = context.MakeWindow(size, size);
      renderer->SetBackground(0, 0, 0);
      window->AddRenderer(renderer);
      AddGeometry(renderer);
      SetCamera(renderer);
      background = plume::ReadBack(window);
    }
    else if (Lit(variant))
    {
      SetCamera(renderer);
      AddLitLight(renderer);
    }
    else
    {
      SetCamera(renderer);
      renderer->CreateLight();
      renderer->UpdateLightsGeometryToFollowCamera();
    }
    vtkNew<vtkPlumeVolumeReference> reference;
    if (Lit(variant))
    {
      reference->SetMode(vtkPlumeVolumeReference::SMOKE);
      reference->SetStep(0.25);
      reference->SetShadowStep(0.25);
    }
    reference->SetInputData(image);
    reference->SetVolume(volume);
    reference->SetRenderer(renderer);
    if (!Lit(variant))
    {
      reference->SetStep(0.125);
    }
    reference->SetPixelStride(stride);
    reference->SetOpaqueDepth(background.Depth);
    const double t0 = Now();
    reference->Compute(size, size);
    const double seconds = Now() - t0;
    const std::vector<float> expected =
      WithGeometry(variant) ? reference->CompositeOver(background.RGBA) : reference->GetImage();
    std::ofstream out(ReferencePath(variant, n, quick, getppid()), std::ios::binary);
    out.write(reinterpret_cast<const char*>(expected.data()), expected.size() * sizeof(float));
    return { { "reference_s", seconds }, { "peak_rss_mb", PeakRSSMB() } };
  }

  auto window = context.MakeWindow(size, size);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  window->AddRenderer(renderer);
  if (WithGeometry(variant))
  {
    AddGeometry(renderer);
  }
  window->Render();
  window->WaitForCompletion();
  SetCamera(renderer);
  vtkSmartPointer<vtkLight> litLight = Lit(variant) ? AddLitLight(renderer) : nullptr;

  const double spacing = 1.0 / (n - 1);
  vtkNew<vtkPlumeVolumeMapper> ours;
  const bool isOurs = kind.compare(0, 4, "ours") == 0;
  vtkSmartPointer<vtkGPUVolumeRayCastMapper> gpuPeer;
  vtkSmartPointer<vtkFixedPointVolumeRayCastMapper> fixedPeer;
  vtkSmartPointer<plumeBenchFloorMapper> floorMapper;
  if (isOurs)
  {
    ours->SetInputData(image);
    ours->SetSampleDistance(step);
    ours->SetImageSampleDistance(OurImageSampleDistance(kind));
    if (OurLatticeTolerance(kind) > 0)
    {
      ours->SetLatticeTolerance(OurLatticeTolerance(kind));
    }
    ours->SetPreIntegration(kind == PreIntKind);
    ours->SetSmoke(Lit(variant));
    ours->SetLightCache(kind != "ours-shadowrays");
    if (kind == "ours-base")
    {
      ours->SetTerminationError(0.005); // the former fixed threshold, 0.995, where R <= 1
    }
    ours->SetEmptySpaceSkipping(kind != "ours-noskip" && kind != "ours-plain");
    if (kind == "ours-noert" || kind == "ours-plain")
    {
      ours->SetTerminationError(0.0); // never stop early
    }
    if (ModeOf(variant) == "mip")
    {
      ours->SetBlendModeToMaximumIntensity();
      ours->MIPSkippingOn(); // opt-in (off by default): measured here
    }
    else if (ModeOf(variant) == "iso")
    {
      ours->SetBlendModeToIsoSurface();
      ours->SetIsoValue(0.5);
    }
    volume->SetMapper(ours);
  }
  else if (kind == WindowKind)
  {
    // no volume: the frame every renderer pays (clear, the geometry, resolve)
  }
  else if (IsFloor(kind))
  {
    floorMapper = vtkSmartPointer<plumeBenchFloorMapper>::New();
    plumeBenchFloorMapper* mapper = floorMapper;
    mapper->SetInputData(image); // (bounds only: nothing of it is drawn)
    if (kind != "floor-quad")
    {
      mapper->SetLatticeSize(std::stoi(kind.substr(9)));
      const size_t f = kind.find("-f");
      mapper->SetBits(f == std::string::npos ? 8 : std::stoi(kind.substr(f + 2)));
    }
    volume->SetMapper(mapper);
  }
  else if (IsGPU(kind))
  {
    vtkNew<vtkOpenGLGPUVolumeRayCastMapper> mapper; // what vtkGPUVolumeRayCastMapper::New() gives
    mapper->SetInputData(image);
    mapper->SetAutoAdjustSampleDistances(PeerAuto(kind));
    mapper->LockSampleDistanceToInputSpacingOff();
    mapper->SetSampleDistance(step * spacing);
    mapper->SetImageSampleDistance(PeerImageSampleDistance(kind));
    volume->SetMapper(mapper);
    gpuPeer = mapper;
  }
  else
  {
    vtkNew<vtkFixedPointVolumeRayCastMapper> mapper;
    mapper->SetInputData(image);
    mapper->SetAutoAdjustSampleDistances(PeerAuto(kind));
    mapper->LockSampleDistanceToInputSpacingOff();
    mapper->SetSampleDistance(step * spacing);
    mapper->SetImageSampleDistance(PeerImageSampleDistance(kind));
    volume->SetMapper(mapper);
    fixedPeer = mapper;
  }
  if (kind != WindowKind)
  {
    renderer->AddVolume(volume);
  }
  if (PeerAuto(kind))
  {
    window->SetDesiredUpdateRate(15.0); // what vtkRenderWindowInteractor sets while the user interacts
  }

  const bool profile = isOurs && ProfilePasses();
  ours->SetProfilePasses(profile);
  std::map<std::string, std::vector<double>> passTimes, passCPUTimes;
  std::vector<double> times;
  // warm-up frames (texture upload, shader compilation; the auto-adjusting
  // peers settle their sample distances over a few frames)
  const int warmUp = PeerAuto(kind) ? 8 : 2;
  for (int f = 0; f < frames + warmUp; ++f)
  {
    if (kind == "ours-relight")
    {
      // a light that moves every frame (to a new place each time)
      litLight->SetPosition(LitLightPosition[0] + 1e-3 * f, LitLightPosition[1], LitLightPosition[2]);
    }
    if (kind == "ours-remake")
    {
      // the frame after the light moved, which remakes the light volume
      // (before the sweep, a frame whose light had just moved cast shadow
      // rays, and the next, timed alone, remade it)
      litLight->SetPosition(LitLightPosition[0] + 1e-3 * f, LitLightPosition[1], LitLightPosition[2]);
    }
    const double t0 = Now();
    window->Render();
    window->WaitForCompletion();
    if (f >= warmUp)
    {
      times.push_back(Now() - t0);
      for (int pass = 0; profile && pass < ours->GetNumberOfProfiledPasses(); ++pass)
      {
        passTimes[ours->GetProfiledPassName(pass)].push_back(ours->GetProfiledPassSeconds(pass));
        passCPUTimes[ours->GetProfiledPassName(pass)].push_back(ours->GetProfiledPassCPUSeconds(pass));
      }
    }
  }
  ours->SetProfilePasses(false);
  // one more frame of ours, the same image, counting its rays (the count reads
  // the lattice's cells back: not in the timed frames)
  double rays = 0;
  if (litLight)
  {
    litLight->SetPosition(LitLightPosition[0], LitLightPosition[1], LitLightPosition[2]);
  }
  if (isOurs)
  {
    ours->CountRaysOn();
    window->Render();
    rays = ours->GetLastRayCount();
  }
  // error of the last frame against the reference (background black: the
  // image is the volume, over the geometry's colours where there is geometry)
  vtkNew<vtkFloatArray> rgba;
  window->GetRGBAPixelData(0, 0, size - 1, size - 1, 0, rgba, 0);
  std::vector<float> expected(4 * static_cast<size_t>(size) * size);
  std::ifstream in(ReferencePath(variant, n, quick, getppid()), std::ios::binary);
  in.read(reinterpret_cast<char*>(expected.data()), expected.size() * sizeof(float));
  double sum = 0, worst = 0;
  const bool haveReference = static_cast<bool>(in);
  size_t compared = 0;
  for (int y = 0; y < size; y += stride)
  {
    for (int x = 0; x < size; x += stride)
    {
      const size_t p = 4 * (static_cast<size_t>(y) * size + x);
      for (int c = 0; c < 3; ++c)
      {
        const double d = std::fabs(double(rgba->GetValue(p + c)) - expected[p + c]);
        sum += d * d;
        worst = std::max(worst, d);
      }
      ++compared;
    }
  }
  nlohmann::json result = { { "render_s", Median(times) }, { "peak_rss_mb", PeakRSSMB() },
    { "empty_block_fraction", isOurs ? ours->GetEmptyBlockFraction() : 0.0 } };
  if (isOurs)
  {
    result["rays"] = rays;
  }
  if (floorMapper)
  {
    result["coverage"] = floorMapper->GetLastCoverage();
  }
  for (const auto& pass : passTimes)
  {
    result["pass_ms"][pass.first] = 1e3 * Median(pass.second);
    result["pass_cpu_ms"][pass.first] = 1e3 * Median(passCPUTimes[pass.first]);
  }
  // the image sample distance the peer ended on (auto: what it adapted to)
  if (gpuPeer)
  {
    result["image_sample_distance"] = gpuPeer->GetImageSampleDistance();
  }
  else if (fixedPeer)
  {
    result["image_sample_distance"] = fixedPeer->GetImageSampleDistance();
  }
  result["multisamples"] = RenderFramebufferSamples(window);
  if (haveReference)
  {
    result["rms_error"] = std::sqrt(sum / (3.0 * compared));
    result["max_error"] = worst;
    result["error_pixels"] = compared;
  }
  return result;
}

// sparsity jobs: (variant, grid) pairs, each run "ours" (all on) and in every SparsityConfigs
std::vector<std::pair<std::string, int>> SparsityCases(bool quick)
{
  const std::vector<int> grids = Grids(quick);
  if (quick)
  {
    return { { "smoke", grids[0] }, { "smoke+iso", grids[0] } }; // the code paths, fast
  }
  std::vector<std::pair<std::string, int>> cases;
  for (int n : grids)
  {
    for (const char* field : { "smoke", "dense", "opaque" })
    {
      if (n == grids[0] || std::string(field) != "opaque")
      {
        cases.emplace_back(field, n);
      }
    }
  }
  for (const char* variant : { "smoke+mip", "dense+mip", "smoke+iso", "dense+iso" })
  {
    cases.emplace_back(variant, grids[0]);
  }
  return cases;
}

std::vector<std::string> Jobs(bool quick)
{
  std::vector<std::string> jobs;
  const bool interactive = !quick && InteractiveSet();
  for (int n : Grids(quick))
  {
    for (const char* field : Fields)
    {
      jobs.push_back(JobId("reference", field, n));
      jobs.push_back(JobId(WindowKind, field, n, 1.0));
      for (const char* floor : FloorKinds)
      {
        if (!quick && std::string(field) == "smoke")
        {
          jobs.push_back(JobId(floor, field, n, 1.0));
        }
      }
      for (const auto& setting : OurSettings(quick, n))
      {
        jobs.push_back(JobId(setting.first, field, n, setting.second));
      }
      if (interactive)
      {
        for (const char* kind : PeerKinds)
        {
          for (double step : InteractivePeer(kind) ? PeerSteps(kind, quick, n) : std::vector<double>())
          {
            jobs.push_back(JobId(kind, field, n, step));
          }
        }
        continue;
      }
      for (double step : OurSteps(quick, n))
      {
        jobs.push_back(JobId(BeforeKind, field, n, step));
      }
      if (std::string(field).find('+') == std::string::npos) // (not with shading)
      {
        const std::vector<double> plainSteps = OurSteps(quick, n);
        for (double step : PreIntSteps(quick))
        {
          jobs.push_back(JobId(PreIntKind, field, n, step));
          if (std::find(plainSteps.begin(), plainSteps.end(), step) == plainSteps.end())
          {
            jobs.push_back(JobId("ours", field, n, step));
          }
        }
      }
      for (const char* kind : PeerKinds)
      {
        for (double step : PeerSteps(kind, quick, n))
        {
          jobs.push_back(JobId(kind, field, n, step));
        }
      }
    }
  }
  if (interactive)
  {
    return jobs;
  }
  for (int n : Grids(quick))
  {
    jobs.push_back(JobId("reference", "smoke+lit", n));
    for (const char* kind : LitKinds)
    {
      for (double step : LitSteps(quick))
      {
        jobs.push_back(JobId(kind, "smoke+lit", n, step));
      }
    }
  }
  for (const auto& c : SparsityCases(quick))
  {
    if (c.first == "opaque" || c.first.find('+') != std::string::npos)
    {
      jobs.push_back(JobId("ours", c.first, c.second, 1.0)); // the others are timed above
    }
    for (const auto& config : SparsityConfigs)
    {
      jobs.push_back(JobId(config[0], c.first, c.second, 1.0));
    }
  }
  return jobs;
}

std::string CaseName(const std::string& variant, int n, int size)
{
  return Describe(variant) + " " + std::to_string(n) + "^3 -> " + std::to_string(size) + "^2";
}

std::vector<nlohmann::json> Report(const std::map<std::string, nlohmann::json>& results, bool quick)
{
  std::vector<nlohmann::json> lines;
  const int size = Size(quick);
  vtkNew<vtkPlumeVolumeMapper> defaults; // (the default LatticeTolerance)
  auto find = [&](const std::string& id) -> const nlohmann::json* {
    const auto it = results.find(id);
    return it == results.end() || !it->second.contains("render_s") ? nullptr : &it->second;
  };
  auto peerFields = [](nlohmann::json& line, const nlohmann::json& other) {
    line["peer_peak_rss_mb"] = other["peak_rss_mb"];
    if (other.contains("image_sample_distance"))
    {
      line["peer_image_sample_distance"] = other["image_sample_distance"];
    }
    if (other.contains("rms_error"))
    {
      line["peer_error"] = other["rms_error"];
      line["peer_max_error"] = other["max_error"];
    }
  };
  for (int n : Grids(quick))
  {
    for (const char* field : Fields)
    {
      std::remove(ReferencePath(field, n, quick, getpid()).c_str()); // (same parent: this process)
      for (const std::string peer : PeerKinds)
      {
        for (double peerStep : PeerSteps(peer, quick, n))
        {
          const nlohmann::json* other = find(JobId(peer, field, n, peerStep));
          if (!other)
          {
            continue;
          }
          const double p = (*other)["render_s"].get<double>();
          const std::string peerStepText = peer == "gpu-auto" ? std::string("its own") : StepText(peerStep) + " voxel";
          // like for like: ours at the same step; and the per-ray floor: ours at
          // 100-voxel steps (a few samples per ray), ratio = the most that fewer or
          // cheaper samples could give with one ray per pixel
          for (double ourStep : { peerStep, FloorStep })
          {
            const nlohmann::json* ours = find(JobId("ours", field, n, ourStep));
            if (!ours || (ourStep == peerStep && peer == "gpu-auto"))
            {
              continue;
            }
            const bool floor = ourStep == FloorStep;
            const double o = (*ours)["render_s"].get<double>();
            nlohmann::json line = { { "bench", "volume" },
              { "case", CaseName(field, n, size) +
                  (floor ? ", per-ray floor: ours at " + StepText(ourStep) + "-voxel steps (a few samples per ray)"
                         : ", ours step " + StepText(ourStep) + " voxel") +
                  ", peer step " + peerStepText },
              { "ours_s", o }, { "peer", PeerName(peer) }, { "peer_s", p }, { "ratio", p / o }, { "grid", n },
              { "ours_step", ourStep }, { "peer_step", peerStep }, { "peak_rss_mb", (*ours)["peak_rss_mb"] },
              { "empty_block_fraction", (*ours)["empty_block_fraction"] } };
            if (floor)
            {
              line["floor"] = true;
            }
            if (ours->contains("rms_error"))
            {
              line["error"] = (*ours)["rms_error"];
              line["max_error"] = (*ours)["max_error"];
              line["error_pixels"] = (*ours)["error_pixels"];
            }
            peerFields(line, *other);
            lines.push_back(line);
          }
        }
      }
    }
    // headline per field and peer setting: every peer setting against our
    // fastest setting whose RMS and max errors are both not larger than that
    // peer setting's ("headline"); "rms_only" lines: RMS alone not larger (the
    // former headline); "before" lines: ours-base, RMS alone
    for (const char* field : Fields)
    {
      for (const std::string peer : PeerKinds)
      {
        for (double peerStep : PeerSteps(peer, quick, n))
        {
          const nlohmann::json* other = find(JobId(peer, field, n, peerStep));
          if (!other || !other->contains("rms_error"))
          {
            continue;
          }
          const double peerError = (*other)["rms_error"].get<double>();
          const double peerMax = (*other)["max_error"].get<double>();
          for (const char* criterion : { "headline", "rms_only", "before" })
          {
            const bool before = std::string(criterion) == "before";
            const bool withMax = std::string(criterion) == "headline";
            const nlohmann::json* best = nullptr;
            double bestStep = 0;
            int bestLattice = 1;
            double bestTolerance = 0;
            std::vector<std::pair<std::string, double>> candidates;
            if (before)
            {
              for (double ourStep : OurSteps(quick, n))
              {
                candidates.emplace_back(BeforeKind, ourStep);
              }
            }
            else
            {
              candidates = OurSettings(quick, n);
            }
            for (const auto& candidate : candidates)
            {
              const std::string& ourKind = candidate.first;
              const double ourStep = candidate.second;
              const nlohmann::json* ours = find(JobId(ourKind, field, n, ourStep));
              if (!ours || !ours->contains("rms_error") || (*ours)["rms_error"].get<double>() > peerError ||
                (withMax && (*ours)["max_error"].get<double>() > peerMax))
              {
                continue;
              }
              if (!best || (*ours)["render_s"].get<double>() < (*best)["render_s"].get<double>())
              {
                best = ours;
                bestStep = ourStep;
                bestLattice = OurImageSampleDistance(ourKind);
                bestTolerance = OurLatticeTolerance(ourKind);
              }
            }
            if (!best)
            {
              continue;
            }
            const double o = (*best)["render_s"].get<double>();
            const double p = (*other)["render_s"].get<double>();
            nlohmann::json line = { { "bench", "volume" },
              { "case", CaseName(field, n, size) + (before ? ", before (one ray per pixel, threshold 0.995)" : "") +
                  (withMax ? ", equal or lower RMS and max error" : ", equal or lower RMS error") +
                  ": our fastest vs peer step " +
                  (peer == "gpu-auto" ? std::string("its own") : StepText(peerStep) + " voxel") },
              { criterion, true }, { "ours_s", o }, { "peer", PeerName(peer) }, { "peer_s", p },
              { "ratio", p / o }, { "grid", n }, { "ours_step", bestStep }, { "ours_image_sample_distance", bestLattice },
              { "ours_lattice_tolerance", bestTolerance > 0 ? bestTolerance : defaults->GetLatticeTolerance() },
              { "ours_rays", best->value("rays", 0.0) },
              { "peer_step", peerStep },
              { "error", (*best)["rms_error"] }, { "max_error", (*best)["max_error"] },
              { "error_pixels", (*best)["error_pixels"] },
              { "peak_rss_mb", (*best)["peak_rss_mb"] }, { "empty_block_fraction", (*best)["empty_block_fraction"] } };
            if (const nlohmann::json* window = find(JobId(WindowKind, field, n, 1.0)))
            {
              // the window's own frame, and the most any volume renderer could reach
              line["window_s"] = (*window)["render_s"];
              line["window_bound"] = p / (*window)["render_s"].get<double>();
            }
            peerFields(line, *other);
            lines.push_back(line);
          }
        }
      }
    }
  }
  // the frame floors against the fastest peer interactive setting at that grid
  // (any field): ratio = the most any renderer drawing that frame could reach;
  // "needed_s" = the frame that would be 3x that peer
  for (int n : Grids(quick))
  {
    const nlohmann::json* fastest = nullptr;
    std::string fastestName;
    for (const char* field : Fields)
    {
      for (const std::string peer : PeerKinds)
      {
        for (double peerStep : InteractivePeer(peer) ? PeerSteps(peer, quick, n) : std::vector<double>())
        {
          const nlohmann::json* other = find(JobId(peer, field, n, peerStep));
          if (other && (!fastest || (*other)["render_s"].get<double>() < (*fastest)["render_s"].get<double>()))
          {
            fastest = other;
            fastestName = PeerName(peer) + ", " + CaseName(field, n, size) +
              (PeerAuto(peer) ? std::string() : ", step " + StepText(peerStep) + " voxel");
          }
        }
      }
    }
    for (const std::string floor : FloorKinds)
    {
      const nlohmann::json* frame = find(JobId(floor, "smoke", n, 1.0));
      if (!frame || !fastest)
      {
        continue;
      }
      const double o = (*frame)["render_s"].get<double>();
      const double p = (*fastest)["render_s"].get<double>();
      lines.push_back({ { "bench", "volume" },
        { "case", "frame floor " + std::to_string(size) + "^2 (" + floor + ") vs the fastest peer interactive setting at " +
            std::to_string(n) + "^3" },
        { "frame_floor", floor }, { "ours_s", o }, { "peer", fastestName }, { "peer_s", p }, { "ratio", p / o },
        { "needed_s", p / 3.0 }, { "grid", n } });
    }
  }
  // pre-integration vs plain sampling at the same step (ratio = plain s / pre-integrated s)
  for (int n : Grids(quick))
  {
    for (const char* field : Fields)
    {
      for (double step : PreIntSteps(quick))
      {
        const nlohmann::json* pre = find(JobId(PreIntKind, field, n, step));
        const nlohmann::json* plain = find(JobId("ours", field, n, step));
        if (!pre || !plain)
        {
          continue;
        }
        const double o = (*pre)["render_s"].get<double>();
        const double p = (*plain)["render_s"].get<double>();
        nlohmann::json line = { { "bench", "volume" },
          { "case", CaseName(field, n, size) + ", pre-integrated vs plain sampling, step " + StepText(step) + " voxel" },
          { "preint", true }, { "ours_s", o }, { "peer", std::string("vtkPlumeVolumeMapper, plain sampling") },
          { "peer_s", p }, { "ratio", p / o }, { "grid", n }, { "ours_step", step }, { "peer_step", step },
          { "peak_rss_mb", (*pre)["peak_rss_mb"] } };
        if (pre->contains("rms_error"))
        {
          line["error"] = (*pre)["rms_error"];
          line["max_error"] = (*pre)["max_error"];
        }
        peerFields(line, *plain);
        lines.push_back(line);
      }
    }
  }
  // cached lighting (smoke mode): shadow rays and a light moving every frame vs
  // the light volume (ratio = their time / ours)
  for (int n : Grids(quick))
  {
    std::remove(ReferencePath("smoke+lit", n, quick, getpid()).c_str());
    for (double step : LitSteps(quick))
    {
      const nlohmann::json* cached = find(JobId("ours", "smoke+lit", n, step));
      if (!cached)
      {
        continue;
      }
      for (const char* kind : { "ours-shadowrays", "ours-relight", "ours-remake" })
      {
        const nlohmann::json* other = find(JobId(kind, "smoke+lit", n, step));
        if (!other)
        {
          continue;
        }
        const bool relight = std::string(kind) == "ours-relight";
        const bool remake = std::string(kind) == "ours-remake";
        const double o = (*cached)["render_s"].get<double>();
        const double p = (*other)["render_s"].get<double>();
        nlohmann::json line = { { "bench", "volume" },
          { "case", "smoke mode, side light " + std::to_string(n) + "^3 -> " + std::to_string(size) + "^2, step " +
              StepText(step) + " voxel: cached light volume (still light) vs " +
              (relight ? "a light moving every frame (the light volume remade every frame)"
                       : (remake ? "the first still frame after the light moved (the light volume remade)"
                                 : "a shadow ray per sample")) },
          { "lightcache", true }, { "ours_s", o },
          { "peer", std::string("vtkPlumeVolumeMapper, ") +
              (relight ? "light moving every frame" : (remake ? "light volume remade" : "LightCache off")) },
          { "peer_s", p }, { "ratio", p / o }, { "grid", n }, { "ours_step", step }, { "peer_step", step },
          { "peak_rss_mb", (*cached)["peak_rss_mb"] } };
        if (cached->contains("rms_error"))
        {
          line["error"] = (*cached)["rms_error"];
          line["max_error"] = (*cached)["max_error"];
          line["error_pixels"] = (*cached)["error_pixels"];
        }
        peerFields(line, *other);
        lines.push_back(line);
      }
    }
  }
  // sparsity: what each of our switches saves (ratio = time with it off / time with everything on)
  for (const auto& c : SparsityCases(quick))
  {
    const nlohmann::json* on = find(JobId("ours", c.first, c.second, 1.0));
    if (!on)
    {
      continue;
    }
    for (const auto& config : SparsityConfigs)
    {
      const nlohmann::json* off = find(JobId(config[0], c.first, c.second, 1.0));
      if (!off)
      {
        continue;
      }
      const std::string mode = ModeOf(c.first);
      const double o = (*on)["render_s"].get<double>();
      const double p = (*off)["render_s"].get<double>();
      nlohmann::json line = { { "bench", "volume" },
        { "case", "sparsity: " + FieldOf(c.first) + " " + mode + " " + std::to_string(c.second) + "^3 -> " +
            std::to_string(size) + "^2, step 1 voxel, " + config[1] + " vs all on" },
        { "ours_s", o }, { "peer", std::string("vtkPlumeVolumeMapper, ") + config[1] }, { "peer_s", p },
        { "ratio", p / o }, { "grid", c.second }, { "field", FieldOf(c.first) }, { "mode", mode },
        { "peak_rss_mb", (*on)["peak_rss_mb"] }, { "empty_block_fraction", (*on)["empty_block_fraction"] } };
      if (on->contains("rms_error") && off->contains("rms_error"))
      {
        line["error"] = (*on)["rms_error"];
        line["peer_error"] = (*off)["rms_error"];
      }
      lines.push_back(line);
    }
  }
  return lines;
}
}

void RegisterVolume(std::map<std::string, Benchmark>& registry)
{
  Benchmark b;
  b.Description = "raycast 128^3 and 256^3 volumes into 512x512 (smoke and dense fields, shaded, smoke with an opaque sphere; several steps and ray lattices) vs "
                  "vtkGPUVolumeRayCastMapper and vtkFixedPointVolumeRayCastMapper, errors vs the CPU reference; "
                  "sparsity report (skipping / early termination off vs on); smoke mode's cached lighting vs shadow rays";
  b.Jobs = Jobs;
  b.Run = RunJob;
  b.Report = Report;
  registry["volume"] = b;
}

}
}
