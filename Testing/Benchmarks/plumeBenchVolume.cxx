// `plume bench volume`: raycasting a 128³ scalar volume into 512x512 with
// vtkPlumeVolumeMapper against VTK's own vtkGPUVolumeRayCastMapper and
// vtkFixedPointVolumeRayCastMapper (the faster one on software GL): same
// volume, transfer functions and camera, several sample distances each, and
// every image's error against vtkPlumeVolumeReference (computed once per
// field in its own job and passed to the render jobs through a temporary file).
// Two fields: "smoke" (three Gaussian puffs, mostly empty space) and "dense"
// (a low-opacity field that fills the box), each unshaded and shaded (the
// property's Shade on, headlight; note the peers' shading models differ from
// ours in detail, so part of their shaded error is model, not sampling).
#include "plumeBenchmarks.h"

#include "vtkPlumeVolumeMapper.h"
#include "vtkPlumeVolumeReference.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFixedPointVolumeRayCastMapper.h"
#include "vtkFloatArray.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

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
int Size(bool quick)
{
  return quick ? 128 : 512;
}

int Grid(bool quick)
{
  return quick ? 32 : 128;
}

std::vector<double> Steps(bool quick)
{
  return quick ? std::vector<double>{ 1.0 } : std::vector<double>{ 0.5, 1.0, 2.0, 4.0 };
}

// a variant is a field, optionally shaded (property Shade on, same lighting for all)
const char* Fields[] = { "smoke", "dense", "smoke+shaded", "dense+shaded" };

std::string FieldOf(const std::string& variant)
{
  return variant.substr(0, variant.find('+'));
}

bool Shaded(const std::string& variant)
{
  return variant.find("+shaded") != std::string::npos;
}

std::string Describe(const std::string& variant)
{
  return FieldOf(variant) + (Shaded(variant) ? ", shaded" : ", unshaded");
}

