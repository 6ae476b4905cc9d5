// `plume bench airlight`: vtkPlumeAirlightPass (closed form, unshadowed) on a
// room (floor, back wall, a box, a sphere) lit by a point light and a spot
// light (35 degrees, exponent 2) in a coloured haze, 512x512, against what a
// user would write instead: brute-force ray marching of the same integral in
// the same full-screen shader (the pass's MarchSteps mode: midpoint rule,
// N samples per ray and light). Each job in its own process: frame time
// (median after two warm-ups), peak memory, and RMS/max error against
// vtkPlumeAirlightReference on a pixel lattice, in % of the airlight
// image's range. Also the scene without the medium, for the pass's own cost,
// and the shadowed path (a cube map for the point light, a map for the spot)
// against the march with the same shadow-map tests, and the share of a
// shadowed frame spent rebuilding a map (the spot light moved every frame).
// Two more peers: Plume's own smoke volume (vtkPlumeVolumeMapper, smoke mode,
// on a constant-density grid: what a Plume user could do without the pass)
// at its defaults and interactive settings, against ours in the same grey
// haze; and the spot textured with room_gobo's image, against the untextured
// spot and the march that reads the image at every sample.
#include "plumeBenchmarks.h"
#include "plumeAirlightTestUtil.h" // For airtest::Compare, the airlight tests' error measure
#include "plumeTestSupport.h"

#include "vtkPlumeAirlightPass.h"
#include "vtkPlumeAirlightReference.h"
#include "vtkPlumeVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkFramebufferPass.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkPNGReader.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPixelBufferObject.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <map>

namespace plume
{
namespace bench
{
namespace
{
std::vector<int> MarchSteps(bool quick)
{
  return quick ? std::vector<int>{ 16, 64 } : std::vector<int>{ 16, 32, 64, 128, 256, 512, 1024 };
}

// The shadowed peers: the march tests every sample in the same shadow maps.
std::vector<int> ShadowMarchSteps(bool quick)
{
  return quick ? std::vector<int>{ 64 } : std::vector<int>{ 64, 128, 256, 512 };
}

// The smoke-volume peer's settings "L:S:SS" (see RunSmokeVolume): the
// mapper's defaults; its interactive ray lattice (InteractiveImageSampleDistance
// 2); that lattice with 4x longer steps and shadow steps.
// --quick: the last only (the defaults cost seconds per frame even at 128x128).
std::vector<std::string> SmokeSettings(bool quick)
{
  return quick ? std::vector<std::string>{ "2:2:4" } : std::vector<std::string>{ "1:0.5:1", "2:0.5:1", "2:2:4" };
}

// The textured spot's brute-force peer (the image read at every sample).
int GoboMarchSteps(bool quick)
{
  return quick ? 64 : 256;
}

void AddBox(vtkRenderer* renderer, const double b[6], double r, double g, double bl)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(b);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, bl);
  renderer->AddActor(actor);
}

void BuildScene(vtkRenderer* renderer)
{
  const double floor[6] = { -5, 5, -0.1, 0, -4, 4 }, wall[6] = { -5, 5, 0, 5, -4.1, -4 },
               box[6] = { -2.5, -1.2, 0, 1.6, -2, -0.8 };
  AddBox(renderer, floor, 0.6, 0.6, 0.55);
  AddBox(renderer, wall, 0.5, 0.55, 0.6);
  AddBox(renderer, box, 0.8, 0.3, 0.2);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(1.6, 0.7, -1.0);
  sphere->SetRadius(0.7);
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(20);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.2, 0.5, 0.8);
  renderer->AddActor(actor);

  vtkNew<vtkLight> point;
  point->SetLightTypeToSceneLight();
  point->SetPositional(true);
  point->SetConeAngle(180);
  point->SetPosition(-4.5, 3.6, 2.5);
  point->SetColor(1.0, 0.9, 0.7);
  renderer->AddLight(point);
  vtkNew<vtkLight> spot;
  spot->SetLightTypeToSceneLight();
  spot->SetPositional(true);
  spot->SetPosition(2.5, 3.5, -1.5);
  spot->SetFocalPoint(0.5, 0.0, -1.5);
  spot->SetConeAngle(35);
  spot->SetExponent(2);
  spot->SetColor(0.7, 0.8, 1.0);
  renderer->AddLight(spot);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.5, 1.6, 6.0);
  camera->SetFocalPoint(-0.3, 1.2, -2.0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(50);
  renderer->ResetCameraClippingRange();
}

void SetMedium(vtkPlumeAirlightPass* pass, bool grey)
{
  if (grey)
  {
    pass->SetScattering(0.2, 0.2, 0.2); // same kt in R, G, B: one look-up for the three
    pass->SetAbsorption(0.05, 0.05, 0.05);
  }
  else
  {
    pass->SetScattering(0.25, 0.2, 0.15);
    pass->SetAbsorption(0.02, 0.04, 0.08);
  }
  pass->SetIntensityScale(40.0);
}

