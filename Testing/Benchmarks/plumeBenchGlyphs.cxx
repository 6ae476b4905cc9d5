// `plume bench glyphs`: velocity glyph lines on an analytic vortex, one glyph
// per grid node, against what a VTK user would do today (vtkHedgeHog +
// vtkPolyDataMapper, vtkGlyph3DMapper with a line source): first frame,
// re-render and peak memory, each renderer in its own process.
#include "plumeBenchmarks.h"

#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkPlumeVortexSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkGlyph3DMapper.h"
#include "vtkHedgeHog.h"
#include "vtkImageData.h"
#include "vtkLineSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

namespace plume
{
namespace bench
{
namespace
{
constexpr int Size = 512;
constexpr double GlyphScale = 0.15; // world units per unit speed: glyphs ≈ one node spacing long at 64³

std::vector<int> Grids(bool quick)
{
  return quick ? std::vector<int>{ 32 } : std::vector<int>{ 64, 128 };
}

const char* PeerName(const std::string& kind)
{
  return kind == "hedgehog" ? "vtkHedgeHog+vtkPolyDataMapper" : "vtkGlyph3DMapper(vtkLineSource)";
}

vtkSmartPointer<vtkColorTransferFunction> Table(double max)
{
  auto ctf = vtkSmartPointer<vtkColorTransferFunction>::New();
  ctf->AddRGBPoint(0, 0.2, 0.3, 0.9);
  ctf->AddRGBPoint(max, 1.0, 0.9, 0.2);
  return ctf;
}

nlohmann::json RunJob(const Context& context, const std::string& job)
{
  const auto colon = job.find(':');
  const std::string kind = job.substr(0, colon);
  const int n = std::stoi(job.substr(colon + 1));
  const int frames = context.Quick ? 3 : 10;

  vtkNew<vtkPlumeVortexSource> source;
  source->SetDimensions(n, n, n);
  source->Update();
  vtkImageData* image = source->GetOutput();
  double speedRange[2];
  image->GetPointData()->GetScalars()->GetRange(speedRange);

  auto window = context.MakeWindow(Size, Size);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.12);
  window->AddRenderer(renderer);
  window->Render(); // the GL context exists before timing starts
  window->WaitForCompletion();

  vtkNew<vtkActor> actor;
  renderer->AddActor(actor);
  vtkSmartPointer<vtkPlumeVelocityGlyphMapper> ours;
  vtkNew<vtkHedgeHog> hedgehog;

  const double start = Now();
  if (kind == "ours" || kind == "adaptive" || kind == "small")
  {
    ours = vtkSmartPointer<vtkPlumeVelocityGlyphMapper>::New();
    ours->SetInputData(image);
    ours->SetRootMode(kind == "adaptive" ? vtkPlumeVelocityGlyphMapper::ROOTS_SCREEN_ADAPTIVE
                                         : vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
    ours->SetLatticeStride(1);
    if (kind == "small")
    {
      ours->SetMaximumGlyphsPerDraw(16384); // least driver memory, at some time
    }
    ours->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
    ours->SetScale(GlyphScale);
    ours->SetRootAlpha(1.0); // opaque lines, as the peers draw them
    ours->SetLookupTable(Table(speedRange[1]));
    ours->SetUseDataRange(false);
    ours->SetScalarRange(speedRange);
    actor->SetMapper(ours);
  }
  else if (kind == "hedgehog")
  {
    hedgehog->SetInputData(image);
    hedgehog->SetScaleFactor(GlyphScale);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(hedgehog->GetOutputPort());
    mapper->SetLookupTable(Table(speedRange[1]));
    mapper->SetScalarRange(speedRange);
    mapper->SetScalarModeToUsePointData();
    actor->SetMapper(mapper);
  }
  else
  {
    vtkNew<vtkLineSource> line;
    line->SetPoint1(0, 0, 0);
    line->SetPoint2(1, 0, 0);
    vtkNew<vtkGlyph3DMapper> mapper;
    mapper->SetInputData(image);
    mapper->SetSourceConnection(line->GetOutputPort());
    mapper->SetOrientationArray("velocity");
    mapper->SetScaleArray("velocity");
    mapper->SetScaleModeToScaleByMagnitude();
    mapper->SetScaleFactor(GlyphScale);
    mapper->SetLookupTable(Table(speedRange[1]));
    mapper->SetScalarRange(speedRange);
    actor->SetMapper(mapper);
  }
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30);
  renderer->GetActiveCamera()->Elevation(20);
  renderer->ResetCameraClippingRange();
  window->Render();
  window->WaitForCompletion();
  const double firstFrame = Now() - start;

