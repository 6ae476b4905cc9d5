// `plume bench splat`: Gaussian splats of random points onto a grid, ours
// (vtkPlumeGaussianSplatter, CPU and GPU backends) against what a VTK user
// would do today: vtkGaussianSplatter for scalars (sequential, its fastest
// here) and vtkPointInterpolator + vtkGaussianKernel for vectors (threads).
// Every method computes the same quantity, the sum of normalised Gaussians
// sampled at the voxel centres, cut off at k·σ (k = 4): the peers are
// configured for it (scale factor, exponent, radius, unnormalised weights)
// and ours runs with IntegrateOverVoxel off. Each result's error is measured
// against vtkPlumeSplatReference (double precision, no cutoff) at a sample of
// voxels (near splat centres and random), relative to the largest reference
// value of the sample. Each job runs in its own process.
#include "plumeBenchmarks.h"

#include "vtkPlumeGaussianSplatter.h"
#include "vtkPlumeSplatReference.h"
#include "vtkPlumeVelocityGlyphMapper.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkGaussianKernel.h"
#include "vtkGaussianSplatter.h"
#include "vtkImageData.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkPointData.h"
#include "vtkPointInterpolator.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkActor.h"
#include "vtkSMPTools.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace plume
{
namespace bench
{
namespace
{
constexpr double K = 4.0;            // cutoff, in σ
constexpr double SigmaVoxels = 1.5;  // σ in voxels (the default cases)
constexpr int ErrorSamples = 3000;

struct Case
{
  int Points;
  int Grid;
  double Sigma; // in voxels
};

std::vector<Case> Cases(bool quick)
{
  if (quick)
  {
    return { { 1000, 32, SigmaVoxels } };
  }
  std::vector<Case> cases;
  for (int grid : { 64, 128, 256 })
  {
    for (int points : { 1000, 10000, 100000 })
    {
      cases.push_back({ points, grid, SigmaVoxels });
    }
  }
  // scaling with σ
  cases.push_back({ 10000, 64, 0.5 });
  cases.push_back({ 10000, 64, 4.0 });
  return cases;
}

// GPU hand-over to the glyph mapper: splat + first frame, with and without
std::vector<Case> HandOverCases(bool quick)
{
  if (quick)
  {
    return { { 1000, 32, SigmaVoxels } };
  }
  return { { 10000, 64, SigmaVoxels }, { 10000, 128, SigmaVoxels } };
}

std::string CaseId(const Case& c)
{
  std::ostringstream s;
  s << c.Points << ":" << c.Grid << ":" << c.Sigma;
  return s.str();
}

vtkSmartPointer<vtkPolyData> MakePoints(int n)
{
  vtkNew<vtkMinimalStandardRandomSequence> rng;
  rng->SetSeed(1234);
  auto next = [&](double a, double b) {
    rng->Next();
    return rng->GetRangeValue(a, b);
  };
  vtkNew<vtkPoints> pts;
  vtkNew<vtkFloatArray> v, s;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  s->SetName("s");
  for (int i = 0; i < n; ++i)
  {
    // one draw per statement: argument evaluation order is unspecified (gcc and clang differ)
    const double x = next(-0.9, 0.9);
    const double y = next(-0.9, 0.9);
    const double z = next(-0.9, 0.9);
    pts->InsertNextPoint(x, y, z);
    const double vx = next(-1, 1);
    const double vy = next(-1, 1);
    const double vz = next(-1, 1);
    v->InsertNextTuple3(vx, vy, vz);
    s->InsertNextValue(static_cast<float>(next(0.2, 2)));
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(pts);
  poly->GetPointData()->SetVectors(v);
  poly->GetPointData()->SetScalars(s);
  return poly;
}

// max |a - ref| / max |ref| and RMS / max |ref| over sampled voxels
std::pair<double, double> SampledError(vtkDataArray* values, const vtkPlumeSplatReference* reference,
  const std::vector<std::array<int, 3>>& voxels, int grid, int comps)
{
  double maxErr = 0, sum2 = 0, peak = 0;
  for (const auto& ijk : voxels)
  {
    double exact[3];
    reference->Evaluate(ijk[0], ijk[1], ijk[2], exact);
    const vtkIdType id = (vtkIdType(ijk[2]) * grid + ijk[1]) * grid + ijk[0];
    for (int c = 0; c < comps; ++c)
    {
      const double e = values->GetComponent(id, c) - exact[c];
      maxErr = std::max(maxErr, std::fabs(e));
      sum2 += e * e;
      peak = std::max(peak, std::fabs(exact[c]));
    }
  }
  const double rms = std::sqrt(sum2 / (double(voxels.size()) * comps));
  return { peak > 0 ? maxErr / peak : maxErr, peak > 0 ? rms / peak : rms };
}

// Hand-over job: a vector field splatted on the GPU in the render window,
// then drawn by the glyph mapper (every 8th node: the draw stays small, the
// measured difference is the hand-over). "on": the mapper binds the
// splatter's texture; "off": it converts and uploads the read-back array.
nlohmann::json RunHandOverJob(const Context& context, bool on, int npts, int grid, double sigmaVoxels)
{
  const int runs = context.Quick ? 2 : 7;
  auto points = MakePoints(npts);
  auto window = context.MakeWindow(512, 512);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render(); // the GL context exists before timing starts
  vtkNew<vtkPlumeGaussianSplatter> ours;
  ours->SetInputData(points);
  ours->SetDimensions(grid, grid, grid);
  ours->SetModelBounds(-1, 1, -1, 1, -1, 1);
  ours->SetRadius(sigmaVoxels * 2.0 / (grid - 1));
  ours->SetCutoffFactor(K);
  ours->SetBackend(vtkPlumeGaussianSplatter::BACKEND_GPU);
  ours->SetRenderWindow(window);
  ours->SetGPUHandOver(on);
  vtkNew<vtkPlumeVelocityGlyphMapper> mapper;
  mapper->SetInputConnection(ours->GetOutputPort());
  mapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
  mapper->SetLatticeStride(8);
  mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED); // as before auto was the default
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  renderer->ResetCamera(-1, 1, -1, 1, -1, 1);
  std::vector<double> total, frame;
  for (int r = 0; r <= runs; ++r)
  {
    ours->Modified(); // new data each time, as when a user edits the path
    const double t0 = Now();
    ours->Update();
    const double t1 = Now();
    window->Render();
    window->WaitForCompletion();
    const double t2 = Now();
    if (r > 0) // the first run builds the programs
    {
      total.push_back(t2 - t0);
      frame.push_back(t2 - t1);
    }
  }
  if (ours->GetLastBackend() != vtkPlumeGaussianSplatter::BACKEND_GPU ||
    (on ? mapper->GetHandOverCount() : mapper->GetUploadCount()) < runs)
  {
    throw std::runtime_error(on ? "the glyph mapper did not take the hand-over" : "the glyph mapper did not upload");
  }
  return { { "seconds", Median(total) }, { "frame_s", Median(frame) }, { "peak_rss_mb", PeakRSSMB() } };
}

nlohmann::json RunJob(const Context& context, const std::string& job)
{
  // job = kind:field:points:grid:sigma
  std::vector<std::string> parts;
  {
    std::istringstream in(job);
    std::string p;
    while (std::getline(in, p, ':'))
    {
      parts.push_back(p);
    }
  }
  const std::string kind = parts.at(0);
  if (kind == "handover")
  {
    return RunHandOverJob(context, parts.at(1) == "on", std::stoi(parts.at(2)), std::stoi(parts.at(3)),
      std::stod(parts.at(4)));
  }
  const bool vectors = parts.at(1) == "vector";
  const int npts = std::stoi(parts.at(2));
  const int grid = std::stoi(parts.at(3));
  const double h = 2.0 / (grid - 1);
  const double sigma = std::stod(parts.at(4)) * h;
  const double norm = 1.0 / (std::pow(2 * 3.14159265358979323846, 1.5) * sigma * sigma * sigma);
  const int runs = context.Quick ? 2 : (npts * double(grid) * grid * grid > 1e10 ? 3 : 5);

  auto points = MakePoints(npts);
  vtkSmartPointer<vtkRenderWindow> window;
  std::function<vtkDataArray*()> run;

  vtkNew<vtkPlumeGaussianSplatter> ours;
  ours->SetInputData(points);
  ours->SetDimensions(grid, grid, grid);
  ours->SetModelBounds(-1, 1, -1, 1, -1, 1);
  ours->SetRadius(sigma);
  ours->SetCutoffFactor(K);
  ours->SetIntegrateOverVoxel(false);
  ours->SetMode(vectors ? vtkPlumeGaussianSplatter::VECTOR_SUM : vtkPlumeGaussianSplatter::SCALAR_SUM);
  ours->SetBackend(vtkPlumeGaussianSplatter::BACKEND_CPU);

  vtkNew<vtkGaussianSplatter> splatter;
  vtkNew<vtkPointInterpolator> interpolator;
  vtkNew<vtkImageData> lattice;
  vtkSmartPointer<vtkPolyData> scaled;

  if (kind == "cpu" || kind == "gpu")
  {
    if (kind == "gpu")
    {
      window = context.MakeWindow(8, 8);
      window->Render(); // the GL context exists before timing starts
      ours->SetRenderWindow(window);
      ours->SetBackend(vtkPlumeGaussianSplatter::BACKEND_GPU);
    }
    run = [&]() -> vtkDataArray* {
      ours->Modified();
      ours->Update();
      return ours->GetOutput()->GetPointData()->GetArray(0);
    };
  }
  else if (kind == "gsplat")
  {
    vtkSMPTools::SetBackend("Sequential"); // its fastest here (TOOLCHAIN.md)
    splatter->SetInputData(points);
    splatter->SetSampleDimensions(grid, grid, grid);
    splatter->SetModelBounds(-1, 1, -1, 1, -1, 1);
    splatter->SetRadius(K * sigma / 2.0); // a fraction of the longest side (2)
    splatter->SetExponentFactor(-0.5 * K * K);
    splatter->SetScaleFactor(norm);
    splatter->ScalarWarpingOn();
    splatter->NormalWarpingOff();
    splatter->CappingOff();
    splatter->SetAccumulationModeToSum();
    splatter->SetNullValue(0);
    run = [&]() -> vtkDataArray* {
      splatter->Modified();
      splatter->Update();
      return splatter->GetOutput()->GetPointData()->GetScalars();
    };
  }
  else // interp
  {
    // unnormalised Gaussian weights exp(-(Sharpness·r/Radius)²) = exp(-r²/2σ²) with
    // Radius = kσ, Sharpness = k/√2; the normalisation goes into the input (not timed)
    scaled = vtkSmartPointer<vtkPolyData>::New();
    scaled->DeepCopy(points);
    vtkDataArray* v = scaled->GetPointData()->GetVectors();
    for (vtkIdType i = 0; i < v->GetNumberOfValues(); ++i)
    {
      v->SetComponent(i / 3, i % 3, v->GetComponent(i / 3, i % 3) * norm);
    }
    vtkDataArray* s = scaled->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
    {
      s->SetComponent(i, 0, s->GetComponent(i, 0) * norm);
    }
    if (vectors)
    {
      scaled->GetPointData()->SetActiveScalars(nullptr);
      scaled->GetPointData()->RemoveArray("s");
    }
    else
    {
      scaled->GetPointData()->RemoveArray("v");
    }
    lattice->SetDimensions(grid, grid, grid);
    lattice->SetOrigin(-1, -1, -1);
    lattice->SetSpacing(h, h, h);
    vtkNew<vtkGaussianKernel> kernel;
    kernel->SetKernelFootprintToRadius();
    kernel->SetRadius(K * sigma);
    kernel->SetSharpness(K / std::sqrt(2.0));
    kernel->NormalizeWeightsOff();
    interpolator->SetInputData(lattice);
    interpolator->SetSourceData(scaled);
    interpolator->SetKernel(kernel);
    interpolator->SetNullPointsStrategyToNullValue();
    interpolator->SetNullValue(0);
    interpolator->PassPointArraysOff();
    run = [&]() -> vtkDataArray* {
      interpolator->Modified();
      interpolator->Update();
      return interpolator->GetOutput()->GetPointData()->GetArray(vectors ? "v" : "s");
    };
  }

  run(); // warm-up (first GL program build, page faults)
  std::vector<double> times;
  vtkDataArray* values = nullptr;
  for (int r = 0; r < runs; ++r)
  {
    const double t0 = Now();
    values = run();
    times.push_back(Now() - t0);
  }
  nlohmann::json result = { { "seconds", Median(times) }, { "peak_rss_mb", PeakRSSMB() } };
  if (!values)
  {
    throw std::runtime_error("no output array");
  }
  // the reference, at sampled voxels: those nearest to some splat centres, and random ones
  vtkSmartPointer<vtkDataArray> measured = values; // kept alive across the re-run below
  ours->SetBackend(vtkPlumeGaussianSplatter::BACKEND_CPU);
  ours->SetRenderWindow(nullptr);
  ours->Update();
  vtkNew<vtkPlumeSplatReference> reference;
  reference->Configure(ours);
  std::vector<std::array<int, 3>> voxels;
  vtkNew<vtkMinimalStandardRandomSequence> rng;
  rng->SetSeed(99);
  for (int i = 0; i < ErrorSamples; ++i)
  {
    std::array<int, 3> ijk;
    if (i % 2 == 0)
    {
      double p[3];
      points->GetPoint((vtkIdType(i) * 7919) % npts, p);
      for (int a = 0; a < 3; ++a)
      {
        ijk[a] = std::min(grid - 1, std::max(0, int(std::lround((p[a] + 1) / h))));
      }
    }
    else
    {
      for (int a = 0; a < 3; ++a)
      {
        rng->Next();
        ijk[a] = std::min(grid - 1, int(rng->GetValue() * grid));
      }
    }
    voxels.push_back(ijk);
  }
  // flat fields: the parent parses the job's last JSON object
  const auto error = SampledError(measured, reference, voxels, grid, vectors ? 3 : 1);
  result["error_max"] = error.first;
  result["error_rms"] = error.second;
  if (kind == "cpu" || kind == "gpu")
  {
    result["splats"] = ours->GetSplatCount();
  }
  return result;
}

std::vector<nlohmann::json> Report(const std::map<std::string, nlohmann::json>& results, bool quick)
{
  std::vector<nlohmann::json> lines;
  for (const Case& c : Cases(quick))
  {
    const std::string id = CaseId(c);
    for (const std::string field : { "scalar", "vector" })
    {
      const std::string peerKind = field == "scalar" ? "gsplat" : "interp";
      const auto peer = results.find(peerKind + ":" + field + ":" + id);
      if (peer == results.end())
      {
        continue;
      }
      for (const std::string backend : { "cpu", "gpu" })
      {
        const auto ours = results.find(backend + ":" + field + ":" + id);
        if (ours == results.end())
        {
          continue;
        }
        const double o = ours->second["seconds"].get<double>();
        const double p = peer->second["seconds"].get<double>();
        std::ostringstream name;
        name << field << "s, " << c.Points << " points -> " << c.Grid << "^3, sigma " << c.Sigma << " voxel, "
             << backend;
        lines.push_back({ { "bench", "splat" }, { "case", name.str() }, { "ours_s", o },
          { "peer", field == "scalar" ? "vtkGaussianSplatter (sequential)" : "vtkPointInterpolator+vtkGaussianKernel" },
          { "peer_s", p }, { "ratio", p / o }, { "error", ours->second["error_max"] },
          { "error_rms", ours->second["error_rms"] }, { "peer_error", peer->second["error_max"] },
          { "peer_error_rms", peer->second["error_rms"] }, { "peak_rss_mb", ours->second["peak_rss_mb"] },
          { "peer_peak_rss_mb", peer->second["peak_rss_mb"] } });
      }
    }
  }
  for (const Case& c : HandOverCases(quick))
  {
    const auto on = results.find("handover:on:" + CaseId(c));
    const auto off = results.find("handover:off:" + CaseId(c));
    if (on == results.end() || off == results.end())
    {
      continue;
    }
    std::ostringstream name;
    name << "vectors, " << c.Points << " points -> " << c.Grid << "^3 on the GPU, then a glyph frame: texture handed over";
    const double o = on->second["seconds"].get<double>();
    const double p = off->second["seconds"].get<double>();
    lines.push_back({ { "bench", "splat" }, { "case", name.str() }, { "ours_s", o },
      { "peer", "same with read-back array uploaded by the glyph mapper" }, { "peer_s", p }, { "ratio", p / o },
      { "frame_s", on->second["frame_s"] }, { "peer_frame_s", off->second["frame_s"] },
      { "saving_s", p - o }, { "peak_rss_mb", on->second["peak_rss_mb"] },
      { "peer_peak_rss_mb", off->second["peak_rss_mb"] } });
  }
  return lines;
}
}

void RegisterSplat(std::map<std::string, Benchmark>& registry)
{
  Benchmark b;
  b.Description = "Gaussian splatting of random points (scalars, vectors) onto 64^3/128^3/256^3, CPU and GPU, vs "
                  "vtkGaussianSplatter and vtkPointInterpolator+vtkGaussianKernel, errors vs the exact reference";
  b.Jobs = [](bool quick) {
    std::vector<std::string> jobs;
    for (const Case& c : Cases(quick))
    {
      for (const char* field : { "scalar", "vector" })
      {
        const std::string peer = std::string(field) == "scalar" ? "gsplat" : "interp";
        for (const std::string& kind : { std::string("cpu"), std::string("gpu"), peer })
        {
          jobs.push_back(kind + ":" + field + ":" + CaseId(c));
        }
      }
    }
    for (const Case& c : HandOverCases(quick))
    {
      jobs.push_back("handover:on:" + CaseId(c));
      jobs.push_back("handover:off:" + CaseId(c));
    }
    return jobs;
  };
  b.Run = RunJob;
  b.Report = Report;
  registry["splat"] = b;
}

}
}