// The frame through `pass` (nullptr: the plain scene) into an RGBA32F target.
test::FloatImage RenderFloat(vtkRenderWindow* window, vtkRenderer* renderer, vtkRenderPass* pass)
{
  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkFramebufferPass> framebuffer;
  framebuffer->SetDelegatePass(pass ? pass : steps.Get());
  framebuffer->SetColorFormat(vtkTextureObject::Float32);
  renderer->SetPass(framebuffer);
  window->Render();
  test::FloatImage image;
  vtkTextureObject* textures[2] = { framebuffer->GetColorTexture(), framebuffer->GetDepthTexture() };
  image.Width = static_cast<int>(textures[0]->GetWidth());
  image.Height = static_cast<int>(textures[0]->GetHeight());
  for (int k = 0; k < 2; ++k)
  {
    const int components = k == 0 ? 4 : 1;
    vtkSmartPointer<vtkPixelBufferObject> pbo;
    pbo.TakeReference(textures[k]->Download());
    const size_t n = static_cast<size_t>(image.Width) * image.Height * components;
    const auto* mapped = static_cast<const float*>(pbo->MapPackedBuffer());
    (k == 0 ? image.RGBA : image.Depth).assign(mapped, mapped + n);
    pbo->UnmapPackedBuffer();
  }
  framebuffer->ReleaseGraphicsResources(window);
  renderer->SetPass(nullptr);
  return image;
}

// The reference's frame on every `stride`-th pixel (NaN elsewhere): the
// surfaces of `plain` (the scene without the medium) dimmed by `medium`'s
// haze plus its airlight, and the airlight alone.
struct Expected
{
  test::FloatImage Frame, Airlight;
};

Expected ReferenceFrame(
  vtkRenderer* renderer, vtkPlumeAirlightPass* medium, bool shadowed, const test::FloatImage& plain, int stride)
{
  vtkNew<vtkPlumeAirlightReference> reference;
  reference->SetScattering(medium->GetScattering());
  reference->SetAbsorption(medium->GetAbsorption());
  reference->SetIntensityScale(medium->GetIntensityScale());
  if (shadowed)
  {
    reference->SetOccluders(renderer); // exact ray-cast shadows
  }
  reference->SetLights(renderer);
  std::vector<float> surface(plain.RGBA);
  for (float& v : surface)
  {
    v = std::min(std::max(v, 0.0f), 1.0f);
  }
  Expected expected;
  expected.Frame.Width = expected.Airlight.Width = plain.Width;
  expected.Frame.Height = expected.Airlight.Height = plain.Height;
  reference->ComputeImage(renderer, plain.Width, plain.Height, surface.data(), plain.Depth.data(),
    expected.Frame.RGBA, stride, &expected.Airlight.RGBA);
  return expected;
}

// RMS and max error of `image` against the reference's pixels, in units of
// the reference airlight's range (the airlight tests' measure): error,
// error_max, error_pixels.
nlohmann::json ErrorAgainst(const test::FloatImage& image, const Expected& expected)
{
  const airtest::Error e = airtest::Compare(image, expected.Frame, expected.Airlight);
  return { { "error", e.RMS }, { "error_max", e.Max }, { "error_pixels", e.Pixels } };
}

// Median time of `frames` renders after `warmups`; the camera turns by half
// a degree each frame (a real re-render); `beforeFrame(f)` may change the scene.
// `cpu` (optional): the median CPU time of the process per frame (all its
// threads, llvmpipe's included: less sensitive to the machine's load than
// wall time).
double TimeFrames(vtkRenderWindow* window, vtkRenderer* renderer, int frames, int warmups = 2,
  const std::function<void(int)>& beforeFrame = nullptr, double* cpu = nullptr)
{
  std::vector<double> times, cpuTimes;
  for (int f = 0; f < frames + warmups; ++f)
  {
    renderer->GetActiveCamera()->Azimuth(f % 2 ? 0.5 : -0.5);
    if (beforeFrame)
    {
      beforeFrame(f);
    }
    const double t0 = Now();
    const std::clock_t c0 = std::clock();
    window->Render();
    window->WaitForCompletion();
    if (f >= warmups)
    {
      times.push_back(Now() - t0);
      cpuTimes.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
    }
  }
  if (cpu)
  {
    *cpu = Median(cpuTimes);
  }
  return Median(times);
}