const char* PeerName(const std::string& kind)
{
  return kind == "gpu" ? "vtkGPUVolumeRayCastMapper" : "vtkFixedPointVolumeRayCastMapper";
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
  opacity->AddPoint(1.0, field == "smoke" ? 0.8 : 0.15);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(field == "smoke" ? 0.05 : 0.2);
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

// `run` is the pid of the `plume bench` process: getppid() in a job, getpid() in Report
std::string ReferencePath(const std::string& field, int n, bool quick, long run)
{
  return "/tmp/plume-bench-volume-" + std::to_string(run) + "-" + field + "-" + std::to_string(n) +
    (quick ? "-quick" : "") + ".f32";
}

nlohmann::json RunJob(const Context& context, const std::string& job)
{
  // job = kind:field:step   (kind: reference, ours, gpu, fixed)
  const size_t a = job.find(':'), b = job.find(':', a + 1);
  const std::string kind = job.substr(0, a);
  const std::string variant = job.substr(a + 1, b - a - 1);
  const std::string field = FieldOf(variant);
  const double step = b == std::string::npos ? 0.0 : std::stod(job.substr(b + 1));
  const bool quick = context.Quick;
  const int n = Grid(quick), size = Size(quick);
  const int frames = quick ? 2 : 5;
  auto image = Field(field, n);

  vtkNew<vtkVolume> volume;
  Configure(volume->GetProperty(), variant);
  if (kind == "reference")
  {
    // a window-less renderer: the camera, and the headlight VTK would create
    vtkNew<vtkRenderer> renderer;
    SetCamera(renderer);
    renderer->CreateLight();
    renderer->UpdateLightsGeometryToFollowCamera();
    vtkNew<vtkPlumeVolumeReference> reference;
    reference->SetInputData(image);
    reference->SetVolume(volume);
    reference->SetRenderer(renderer);
    reference->SetStep(0.125);
    const double t0 = Now();
    reference->Compute(size, size);
    const double seconds = Now() - t0;
    std::ofstream out(ReferencePath(variant, n, quick, getppid()), std::ios::binary);
    out.write(reinterpret_cast<const char*>(reference->GetImage().data()),
      reference->GetImage().size() * sizeof(float));
    return { { "reference_s", seconds }, { "peak_rss_mb", PeakRSSMB() } };
  }

  auto window = context.MakeWindow(size, size);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  window->AddRenderer(renderer);
  window->Render();
  window->WaitForCompletion();
  SetCamera(renderer);

  const double spacing = 1.0 / (n - 1);
  vtkNew<vtkPlumeVolumeMapper> ours;
  if (kind == "ours")
  {
    ours->SetInputData(image);
    ours->SetSampleDistance(step);
    volume->SetMapper(ours);
  }
  else if (kind == "gpu")
  {
    vtkNew<vtkOpenGLGPUVolumeRayCastMapper> mapper; // what vtkGPUVolumeRayCastMapper::New() gives
    mapper->SetInputData(image);
    mapper->AutoAdjustSampleDistancesOff();
    mapper->LockSampleDistanceToInputSpacingOff();
    mapper->SetSampleDistance(step * spacing);
    volume->SetMapper(mapper);
  }
  else
  {
    vtkNew<vtkFixedPointVolumeRayCastMapper> mapper;
    mapper->SetInputData(image);
    mapper->AutoAdjustSampleDistancesOff();
    mapper->LockSampleDistanceToInputSpacingOff();
    mapper->SetSampleDistance(step * spacing);
    mapper->SetImageSampleDistance(1.0);
    volume->SetMapper(mapper);
  }
  renderer->AddVolume(volume);

  std::vector<double> times;
  for (int f = 0; f < frames + 2; ++f)
  {
    const double t0 = Now();
    window->Render();
    window->WaitForCompletion();
    if (f >= 2) // warm-up frames (texture upload, shader compilation)
    {
      times.push_back(Now() - t0);
    }
  }
  // error of the last frame against the reference (background black: the image is the volume)
  vtkNew<vtkFloatArray> rgba;
  window->GetRGBAPixelData(0, 0, size - 1, size - 1, 0, rgba, 0);
  std::vector<float> expected(4 * static_cast<size_t>(size) * size);
  std::ifstream in(ReferencePath(variant, n, quick, getppid()), std::ios::binary);
  in.read(reinterpret_cast<char*>(expected.data()), expected.size() * sizeof(float));
  double sum = 0, worst = 0;
  const bool haveReference = static_cast<bool>(in);
  for (size_t p = 0; p < expected.size(); p += 4)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double d = std::fabs(double(rgba->GetValue(p + c)) - expected[p + c]);
      sum += d * d;
      worst = std::max(worst, d);
    }
  }
  nlohmann::json result = { { "render_s", Median(times) }, { "peak_rss_mb", PeakRSSMB() },
    { "empty_block_fraction", kind == "ours" ? ours->GetEmptyBlockFraction() : 0.0 } };
  if (haveReference)
  {
    result["rms_error"] = std::sqrt(sum / (3.0 * size * size));
    result["max_error"] = worst;
  }
  return result;
}

std::vector<std::string> Jobs(bool quick)
{
  std::vector<std::string> jobs;
  for (const char* field : Fields)
  {
    jobs.push_back(std::string("reference:") + field);
    for (double step : Steps(quick))
    {
      char s[32];
      std::snprintf(s, sizeof(s), "%g", step);
      for (const char* kind : { "ours", "gpu", "fixed" })
      {
        jobs.push_back(std::string(kind) + ":" + field + ":" + s);
      }
    }
  }
  return jobs;
}

