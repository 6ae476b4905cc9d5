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
#include "plumeBenchmarks.h"
#include "plumeTestSupport.h"

#include "vtkPlumeAirlightPass.h"
#include "vtkPlumeAirlightReference.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkFramebufferPass.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkPixelBufferObject.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>

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
  const int frames = context.Quick ? 3 : 7;
  auto window = context.MakeWindow(size, size);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.15, 0.3);
  window->AddRenderer(renderer);
  BuildScene(renderer);
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
  if (job != "opaque")
  {
    SetMedium(pass, job == "grey");
  }
  if (job.rfind("march:", 0) == 0)
  {
    pass->SetMarchSteps(std::stoi(job.substr(6)));
  }
  if (job.rfind("shadow_march:", 0) == 0)
  {
    pass->SetMarchSteps(std::stoi(job.substr(13)));
  }
  if (job.rfind("down:", 0) == 0)
  {
    // "down:D" or "down:D:TOL": a low-resolution airlight, upsampled with tolerance TOL.
    pass->SetDownsampling(std::stoi(job.substr(5)));
    const size_t colon = job.find(':', 5);
    if (colon != std::string::npos)
    {
      pass->SetUpsamplingTolerance(std::stod(job.substr(colon + 1)));
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
  std::vector<double> times;
  vtkLight* spot = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(1));
  for (int f = 0; f < frames + 2; ++f)
  {
    renderer->GetActiveCamera()->Azimuth(f % 2 ? 0.5 : -0.5); // a real re-render
    if (job == "shadow_rebake")
    {
      spot->SetPosition(2.5, 3.5, f % 2 ? -1.5 : -1.500001); // a changed light: its map is rebuilt
    }
    const double t0 = Now();
    window->Render();
    window->WaitForCompletion();
    if (f >= 2)
    {
      times.push_back(Now() - t0);
    }
  }
  nlohmann::json result = { { "frame_s", Median(times) }, { "peak_rss_mb", PeakRSSMB() },
    { "shadowed_lights", pass->GetNumberOfShadowedLights() }, { "bakes", pass->GetNumberOfShadowMapBakes() },
    { "light_groups", pass->GetNumberOfLightGroups() } };
  if (job == "opaque" || job == "shadow_rebake" || job == "floor" || job == "copy")
  {
    return result;
  }

  // Error against the reference on a lattice of pixels (every `stride`-th;
  // shadowed: a quarter as many pixels, the reference's exact shadow rays are slow).
  const int stride = (context.Quick ? 4 : 16) * (shadowed ? 2 : 1);
  const test::FloatImage plain = RenderFloat(window, renderer, nullptr);
  const test::FloatImage image = RenderFloat(window, renderer, pass);
  vtkNew<vtkPlumeAirlightReference> reference;
  reference->SetScattering(pass->GetScattering());
  reference->SetAbsorption(pass->GetAbsorption());
  reference->SetIntensityScale(pass->GetIntensityScale());
  if (shadowed)
  {
    reference->SetOccluders(renderer); // exact ray-cast shadows
  }
  reference->SetLights(renderer);
  std::vector<float> surface(plain.RGBA), expected, airlight;
  for (float& v : surface)
  {
    v = std::min(std::max(v, 0.0f), 1.0f);
  }
  reference->ComputeImage(
    renderer, size, size, surface.data(), plain.Depth.data(), expected, stride, &airlight);
  double lo = HUGE_VAL, hi = -HUGE_VAL, sum = 0, worst = 0;
  size_t count = 0;
  for (size_t p = 0; p < expected.size() / 4; ++p)
  {
    if (std::isnan(expected[4 * p]))
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      lo = std::min(lo, double(airlight[4 * p + c]));
      hi = std::max(hi, double(airlight[4 * p + c]));
      const double d = std::fabs(double(image.RGBA[4 * p + c]) - expected[4 * p + c]);
      sum += d * d;
      worst = std::max(worst, d);
      ++count;
    }
  }
  const double range = hi > lo ? hi - lo : 1.0;
  result["error"] = std::sqrt(sum / std::max<size_t>(count, 1)) / range;
  result["error_max"] = worst / range;
  result["error_pixels"] = count / 3;
  return result;
}

std::vector<std::string> Jobs(bool quick)
{
  const std::string half = quick ? "@64" : "@256";
  std::vector<std::string> jobs = { "opaque", "ours", "grey", "shadow", "shadow_rebake", "opaque" + half,
    "ours" + half, "floor", "copy", "down:2", "down:4", "down:2:0.25", "down:4:0.25", "down:2:1", "down:4:1",
    "lights:7", "lights:8", "lights:9", "lights:16", "lights:17" };
  for (int n : MarchSteps(quick))
  {
    jobs.push_back("march:" + std::to_string(n));
  }
  for (int n : ShadowMarchSteps(quick))
  {
    jobs.push_back("shadow_march:" + std::to_string(n));
  }
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
  // The low-resolution airlight (Downsampling D) against the full resolution,
  // and the floor of any full-screen pass on this renderer.
  for (const std::string d : { "2", "4", "2:0.25", "4:0.25", "2:1", "4:1" })
  {
    const auto down = results.find("down:" + d);
    if (down == results.end())
    {
      continue;
    }
    const double downTime = down->second.value("frame_s", 0.0);
    nlohmann::json line = { { "bench", "airlight" },
      { "case", size + " point+spot, airlight at 1/" + d.substr(0, 1) + " resolution, upsampled, tolerance " +
          (d.size() > 1 ? d.substr(2) : std::string("0.05")) },
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
  b.Description = "airlight pass (closed form) vs brute-force shader ray marching of the same integral";
  b.Jobs = Jobs;
  b.Run = RunJob;
  b.Report = Report;
  registry["airlight"] = b;
}
}
}