// The peer a Plume user has today: vtkPlumeVolumeMapper in smoke mode on a
// constant-density grid over the room (and the camera: the haze lies between
// it and the room) in the grey haze of the "grey" job (the mapper's
// extinction is one scalar, so it cannot do a coloured one), lit by the
// scene's two lights and self-shadowed by its shadow rays. Its extinction
// is the haze's kt and its colour the albedo ks/kt, ambient 0; the mapper
// treats lights as directional (no inverse-square falloff, no cone), so its
// brightness cannot match the point source's everywhere: its diffuse factor
// is the single scale that fits the reference best (least squares over the
// error lattice, from a frame at diffuse 0 and one at 1: the frame is affine
// in it), the most favourable choice for the peer. `setting`
// "L:S:SS": ray lattice L (ImageSampleDistance; 2 is the mapper's
// interactive default), step S and shadow step SS in voxels (defaults 0.5, 1).
nlohmann::json RunSmokeVolume(const Context& context, vtkRenderWindow* window, vtkRenderer* renderer,
  const std::string& setting, int frames)
{
  const double spacing = 0.2; // world units: 61 x 37 x 56 nodes
  const double lo[3] = { -6, -0.1, -4.1 }, hi[3] = { 6, 7, 7 };
  vtkNew<vtkImageData> grid;
  int dims[3];
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = static_cast<int>(std::ceil((hi[a] - lo[a]) / spacing)) + 1;
  }
  grid->SetDimensions(dims);
  grid->SetOrigin(lo[0], lo[1], lo[2]);
  grid->SetSpacing(spacing, spacing, spacing);
  vtkNew<vtkFloatArray> density;
  density->SetName("density");
  density->SetNumberOfValues(grid->GetNumberOfPoints());
  density->Fill(1.0f);
  grid->GetPointData()->SetScalars(density);

  vtkNew<vtkPlumeAirlightPass> medium; // holds the haze's coefficients for the reference
  SetMedium(medium, true);
  const double ks = medium->GetScattering()[0], kt = ks + medium->GetAbsorption()[0];
  vtkNew<vtkPlumeVolumeMapper> mapper;
  mapper->SetInputData(grid);
  mapper->SetRenderMode(vtkPlumeVolumeMapper::RENDER_SMOKE);
  mapper->SetTransferFunctionRange(0.0, 2.0); // the data's range is a single value
  mapper->SetOpacityUnitDistance(1.0);        // opacity per world unit: sigma = kt
  int lattice = 1;
  double step = 0.5, shadowStep = 1.0;
  std::sscanf(setting.c_str(), "%d:%lf:%lf", &lattice, &step, &shadowStep);
  mapper->SetImageSampleDistance(lattice);
  mapper->SetSampleDistance(step);
  mapper->SetShadowSampleDistance(shadowStep);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, ks / kt, ks / kt, ks / kt);
  color->AddRGBPoint(2.0, ks / kt, ks / kt, ks / kt);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 1.0 - std::exp(-kt));
  opacity->AddPoint(2.0, 1.0 - std::exp(-kt));
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetInterpolationTypeToLinear();
  mapper->ApplyDefaultLighting(property);
  property->SetAmbient(0.0); // single scattering of the lamps only
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);

  // Drawn straight into the window (a plain vtkRenderer). Timed first: the
  // frame's cost does not depend on the brightness fitted below.
  const double frameTime = TimeFrames(window, renderer, frames, 1);
  // The brightness scale, then the error at that scale.
  const int stride = context.Quick ? 4 : 16;
  volume->VisibilityOff();
  const Expected expected = ReferenceFrame(renderer, medium, false, RenderFloat(window, renderer, nullptr), stride);
  volume->VisibilityOn();
  property->SetDiffuse(0.0);
  const test::FloatImage dark = RenderFloat(window, renderer, nullptr);
  property->SetDiffuse(1.0);
  const test::FloatImage lit = RenderFloat(window, renderer, nullptr);
  double num = 0, den = 0;
  for (size_t p = 0; p < expected.Frame.RGBA.size() / 4; ++p)
  {
    for (int c = 0; c < 3 && !std::isnan(expected.Frame.RGBA[4 * p]); ++c)
    {
      const double d = double(lit.RGBA[4 * p + c]) - dark.RGBA[4 * p + c];
      num += d * (double(expected.Frame.RGBA[4 * p + c]) - dark.RGBA[4 * p + c]);
      den += d * d;
    }
  }
  const double scale = den > 0 ? std::max(num / den, 0.0) : 0.0;
  // the frame at that diffuse factor (with ambient 0 the radiance is linear
  // in it, and the brightest sample stays below 1, so the rays' termination
  // does not change: checked once against a render at `scale`, same error)
  test::FloatImage image = dark;
  for (size_t k = 0; k < image.RGBA.size(); ++k)
  {
    image.RGBA[k] = static_cast<float>(dark.RGBA[k] + scale * (double(lit.RGBA[k]) - dark.RGBA[k]));
  }
  nlohmann::json result = { { "frame_s", frameTime }, { "peak_rss_mb", PeakRSSMB() }, { "diffuse", scale },
    { "grid", { dims[0], dims[1], dims[2] } }, { "lattice", mapper->GetLastImageSampleDistance() } };
  result.update(ErrorAgainst(image, expected));
  return result;
}