std::vector<nlohmann::json> Report(const std::map<std::string, nlohmann::json>& results, bool quick)
{
  std::vector<nlohmann::json> lines;
  const int n = Grid(quick), size = Size(quick);
  for (const char* field : Fields)
  {
    std::remove(ReferencePath(field, n, quick, getpid()).c_str()); // (same parent: this process)
    for (double ourStep : Steps(quick))
    {
      char s[32];
      std::snprintf(s, sizeof(s), "%g", ourStep);
      const auto ours = results.find(std::string("ours:") + field + ":" + s);
      if (ours == results.end())
      {
        continue;
      }
      for (const std::string peer : { "gpu", "fixed" })
      {
        for (double peerStep : Steps(quick))
        {
          char ps[32];
          std::snprintf(ps, sizeof(ps), "%g", peerStep);
          const auto other = results.find(peer + ":" + field + ":" + ps);
          if (other == results.end())
          {
            continue;
          }
          const double o = ours->second["render_s"].get<double>();
          const double p = other->second["render_s"].get<double>();
          nlohmann::json line = { { "bench", "volume" },
            { "case", Describe(field) + " " + std::to_string(n) + "^3 -> " + std::to_string(size) + "^2, ours step " +
                s + " voxel, peer step " + ps + " voxel" },
            { "ours_s", o }, { "peer", PeerName(peer) }, { "peer_s", p }, { "ratio", p / o },
            { "ours_step", ourStep }, { "peer_step", peerStep },
            { "peak_rss_mb", ours->second["peak_rss_mb"] }, { "peer_peak_rss_mb", other->second["peak_rss_mb"] },
            { "empty_block_fraction", ours->second["empty_block_fraction"] } };
          if (ours->second.contains("rms_error") && other->second.contains("rms_error"))
          {
            line["error"] = ours->second["rms_error"];
            line["peer_error"] = other->second["rms_error"];
            line["max_error"] = ours->second["max_error"];
            line["peer_max_error"] = other->second["max_error"];
          }
          lines.push_back(line);
        }
      }
    }
  }
  // headline per field and peer: every peer configuration against our fastest
  // configuration whose error is not larger than that peer configuration's
  for (const char* field : Fields)
  {
    for (const std::string peer : { "gpu", "fixed" })
    {
      for (double peerStep : Steps(quick))
      {
        char ps[32];
        std::snprintf(ps, sizeof(ps), "%g", peerStep);
        const auto other = results.find(peer + ":" + field + ":" + ps);
        if (other == results.end() || !other->second.contains("rms_error"))
        {
          continue;
        }
        const double peerError = other->second["rms_error"].get<double>();
        const nlohmann::json* best = nullptr;
        double bestStep = 0;
        for (double ourStep : Steps(quick))
        {
          char s[32];
          std::snprintf(s, sizeof(s), "%g", ourStep);
          const auto ours = results.find(std::string("ours:") + field + ":" + s);
          if (ours == results.end() || !ours->second.contains("rms_error") ||
            ours->second["rms_error"].get<double>() > peerError)
          {
            continue;
          }
          if (!best || ours->second["render_s"].get<double>() < (*best)["render_s"].get<double>())
          {
            best = &ours->second;
            bestStep = ourStep;
          }
        }
        if (!best)
        {
          continue;
        }
        const double o = (*best)["render_s"].get<double>();
        const double p = other->second["render_s"].get<double>();
        lines.push_back({ { "bench", "volume" },
          { "case", Describe(field) + " " + std::to_string(n) + "^3 -> " + std::to_string(size) +
              "^2, equal or lower error: our fastest vs peer step " + ps + " voxel" },
          { "ours_s", o }, { "peer", PeerName(peer) }, { "peer_s", p }, { "ratio", p / o },
          { "ours_step", bestStep }, { "peer_step", peerStep }, { "error", (*best)["rms_error"] },
          { "peer_error", peerError }, { "peak_rss_mb", (*best)["peak_rss_mb"] },
          { "empty_block_fraction", (*best)["empty_block_fraction"] } });
      }
    }
  }
  return lines;
}
}

void RegisterVolume(std::map<std::string, Benchmark>& registry)
{
  Benchmark b;
  b.Description = "raycast 128^3 volumes into 512x512 (smoke and dense fields, several steps) vs "
                  "vtkGPUVolumeRayCastMapper and vtkFixedPointVolumeRayCastMapper, errors vs the CPU reference";
  b.Jobs = Jobs;
  b.Run = RunJob;
  b.Report = Report;
  registry["volume"] = b;
}

}
}