  std::vector<double> times;
  for (int f = 0; f < frames + 2; ++f)
  {
    renderer->GetActiveCamera()->Azimuth(1.0); // a real re-render, as when a user rotates
    const double t0 = Now();
    window->Render();
    window->WaitForCompletion();
    if (f >= 2) // warm-up frames
    {
      times.push_back(Now() - t0);
    }
  }
  nlohmann::json result = { { "first_s", firstFrame }, { "rerender_s", Median(times) },
    { "peak_rss_mb", PeakRSSMB() } };
  if (ours)
  {
    result["glyphs"] = ours->GetLastRootCount();
    result["stride"] = ours->GetEffectiveStride();
  }
  else
  {
    result["glyphs"] = static_cast<long long>(n) * n * n;
  }
  return result;
}

std::vector<nlohmann::json> Report(const std::map<std::string, nlohmann::json>& results, bool quick)
{
  std::vector<nlohmann::json> lines;
  for (int n : Grids(quick))
  {
    const std::string grid = std::to_string(n);
    // one line per metric: our job `kind` against `peer`, `label` naming the configuration
    auto compare = [&](const std::string& kind, const std::string& peer, const std::string& label) {
      const auto ours = results.find(kind + ":" + grid);
      const auto other = results.find(peer + ":" + grid);
      if (ours == results.end() || other == results.end())
      {
        return;
      }
      for (const std::string metric : { "first", "rerender" })
      {
        const double o = ours->second[metric + "_s"].get<double>();
        const double p = other->second[metric + "_s"].get<double>();
        lines.push_back({ { "bench", "glyphs" },
          { "case", "vortex " + grid + "^3 one glyph per node, " + label +
              (metric == "first" ? "first frame" : "re-render") },
          { "ours_s", o }, { "peer", PeerName(peer) }, { "peer_s", p }, { "ratio", p / o },
          { "glyphs", ours->second["glyphs"] }, { "peak_rss_mb", ours->second["peak_rss_mb"] },
          { "peer_peak_rss_mb", other->second["peak_rss_mb"] },
          { "memory_ratio",
            other->second["peak_rss_mb"].get<double>() / ours->second["peak_rss_mb"].get<double>() } });
      }
    };
    compare("ours", "hedgehog", "");
    compare("ours", "glyph3d", "");
    // the same glyphs in 16k draws: the driver's memory bounded tighter
    compare("small", "hedgehog", "16k glyphs per draw, ");
    const auto adaptive = results.find("adaptive:" + grid);
    const auto hedgehog = results.find("hedgehog:" + grid);
    if (adaptive != results.end() && hedgehog != results.end())
    {
      const double o = adaptive->second["rerender_s"].get<double>();
      const double p = hedgehog->second["rerender_s"].get<double>();
      lines.push_back({ { "bench", "glyphs" },
        { "case", "vortex " + grid + "^3 screen-adaptive default (peer draws every node), re-render" },
        { "ours_s", o }, { "peer", PeerName("hedgehog") }, { "peer_s", p }, { "ratio", p / o },
        { "glyphs", adaptive->second["glyphs"] }, { "stride", adaptive->second["stride"] },
        { "peak_rss_mb", adaptive->second["peak_rss_mb"] },
        { "peer_peak_rss_mb", hedgehog->second["peak_rss_mb"] } });
    }
  }
  return lines;
}
}

void RegisterGlyphs(std::map<std::string, Benchmark>& registry)
{
  Benchmark b;
  b.Description = "velocity glyph lines, analytic vortex, one glyph per node, vs vtkHedgeHog and vtkGlyph3DMapper";
  b.Jobs = [](bool quick) {
    std::vector<std::string> jobs;
    for (int n : Grids(quick))
    {
      for (const char* kind : { "ours", "hedgehog", "glyph3d", "adaptive", "small" })
      {
        jobs.push_back(std::string(kind) + ":" + std::to_string(n));
      }
    }
    return jobs;
  };
  b.Run = RunJob;
  b.Report = Report;
  registry["glyphs"] = b;
}

}
}