nlohmann::json RunJob(const Context& context, const std::string& jobName)
{
  // "NAME@S": the job at S x S (the fixed vs per-pixel split of the pass's cost).
  std::string job = jobName;
  int size = context.Quick ? 128 : 512;
  const size_t at = job.find('@');
  if (at != std::string::npos)
  {
    size = std::stoi(job.substr(at + 1));
    job = job.substr(0, at);
  }
  // "grey_J": job J in the grey haze (one look-up for R, G, B)
  bool grey = job == "grey";
  if (job.rfind("grey_", 0) == 0)
  {
    grey = true;
    job = job.substr(5);
  }
  // "points_J": job J with the spot light made a point light (cone 180) at
  // the same place: two lights at the closed form's cheapest (two table
  // look-ups each, no spot sub-intervals), for the floor of the per-pixel cost.
  bool points = false;
  if (job.rfind("points_", 0) == 0)
  {
    points = true;
    job = job.substr(7);
  }
  // "spotN_J": job J with SpotSteps N (default 8).
  int spotSteps = 0;
  if (job.rfind("spot", 0) == 0 && job.find('_') != std::string::npos)
  {
    spotSteps = std::stoi(job.substr(4, job.find('_') - 4));
    job = job.substr(job.find('_') + 1);
  }
  const int frames = context.Quick ? 3 : 7;
  auto window = context.MakeWindow(size, size);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.15, 0.3);
  window->AddRenderer(renderer);
  BuildScene(renderer);
  if (points)
  {
    vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(1))->SetConeAngle(180);
  }
  if (job.rfind("smoke:", 0) == 0)
  {
    // a slow peer (seconds per frame at 512x512): one warm-up, two frames
    return RunSmokeVolume(context, window, renderer, job.substr(6), context.Quick ? 1 : 2);
  }
  if (job.rfind("gobo", 0) == 0)
  {
    // "gobo", "gobo_march:N": the spot projects room_gobo's venetian-blind
    // slats (Examples/Scenes/room_gobo_slats.png, 64 x 64); then as "ours" / "march:N".
    vtkNew<vtkPNGReader> slats;
    slats->SetFileName(PLUME_SOURCE_DIR "/Examples/Scenes/room_gobo_slats.png");
    slats->Update();
    vtkPlumeAirlightPass::SetLightTexture(
      vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(1)), slats->GetOutput());
    job = job == "gobo" ? "ours" : job.substr(5);
  }
  if (job.rfind("lights:", 0) == 0)
  {
    // "lights:N": the scene's two lights plus N - 2 weak point lights under
    // the ceiling; above 8 the lights take a second (third...) light group.
    const int n = std::stoi(job.substr(7));
    for (int k = 2; k < n; ++k)
    {
      vtkNew<vtkLight> extra;
      extra->SetLightTypeToSceneLight();
      extra->SetPositional(true);
      extra->SetConeAngle(180);
      extra->SetPosition(-4.0 + 0.55 * k, 3.0 + 0.2 * (k % 3), -3.5 + 0.35 * k);
      extra->SetColor(0.9, 0.9, 0.8);
      extra->SetIntensity(0.3);
      renderer->AddLight(extra);
    }
  }
  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkPlumeAirlightPass> pass;
  pass->SetDelegatePass(steps);
  // Shadowed jobs: "shadow" (ours), "shadow_rebake" (ours with the maps
  // rebuilt every frame: the light moves by 1e-6), "shadow_march:N".
  const bool shadowed = job.rfind("shadow", 0) == 0;
  pass->SetShadows(shadowed);
  if (shadowed && context.Quick)
  {
    // --quick: maps of 256 texels per side (default 1024: a point light's
    // 3072 x 2048 atlas made up most of the quick run's time)
    pass->SetShadowMapSize(256);
  }
  if (job != "opaque")
  {
    SetMedium(pass, grey);
  }
  if (job.rfind("march:", 0) == 0)
  {
    pass->SetMarchSteps(std::stoi(job.substr(6)));
  }
  if (job.rfind("shadow_march:", 0) == 0)
  {
    pass->SetMarchSteps(std::stoi(job.substr(13)));
  }
  if (job == "shadow_nominmax")
  {
    // ours shadowed without the min-max mipmaps: every march step tested
    pass->SetShadowMinMax(false);
  }
  if (job.rfind("shadow_steps:", 0) == 0)
  {
    // ours shadowed with N march steps instead of 64: with N = 8, what a march
    // that skipped every run of 8 steps (min-max shadow mipmaps, all runs
    // decided) would cost at best
    pass->SetShadowSteps(std::stoi(job.substr(13)));
  }
  if (spotSteps > 0)
  {
    pass->SetSpotSteps(spotSteps);
  }
  if (job.rfind("down:", 0) == 0)
  {
    // "down:D", "down:D:TOL" or "down:D:TOL:L": the airlight lattice every D
    // pixels (1: none), tolerance TOL, L levels.
    pass->SetDownsampling(std::stoi(job.substr(5)));
    const size_t colon = job.find(':', 5);
    if (colon != std::string::npos)
    {
      pass->SetUpsamplingTolerance(std::stod(job.substr(colon + 1)));
      const size_t levels = job.find(':', colon + 1);
      if (levels != std::string::npos)
      {
        pass->SetLatticeLevels(std::stoi(job.substr(levels + 1)));
      }
    }
  }
  if (job == "floor")
  {
    // The pass with a medium but no positional light: its framebuffer, the
    // full-screen pass and the extinction, no airlight (the pass's floor).
    vtkLightCollection* lights = renderer->GetLights();
    for (int k = 0; k < lights->GetNumberOfItems(); ++k)
    {
      vtkLight::SafeDownCast(lights->GetItemAsObject(k))->SetPositional(false);
    }
  }
  vtkNew<vtkFramebufferPass> copy;
  renderer->SetPass(pass);
  if (job == "copy")
  {
    // VTK's own trivial full-screen pass: the scene into a framebuffer, copied to the window.
    copy->SetDelegatePass(steps);
    renderer->SetPass(copy);
  }
  vtkLight* spot = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(1));
  double frameCPU = 0.0;
  const double frameTime = TimeFrames(
    window, renderer, frames, 2,
    [&](int f) {
      if (job == "shadow_rebake")
      {
        spot->SetPosition(2.5, 3.5, f % 2 ? -1.5 : -1.500001); // a changed light: its map is rebuilt
      }
    },
    &frameCPU);
  nlohmann::json result = { { "frame_s", frameTime }, { "frame_cpu_s", frameCPU }, { "peak_rss_mb", PeakRSSMB() },
    { "shadowed_lights", pass->GetNumberOfShadowedLights() }, { "bakes", pass->GetNumberOfShadowMapBakes() },
    { "light_groups", pass->GetNumberOfLightGroups() }, { "downsampling", pass->GetDownsampling() },
    { "tolerance", pass->GetUpsamplingTolerance() }, { "lattice_levels", pass->GetLatticeLevels() },
    { "refined_cells", pass->GetLastRefinedCellFraction() },
    { "refined_pixels", pass->GetLastRefinedPixelFraction() } };
  if (std::getenv("PLUME_BENCH_AIRLIGHT_PROFILE") && job != "copy")
  {
    // Per-pass times (the pass's ProfilePasses: the GL work finished after
    // each pass), medians of `frames` more frames, ms.
    pass->ProfilePassesOn();
    std::map<std::string, std::vector<double>> passes, passesCPU;
    TimeFrames(window, renderer, frames, 1, [&](int f) {
      for (int k = 0; f > 1 && k < pass->GetNumberOfProfiledPasses(); ++k)
      {
        passes[pass->GetProfiledPassName(k)].push_back(1e3 * pass->GetProfiledPassSeconds(k));
        passesCPU[pass->GetProfiledPassName(k)].push_back(1e3 * pass->GetProfiledPassCPUSeconds(k));
      }
    });
    pass->ProfilePassesOff();
    nlohmann::json times, cpuTimes;
    for (auto& p : passes)
    {
      times[p.first] = Median(p.second);
      cpuTimes[p.first] = Median(passesCPU[p.first]);
    }
    result["passes_ms"] = times;
    result["passes_cpu_ms"] = cpuTimes;
  }
  if (job == "opaque" || job == "shadow_rebake" || job == "floor" || job == "copy")
  {
    return result;
  }

  // Error against the reference on a grid of pixels (every `stride`-th;
  // shadowed: a quarter as many pixels, the reference's exact shadow rays are slow).
  // Strides prime to the airlight lattice's spacing (Downsampling 2, 4, 8):
  // the error pixels fall at every phase of its cells, not on its nodes only.
  const int stride = (context.Quick ? 3 : 13) * (shadowed ? 2 : 1);
  // the surfaces as the pass draws them without a medium (a textured spot's image on them)
  vtkNew<vtkPlumeAirlightPass> surfaces;
  surfaces->SetDelegatePass(steps);
  const test::FloatImage plain = RenderFloat(window, renderer, surfaces);
  const test::FloatImage image = RenderFloat(window, renderer, pass);
  result.update(ErrorAgainst(image, ReferenceFrame(renderer, pass, shadowed, plain, stride)));
  return result;
}

std::vector<std::string> Jobs(bool quick)
{
  const std::string half = quick ? "@64" : "@256";
  std::vector<std::string> jobs = { "opaque", "ours", "grey", "shadow", "shadow_rebake", "opaque" + half,
    "ours" + half, "floor", "copy", "down:1", "down:2", "down:4", "down:8", "down:8:0.01", "down:8:0", "grey_down:8",
    "down:8:0.005:1", "down:8:0.005:2", "points_down:1", "points_down:8", "spot4_down:8", "spot2_down:8",
    "lights:7", "lights:8", "lights:9", "lights:16", "lights:17" };
  for (int n : MarchSteps(quick))
  {
    jobs.push_back("march:" + std::to_string(n));
  }
  for (int n : ShadowMarchSteps(quick))
  {
    jobs.push_back("shadow_march:" + std::to_string(n));
  }
  for (const std::string& setting : SmokeSettings(quick))
  {
    jobs.push_back("smoke:" + setting);
  }
  jobs.push_back("shadow_steps:8");
  jobs.push_back("shadow_nominmax");
  jobs.push_back("gobo");
  jobs.push_back("gobo_march:" + std::to_string(GoboMarchSteps(quick)));
  return jobs;
}

std::vector<nlohmann::json> Report(const std::map<std::string, nlohmann::json>& results, bool quick)
{
  std::vector<nlohmann::json> lines;
  const auto ours = results.find("ours");
  const auto opaque = results.find("opaque");
  if (ours == results.end())
  {
    return lines;
  }
  const std::string size = quick ? "128x128" : "512x512";
  const double oursTime = ours->second.value("frame_s", 0.0);
  const double oursError = ours->second.value("error", 0.0);
  std::string matching;
  for (int n : MarchSteps(quick))
  {
    const auto peer = results.find("march:" + std::to_string(n));
    if (peer == results.end())
    {
      continue;
    }
    const double peerTime = peer->second.value("frame_s", 0.0);
    const double peerError = peer->second.value("error", 0.0);
    nlohmann::json line = { { "bench", "airlight" }, { "case", size + " point+spot, march " + std::to_string(n) },
      { "ours_s", oursTime }, { "peer", "shader ray march, " + std::to_string(n) + " steps" },
      { "peer_s", peerTime }, { "ratio", oursTime > 0 ? peerTime / oursTime : 0.0 }, { "error", oursError },
      { "peer_error", peerError }, { "error_max", ours->second.value("error_max", 0.0) },
      { "peer_error_max", peer->second.value("error_max", 0.0) },
      { "peak_rss_mb", ours->second.value("peak_rss_mb", 0.0) },
      { "peer_peak_rss_mb", peer->second.value("peak_rss_mb", 0.0) } };
    if (matching.empty() && peerError <= oursError)
    {
      matching = std::to_string(n);
      line["equal_error"] = true; // the fewest steps whose error is at most ours
    }
    lines.push_back(line);
  }
  // Shadowed: the point light (cube map) and the spot light (one map) both shadowed.
  const auto shadow = results.find("shadow");
  if (shadow != results.end())
  {
    const double shadowTime = shadow->second.value("frame_s", 0.0);
    const double shadowError = shadow->second.value("error", 0.0);
    bool matched = false;
    for (int n : ShadowMarchSteps(quick))
    {
      const auto peer = results.find("shadow_march:" + std::to_string(n));
      if (peer == results.end())
      {
        continue;
      }
      const double peerTime = peer->second.value("frame_s", 0.0);
      const double peerError = peer->second.value("error", 0.0);
      nlohmann::json line = { { "bench", "airlight" },
        { "case", size + " shadowed point+spot, march " + std::to_string(n) }, { "ours_s", shadowTime },
        { "peer", "shader ray march with shadow-map tests, " + std::to_string(n) + " steps" },
        { "peer_s", peerTime }, { "ratio", shadowTime > 0 ? peerTime / shadowTime : 0.0 },
        { "error", shadowError }, { "peer_error", peerError },
        { "error_max", shadow->second.value("error_max", 0.0) },
        { "peer_error_max", peer->second.value("error_max", 0.0) },
        { "shadowed_lights", shadow->second.value("shadowed_lights", 0) },
        { "peak_rss_mb", shadow->second.value("peak_rss_mb", 0.0) },
        { "peer_peak_rss_mb", peer->second.value("peak_rss_mb", 0.0) } };
      if (!matched && peerError <= shadowError)
      {
        matched = true;
        line["equal_error"] = true;
      }
      lines.push_back(line);
    }
    const auto eight = results.find("shadow_steps:8");
    if (eight != results.end())
    {
      const double eightTime = eight->second.value("frame_s", 0.0);
      lines.push_back({ { "bench", "airlight" },
        { "case", size + " shadowed point+spot, 8 march steps (the bound for skipping runs of 8)" },
        { "ours_s", shadowTime }, { "peer", "ours with ShadowSteps 8" }, { "peer_s", eightTime },
        { "ratio", shadowTime > 0 ? eightTime / shadowTime : 0.0 }, { "error", shadowError },
        { "peer_error", eight->second.value("error", 0.0) }, { "error_max", shadow->second.value("error_max", 0.0) },
        { "peer_error_max", eight->second.value("error_max", 0.0) },
        { "peak_rss_mb", shadow->second.value("peak_rss_mb", 0.0) } });
    }
    const auto perStep = results.find("shadow_nominmax");
    if (perStep != results.end())
    {
      const double perStepTime = perStep->second.value("frame_s", 0.0);
      lines.push_back({ { "bench", "airlight" },
        { "case", size + " shadowed point+spot, min-max shadow mipmaps vs every step tested" },
        { "ours_s", shadowTime }, { "peer", "ours with ShadowMinMax off" }, { "peer_s", perStepTime },
        { "ratio", shadowTime > 0 ? perStepTime / shadowTime : 0.0 }, { "error", shadowError },
        { "peer_error", perStep->second.value("error", 0.0) },
        { "error_max", shadow->second.value("error_max", 0.0) },
        { "peer_error_max", perStep->second.value("error_max", 0.0) },
        { "peak_rss_mb", shadow->second.value("peak_rss_mb", 0.0) } });
    }
    const auto rebake = results.find("shadow_rebake");
    if (rebake != results.end())
    {
      const double rebakeTime = rebake->second.value("frame_s", 0.0);
      lines.push_back({ { "bench", "airlight" },
        { "case", size + " shadow-map rebuild share (spot map rebuilt every frame)" }, { "ours_s", shadowTime },
        { "peer", "ours, light moved every frame" }, { "peer_s", rebakeTime },
        { "ratio", shadowTime > 0 ? rebakeTime / shadowTime : 0.0 },
        { "rebuild_share", rebakeTime > 0 ? std::max(0.0, rebakeTime - shadowTime) / rebakeTime : 0.0 },
        { "bakes", rebake->second.value("bakes", 0) },
        { "peak_rss_mb", rebake->second.value("peak_rss_mb", 0.0) } });
    }
  }
  // Where the pass's time goes: added time at S and S/2 -> a per-pixel and a fixed part.
  const std::string half = quick ? "@64" : "@256";
  const auto opaqueHalf = results.find("opaque" + half);
  const auto oursHalf = results.find("ours" + half);
  if (opaque != results.end() && opaqueHalf != results.end() && oursHalf != results.end())
  {
    const double n = quick ? 128.0 * 128.0 : 512.0 * 512.0;
    const double added = oursTime - opaque->second.value("frame_s", 0.0);
    const double addedHalf = oursHalf->second.value("frame_s", 0.0) - opaqueHalf->second.value("frame_s", 0.0);
    const double perPixel = (added - addedHalf) / (0.75 * n);
    const double fixed = added - perPixel * n;
    lines.push_back({ { "bench", "airlight" }, { "case", size + " pass cost split (added time at full and half size)" },
      { "ours_s", oursTime }, { "peer", "ours at half the width and height" },
      { "peer_s", oursHalf->second.value("frame_s", 0.0) },
      { "ratio", oursTime > 0 ? oursHalf->second.value("frame_s", 0.0) / oursTime : 0.0 },
      { "added_ms", 1e3 * added }, { "added_half_ms", 1e3 * addedHalf }, { "per_pixel_ns", 1e9 * perPixel },
      { "fixed_ms", 1e3 * fixed }, { "per_pixel_share", added > 0 ? perPixel * n / added : 0.0 },
      { "peak_rss_mb", ours->second.value("peak_rss_mb", 0.0) } });
  }
  // The airlight lattice (Downsampling D) against the full resolution,
  // and the floor of any full-screen pass on this renderer.
  for (const std::string d :
    { "1", "2", "4", "8", "8:0.01", "8:0", "8:0.005:1", "8:0.005:2" })
  {
    const auto down = results.find("down:" + d);
    if (down == results.end())
    {
      continue;
    }
    const double downTime = down->second.value("frame_s", 0.0);
    nlohmann::json line = { { "bench", "airlight" },
      { "case", size + " point+spot, airlight lattice every " + d.substr(0, 1) + " pixels, tolerance " +
          std::to_string(down->second.value("tolerance", 0.0)) + ", " +
          std::to_string(down->second.value("lattice_levels", 1)) + " level(s)" },
      { "refined_cells", down->second.value("refined_cells", 0.0) },
      { "refined_pixels", down->second.value("refined_pixels", 0.0) },
      { "ours_s", downTime }, { "peer", "ours at full resolution" }, { "peer_s", oursTime },
      { "ratio", downTime > 0 ? oursTime / downTime : 0.0 }, { "error", down->second.value("error", 0.0) },
      { "peer_error", oursError }, { "error_max", down->second.value("error_max", 0.0) },
      { "peer_error_max", ours->second.value("error_max", 0.0) },
      { "peak_rss_mb", down->second.value("peak_rss_mb", 0.0) } };
    if (opaque != results.end())
    {
      line["added_ms"] = 1e3 * (downTime - opaque->second.value("frame_s", 0.0));
    }
    lines.push_back(line);
  }
  // The floor of the lattice frame's per-pixel work: the two lights at their
  // cheapest (the spot made a point light: two table look-ups per light and
  // channel, no spot sub-intervals) at every pixel, against the pass with no
  // light; per pixel, and over the default lattice's refined pixels only.
  const auto pointsFull = results.find("points_down:1");
  const auto floorFrame = results.find("floor");
  if (pointsFull != results.end() && floorFrame != results.end())
  {
    const double n = quick ? 128.0 * 128.0 : 512.0 * 512.0;
    const double t = pointsFull->second.value("frame_s", 0.0), t0 = floorFrame->second.value("frame_s", 0.0);
    const double refined = ours->second.value("refined_pixels", 0.0);
    lines.push_back({ { "bench", "airlight" },
      { "case", size + " floor: two point lights at every pixel (the closed form at its cheapest)" },
      { "ours_s", t }, { "peer", "the pass with no light" }, { "peer_s", t0 }, { "ratio", t > 0 ? t0 / t : 0.0 },
      { "per_pixel_ns", 1e9 * (t - t0) / n }, { "refined_pixels", refined },
      { "over_refined_pixels_ms", 1e3 * (t - t0) * refined },
      { "error", pointsFull->second.value("error", 0.0) },
      { "error_max", pointsFull->second.value("error_max", 0.0) },
      { "peak_rss_mb", pointsFull->second.value("peak_rss_mb", 0.0) } });
  }
  // Light groups: the frame with N lights against 8 (one group); the cost of a
  // group beyond the first is what a 9th light costs over an 8th.
  const auto eight = results.find("lights:8");
  const auto seven = results.find("lights:7");
  if (eight != results.end() && seven != results.end())
  {
    const double t8 = eight->second.value("frame_s", 0.0);
    const double perLight = t8 - seven->second.value("frame_s", 0.0);
    for (const char* n : { "9", "16", "17" })
    {
      const auto more = results.find(std::string("lights:") + n);
      if (more == results.end())
      {
        continue;
      }
      const double t = more->second.value("frame_s", 0.0);
      const int groups = more->second.value("light_groups", 0);
      lines.push_back({ { "bench", "airlight" },
        { "case", size + " " + n + " point lights (" + std::to_string(groups) + " light groups)" },
        { "ours_s", t }, { "peer", "ours with 8 lights (one group)" }, { "peer_s", t8 },
        { "ratio", t > 0 ? t8 / t : 0.0 }, { "light_groups", groups },
        { "added_ms", 1e3 * (t - t8) }, { "eighth_light_ms", 1e3 * perLight },
        { "error", more->second.value("error", 0.0) }, { "error_max", more->second.value("error_max", 0.0) },
        { "peak_rss_mb", more->second.value("peak_rss_mb", 0.0) } });
    }
  }
  const auto floorJob = results.find("floor");
  const auto copyJob = results.find("copy");
  if (opaque != results.end() && floorJob != results.end() && copyJob != results.end())
  {
    const double opaqueTime = opaque->second.value("frame_s", 0.0);
    lines.push_back({ { "bench", "airlight" },
      { "case", size + " floor: the pass without lights vs VTK's framebuffer copy" },
      { "ours_s", floorJob->second.value("frame_s", 0.0) }, { "peer", "vtkFramebufferPass (scene + full-screen copy)" },
      { "peer_s", copyJob->second.value("frame_s", 0.0) },
      { "ratio", copyJob->second.value("frame_s", 0.0) / std::max(floorJob->second.value("frame_s", 0.0), 1e-9) },
      { "added_ms", 1e3 * (floorJob->second.value("frame_s", 0.0) - opaqueTime) },
      { "peer_added_ms", 1e3 * (copyJob->second.value("frame_s", 0.0) - opaqueTime) },
      { "peak_rss_mb", floorJob->second.value("peak_rss_mb", 0.0) } });
  }
  const auto grey = results.find("grey");
  // Plume's smoke volume (vtkPlumeVolumeMapper) against ours in the same grey haze.
  for (const std::string& setting : SmokeSettings(quick))
  {
    const auto peer = results.find("smoke:" + setting);
    if (grey == results.end() || peer == results.end())
    {
      continue;
    }
    const double greyTime = grey->second.value("frame_s", 0.0);
    const double peerTime = peer->second.value("frame_s", 0.0);
    const auto dims = peer->second.value("grid", std::vector<int>{ 0, 0, 0 });
    const std::string grid =
      std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" + std::to_string(dims[2]);
    const std::string name = setting == "1:0.5:1" ? "defaults" : "interactive " + setting;
    lines.push_back({ { "bench", "airlight" }, { "case", size + " grey haze point+spot vs Plume's smoke volume, " + name },
      { "ours_s", greyTime },
      { "peer", "vtkPlumeVolumeMapper smoke mode, constant density on " + grid +
          ", lattice:step:shadow step " + setting + " (brightness fitted)" },
      { "peer_s", peerTime }, { "ratio", greyTime > 0 ? peerTime / greyTime : 0.0 },
      { "error", grey->second.value("error", 0.0) }, { "peer_error", peer->second.value("error", 0.0) },
      { "error_max", grey->second.value("error_max", 0.0) },
      { "peer_error_max", peer->second.value("error_max", 0.0) },
      { "peer_diffuse", peer->second.value("diffuse", 0.0) }, { "peer_lattice", peer->second.value("lattice", 0) },
      { "peak_rss_mb", grey->second.value("peak_rss_mb", 0.0) },
      { "peer_peak_rss_mb", peer->second.value("peak_rss_mb", 0.0) } });
  }
  // The textured spot: against the same spot untextured, and the march that reads the image per sample.
  const auto gobo = results.find("gobo");
  if (gobo != results.end())
  {
    const double goboTime = gobo->second.value("frame_s", 0.0);
    nlohmann::json line = { { "bench", "airlight" },
      { "case", size + " point+spot, the spot textured (room_gobo's slats, 64x64)" }, { "ours_s", goboTime },
      { "peer", "ours, the same spot untextured" }, { "peer_s", oursTime },
      { "ratio", goboTime > 0 ? oursTime / goboTime : 0.0 }, { "added_ms", 1e3 * (goboTime - oursTime) },
      { "error", gobo->second.value("error", 0.0) }, { "peer_error", oursError },
      { "error_max", gobo->second.value("error_max", 0.0) },
      { "peer_error_max", ours->second.value("error_max", 0.0) },
      { "peak_rss_mb", gobo->second.value("peak_rss_mb", 0.0) },
      { "peer_peak_rss_mb", ours->second.value("peak_rss_mb", 0.0) } };
    lines.push_back(line);
    const std::string n = std::to_string(GoboMarchSteps(quick));
    const auto march = results.find("gobo_march:" + n);
    if (march != results.end())
    {
      const double marchTime = march->second.value("frame_s", 0.0);
      lines.push_back({ { "bench", "airlight" },
        { "case", size + " point+spot, the spot textured (room_gobo's slats), march " + n }, { "ours_s", goboTime },
        { "peer", "shader ray march reading the image per sample, " + n + " steps" }, { "peer_s", marchTime },
        { "ratio", goboTime > 0 ? marchTime / goboTime : 0.0 }, { "error", gobo->second.value("error", 0.0) },
        { "peer_error", march->second.value("error", 0.0) }, { "error_max", gobo->second.value("error_max", 0.0) },
        { "peer_error_max", march->second.value("error_max", 0.0) },
        { "peak_rss_mb", gobo->second.value("peak_rss_mb", 0.0) },
        { "peer_peak_rss_mb", march->second.value("peak_rss_mb", 0.0) } });
    }
  }
  if (grey != results.end())
  {
    const double greyTime = grey->second.value("frame_s", 0.0);
    lines.push_back({ { "bench", "airlight" }, { "case", size + " grey medium (one look-up for R, G, B)" },
      { "ours_s", greyTime }, { "peer", "ours, coloured medium (a look-up per channel)" }, { "peer_s", oursTime },
      { "ratio", greyTime > 0 ? oursTime / greyTime : 0.0 }, { "error", grey->second.value("error", 0.0) },
      { "error_max", grey->second.value("error_max", 0.0) },
      { "peak_rss_mb", grey->second.value("peak_rss_mb", 0.0) },
      { "peer_peak_rss_mb", ours->second.value("peak_rss_mb", 0.0) } });
  }
  if (opaque != results.end())
  {
    const double opaqueTime = opaque->second.value("frame_s", 0.0);
    lines.push_back({ { "bench", "airlight" }, { "case", size + " cost of the pass" }, { "ours_s", oursTime },
      { "peer", "the same scene without a medium" }, { "peer_s", opaqueTime },
      { "ratio", oursTime > 0 ? opaqueTime / oursTime : 0.0 }, { "added_ms", 1e3 * (oursTime - opaqueTime) },
      { "peak_rss_mb", ours->second.value("peak_rss_mb", 0.0) },
      { "peer_peak_rss_mb", opaque->second.value("peak_rss_mb", 0.0) } });
  }
  return lines;
}
}

void RegisterAirlight(std::map<std::string, Benchmark>& registry)
{
  Benchmark b;
  b.Description = "airlight pass (closed form) vs brute-force shader ray marching of the same integral and Plume's smoke volume";
  b.Jobs = Jobs;
  b.Run = RunJob;
  b.Report = Report;
  registry["airlight"] = b;
}
}
}
