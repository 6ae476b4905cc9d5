// `plume bench sheets`: smoke sheets on a real mesh (office_stream_sheet.vtp,
// 24,000 triangles) at 512x512 and 1024x1024: time against error for the
// sample settings (the grid mode with 0.5..3 nodes per sigma; the exact mode:
// Gauss-Legendre along the footprint with 2..8 nodes, the
// default; and the paper's regular grid 2x1..16x10), and what a VTK user
// would do today: splat the sheet into a density grid (64^3..256^3), blur it
// and raycast it with vtkGPUVolumeRayCastMapper /
// vtkFixedPointVolumeRayCastMapper. Every error is measured against
// vtkPlumeSheetReference on a sparse 32x32 pixel lattice (the reference is
// slow; offset so its pixels fall between the rays of any ray lattice): RMS
// and max transmittance error as a fraction of the reference's dynamic range
// there. Cheap interactive settings of ours and the peers' interactive
// settings (ImageSampleDistance 2/4, AutoAdjustSampleDistances) give the
// "comparison:" lines: per peer setting, our fastest at equal or lower error. Scaling (256x256, default settings, against splat +
// vtkFixedPointVolumeRayCastMapper 64^3): time against triangle count (the
// fire_ug.vtu mfrac isosurface, 1,278 triangles, split 1->4 up to 5 times:
// the same surface and smoke, up to 1.3 million triangles) and against screen
// coverage (the office sheet zoomed). The grid mode's interactive frames
// (window DesiredUpdateRate 15, as while the user drags the camera) and still
// frames (the default 0.0001, as when the user lets go) are timed apart. The
// 1.3 M-triangle fire runs every mode and the peers with errors against the
// reference of the unsplit surface (splitting a flat triangle at its edge
// midpoints leaves the smoke unchanged: same density, same sigmas).
// The grid mode's build is its own case (`grid build` lines: seconds and
// parts, merged per cell against every quadrature point splatted), and the
// floors of a grid-mode frame are measured in the same window (`floor`
// lines: empty renderer, a screen-filling rectangle, the grid frames with a
// negligible density so no ray terminates early).
// Each job runs in its own process.
// Slow jobs time fewer frames (at least one after the first; see Frames()).
#include "plumeBenchmarks.h"
#include "plumeTestSupport.h"

#include "vtkPlumeSheetDensityGrid.h"
#include "vtkPlumeSheetMapper.h"
#include "vtkPlumeSheetReference.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkContourFilter.h"
#include "vtkDataSet.h"
#include "vtkColorTransferFunction.h"
#include "vtkFixedPointVolumeRayCastMapper.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageGaussianSmooth.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkUnstructuredGrid.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <utility>

namespace plume
{
namespace bench
{
namespace
{
const double Density = 0.03;
const double Blur = 0.04;
const double Thick = 0.03;

// the error lattice is 32x32 pixels at 512^2 and 1024^2 (8x8 at --quick's 128^2)
int StrideOf(int size)
{
  return size <= 128 ? 16 : size / 32;
}
// ... offset from pixel 0 by half a stride less one (odd): the pixels between
// the rays of a ray lattice of 2, 4, 8 or 16 pixels (which go through
// multiples of it), so their interpolation error is measured too
int OffsetOf(int stride)
{
  return stride / 2 - 1;
}
const int ScaleSize = 256;     // scaling runs
const int ScaleSizeQuick = 64;

vtkSmartPointer<vtkPolyData> LoadMesh()
{
  vtkSmartPointer<vtkPolyData> mesh =
    vtkPolyData::SafeDownCast(plume::test::LoadDataset("derived/office_stream_sheet.vtp"));
  if (!mesh || mesh->GetNumberOfPolys() < 1)
  {
    throw std::runtime_error("cannot read derived/office_stream_sheet.vtp");
  }
  return mesh;
}

// the fire_ug.vtu mfrac = 0.005 isosurface (1,278 triangles), each triangle
// split into 4 at its edge midpoints `levels` times (same surface)
vtkSmartPointer<vtkPolyData> FireMesh(int levels)
{
  vtkSmartPointer<vtkDataSet> fire = vtkDataSet::SafeDownCast(plume::test::LoadDataset("classic/fire_ug.vtu"));
  if (!fire || !fire->GetPointData()->GetArray("mfrac"))
  {
    throw std::runtime_error("cannot read classic/fire_ug.vtu (mfrac)");
  }
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(fire);
  contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "mfrac");
  contour->SetValue(0, 0.005);
  contour->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(contour->GetOutput()->GetPoints());
  mesh->SetPolys(contour->GetOutput()->GetPolys());
  for (int level = 0; level < levels; ++level)
  {
    vtkNew<vtkPoints> points;
    points->DeepCopy(mesh->GetPoints());
    vtkNew<vtkCellArray> polys;
    std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> midpoints;
    auto mid = [&](vtkIdType a, vtkIdType b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = midpoints.find(key);
      if (it != midpoints.end())
      {
        return it->second;
      }
      double pa[3], pb[3];
      points->GetPoint(a, pa);
      points->GetPoint(b, pb);
      const vtkIdType id =
        points->InsertNextPoint(0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2]));
      midpoints[key] = id;
      return id;
    };
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    vtkCellArray* old = mesh->GetPolys();
    for (old->InitTraversal(); old->GetNextCell(npts, pts);)
    {
      for (vtkIdType k = 1; k + 1 < npts; ++k)
      {
        const vtkIdType a = pts[0], b = pts[k], c = pts[k + 1];
        const vtkIdType ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
        const vtkIdType t[4][3] = { { a, ab, ca }, { ab, b, bc }, { ca, bc, c }, { ab, bc, ca } };
        for (const auto& tri : t)
        {
          polys->InsertNextCell(3, tri);
        }
      }
    }
    mesh = vtkSmartPointer<vtkPolyData>::New();
    mesh->SetPoints(points);
    mesh->SetPolys(polys);
  }
  return mesh;
}

// office: the view of the error runs, zoomed by `zoom` (coverage runs);
// fire: a view of the whole plume
void SetCamera(vtkRenderer* renderer, double azimuth, bool fire = false, double zoom = 1.0)
{
  vtkCamera* cam = renderer->GetActiveCamera();
  if (fire)
  {
    cam->SetPosition(4.2, 2.4, 5.2);
    cam->SetFocalPoint(1.5, 1.5, 1.2);
    cam->SetViewAngle(40);
  }
  else
  {
    cam->SetPosition(1.0, 9.0, 6.0);
    cam->SetFocalPoint(1.9, 1.6, 1.2);
    cam->SetViewAngle(32 / zoom);
  }
  cam->SetViewUp(0, 1, 0);
  cam->Azimuth(azimuth);
  // a fixed clipping range, so every job (and the reference) sees the same rays
  cam->SetClippingRange(fire ? 1.0 : 4.0, fire ? 12.0 : 16.0);
}

// Timed frames after the first (which compiles and uploads): up to 3, but
// stop once 15 s have been spent (slow 1024^2 and 16x10 settings: minutes
// per frame on llvmpipe); the median of those taken.
bool MoreFrames(const std::vector<double>& times)
{
  double total = 0.0;
  for (double t : times)
  {
    total += t;
  }
  return times.size() < 3 && total < 15.0;
}

// fraction of the frame the smoke darkens by more than 1 % (R channel)
double Coverage(vtkRenderWindow* window, int size)
{
  vtkNew<vtkFloatArray> rgba;
  window->GetRGBAPixelData(0, 0, size - 1, size - 1, 0, rgba, 0);
  size_t dark = 0;
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(size) * size; ++i)
  {
    dark += rgba->GetValue(4 * i) < 0.99f ? 1 : 0;
  }
  return double(dark) / (double(size) * size);
}

// the R channel on the sparse lattice (white background, black smoke: R = T)
std::vector<double> Samples(vtkRenderWindow* window, int size, int stride)
{
  vtkNew<vtkFloatArray> rgba;
  window->GetRGBAPixelData(0, 0, size - 1, size - 1, 0, rgba, 0);
  std::vector<double> out;
  for (int y = OffsetOf(stride); y < size; y += stride)
  {
    for (int x = OffsetOf(stride); x < size; x += stride)
    {
      out.push_back(rgba->GetValue(4 * (static_cast<vtkIdType>(y) * size + x)));
    }
  }
  return out;
}

// mass of every triangle deposited (trilinear) at its centroid, as density per volume, then blurred
vtkSmartPointer<vtkImageData> Splat(vtkPolyData* mesh, int n, double density, double blur, double thick)
{
  double b[6];
  mesh->GetBounds(b);
  const double pad = 4 * std::max(blur, thick);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  double spacing[3];
  for (int a = 0; a < 3; ++a)
  {
    spacing[a] = (b[2 * a + 1] - b[2 * a] + 2 * pad) / (n - 1);
  }
  image->SetOrigin(b[0] - pad, b[2] - pad, b[4] - pad);
  image->SetSpacing(spacing);
  vtkNew<vtkFloatArray> rho;
  rho->SetName("density");
  rho->SetNumberOfValues(static_cast<vtkIdType>(n) * n * n);
  rho->Fill(0.0f);
  const double voxel = spacing[0] * spacing[1] * spacing[2];
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts);)
  {
    for (vtkIdType k = 1; k + 1 < npts; ++k)
    {
      double p[3][3];
      mesh->GetPoint(pts[0], p[0]);
      mesh->GetPoint(pts[k], p[1]);
      mesh->GetPoint(pts[k + 1], p[2]);
      double e1[3], e2[3], c[3];
      for (int a = 0; a < 3; ++a)
      {
        e1[a] = p[1][a] - p[0][a];
        e2[a] = p[2][a] - p[0][a];
      }
      const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2],
                   cz = e1[0] * e2[1] - e1[1] * e2[0];
      const double mass = density * 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
      double f[3];
      int i0[3];
      for (int a = 0; a < 3; ++a)
      {
        c[a] = (p[0][a] + p[1][a] + p[2][a]) / 3.0;
        const double g = (c[a] - image->GetOrigin()[a]) / spacing[a];
        i0[a] = std::min(n - 2, std::max(0, static_cast<int>(std::floor(g))));
        f[a] = std::min(1.0, std::max(0.0, g - i0[a]));
      }
      for (int corner = 0; corner < 8; ++corner)
      {
        double w = mass / voxel;
        int idx[3];
        for (int a = 0; a < 3; ++a)
        {
          const bool hi = (corner >> a) & 1;
          idx[a] = i0[a] + hi;
          w *= hi ? f[a] : 1.0 - f[a];
        }
        const vtkIdType id = (static_cast<vtkIdType>(idx[2]) * n + idx[1]) * n + idx[0];
        rho->SetValue(id, rho->GetValue(id) + static_cast<float>(w));
      }
    }
  }
  image->GetPointData()->SetScalars(rho);
  vtkNew<vtkImageGaussianSmooth> smooth;
  smooth->SetInputData(image);
  smooth->SetDimensionality(3);
  smooth->SetStandardDeviations(blur / spacing[0], blur / spacing[1], thick / spacing[2]);
  smooth->SetRadiusFactors(3, 3, 3);
  smooth->Update();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->ShallowCopy(smooth->GetOutput());
  return out;
}

// The floors of a grid-mode frame on this machine, same window, view and
// frame loop as the ours:SIZE:I|V jobs: "clear" renders the empty white
// renderer (clear, swap, read-back wait); "quad" one screen-filling
// rectangle with a trivial fragment shader (one fragment per pixel); "faintI"
// and "faintV" the grid mode's interactive and still frames with the density
// scaled by 1e-9 (the same grid, blocks, rays, steps and skipping, but no ray
// ever terminates early: the cost of marching the occupied blocks).
nlohmann::json Floor(vtkRenderWindow* window, vtkRenderer* renderer, vtkPolyData* mesh, const std::string& what,
  int size)
{
  vtkNew<vtkActor> actor;
  vtkNew<vtkPlumeSheetMapper> sheet;
  vtkNew<vtkPolyDataMapper> quadMapper;
  if (what == "quad")
  {
    vtkNew<vtkPlaneSource> plane; // covers the view: the camera looks at it face-on from close by
    vtkCamera* cam = renderer->GetActiveCamera();
    double p[3], f[3], up[3];
    cam->GetPosition(p);
    cam->GetFocalPoint(f);
    cam->GetViewUp(up);
    const glm::dvec3 eye(p[0], p[1], p[2]), dir = glm::normalize(glm::dvec3(f[0], f[1], f[2]) - eye);
    const glm::dvec3 u = glm::normalize(glm::cross(dir, glm::dvec3(up[0], up[1], up[2])));
    const glm::dvec3 v = glm::cross(u, dir); // (the view-up is not orthogonal to the view direction)
    const glm::dvec3 c = eye + 5.0 * dir, o = c - 10.0 * u - 10.0 * v, a = c + 10.0 * u - 10.0 * v,
                     b = c - 10.0 * u + 10.0 * v;
    plane->SetOrigin(o.x, o.y, o.z);
    plane->SetPoint1(a.x, a.y, a.z);
    plane->SetPoint2(b.x, b.y, b.z);
    plane->Update();
    quadMapper->SetInputConnection(plane->GetOutputPort());
    actor->SetMapper(quadMapper);
    actor->GetProperty()->LightingOff();
    actor->GetProperty()->SetColor(0.5, 0.5, 0.5);
    renderer->AddActor(actor);
  }
  else if (what == "faintI" || what == "faintV")
  {
    sheet->SetInputData(mesh);
    sheet->SetDensity(Density * 1e-9);
    sheet->SetBlurRadius(Blur);
    sheet->SetThickness(Thick);
    sheet->SetRenderMode(vtkPlumeSheetMapper::RENDER_GRID);
    actor->SetMapper(sheet);
    renderer->AddActor(actor);
    window->SetDesiredUpdateRate(what == "faintI" ? 15.0 : 0.0001);
  }
  else if (what != "clear")
  {
    throw std::runtime_error("unknown floor '" + what + "'");
  }
  window->Render();
  window->WaitForCompletion();
  std::vector<double> times;
  for (int f = 0; f < 5; ++f)
  {
    SetCamera(renderer, (f % 2) ? 1.0 : -1.0);
    if (what == "quad")
    {
      SetCamera(renderer, 0.0); // the rectangle must keep covering the view
      renderer->GetActiveCamera()->Roll((f % 2) ? 0.5 : -0.5);
    }
    const double t0 = Now();
    window->Render();
    window->WaitForCompletion();
    times.push_back(Now() - t0);
  }
  nlohmann::json result = { { "render_s", Median(times) }, { "frames", times.size() },
    { "coverage", Coverage(window, size) }, { "peak_rss_mb", PeakRSSMB() } };
  if (what == "faintI" || what == "faintV")
  {
    result["interactive"] = sheet->GetLastInteractive();
    result["lattice"] = sheet->GetLastImageSampleDistance();
    result["grid_step"] = sheet->GetLastGridSampleDistance();
  }
  return result;
}

std::vector<std::string> Split(const std::string& job)
{
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t c = job.find(':'); c != std::string::npos; c = job.find(':', start))
  {
    parts.push_back(job.substr(start, c - start));
    start = c + 1;
  }
  parts.push_back(job.substr(start));
  return parts;
}

// Settings after a job's fixed parts (grid mode and peers), each KEY VALUE:
// nN grid nodes per sigma (fire jobs; the office's is the ARG), isdN ray
// lattice of the interactive frames (ours: InteractiveImageSampleDistance) or
// the peer's ImageSampleDistance, stepS our interactive step (grid
// spacings), tolT our interactive lattice tolerance, "auto" the peer's
// AutoAdjustSampleDistances at the interactive DesiredUpdateRate 15 (its own
// ImageSampleDistance, up to 10 on the fixed-point mapper, and its own step
// on the GPU mapper: what a VTK user gets while moving the camera).
struct Settings
{
  double Nodes = 0; // 0: the job's default
  int Isd = 0;
  double Step = 0;
  double Tol = -1;
  bool Auto = false;
};

Settings ParseSettings(const std::vector<std::string>& part, size_t from)
{
  Settings s;
  for (size_t i = from; i < part.size(); ++i)
  {
    const std::string& p = part[i];
    auto value = [&](size_t n) { return std::stod(p.substr(n)); };
    if (p == "auto")
    {
      s.Auto = true;
    }
    else if (p.compare(0, 3, "isd") == 0)
    {
      s.Isd = static_cast<int>(value(3));
    }
    else if (p.compare(0, 4, "step") == 0)
    {
      s.Step = value(4);
    }
    else if (p.compare(0, 3, "tol") == 0)
    {
      s.Tol = value(3);
    }
    else if (p.compare(0, 1, "n") == 0)
    {
      s.Nodes = value(1);
    }
    else
    {
      throw std::runtime_error("unknown job setting '" + p + "'");
    }
  }
  return s;
}

std::string DescribeSettings(const Settings& s, bool ours)
{
  std::string d;
  auto num = [](double v) {
    char b[32];
    std::snprintf(b, sizeof(b), "%g", v);
    return std::string(b);
  };
  if (s.Nodes > 0)
  {
    d += ", " + num(s.Nodes) + " nodes per sigma";
  }
  if (s.Auto)
  {
    d += ", AutoAdjustSampleDistances at DesiredUpdateRate 15";
  }
  if (s.Isd > 0)
  {
    d += ours ? ", interactive lattice " + num(s.Isd) : ", ImageSampleDistance " + num(s.Isd);
  }
  if (s.Step > 0)
  {
    d += ", interactive step " + num(s.Step);
  }
  if (s.Tol >= 0)
  {
    d += ", lattice tolerance " + num(s.Tol);
  }
  return d;
}

// Jobs: reference:SIZE | ours:SIZE:A|F|G|V|I:ARG[:SETTING...] |
// peer:SIZE:gpu|fixed:N[:SETTING...] | tris:LEVEL:ours|grid|gridi|peer|gpu[:SETTING...] |
// tris:reference | cover:ZOOM:ours|peer
// (V: grid mode still frames, I: grid mode interactive frames)
nlohmann::json RunJob(const Context& context, const std::string& job)
{
  vtkSMPTools::SetBackend("STDThread");
  const std::vector<std::string> part = Split(job);
  const std::string kind = part[0];
  const bool scaling = kind == "tris" || kind == "cover";
  const int size = scaling ? (context.Quick ? ScaleSizeQuick : ScaleSize) : std::stoi(part[1]);
  const int stride = StrideOf(size);
  const bool fire = kind == "tris";
  const bool fireReference = fire && part[1] == "reference";
  const double zoom = kind == "cover" ? std::stod(part[1]) : 1.0;
  const double density = fire ? 0.25 : Density;
  const double blur = fire ? 0.06 : Blur;
  const double thick = fire ? 0.04 : Thick;
  auto mesh = fire ? FireMesh(fireReference ? 0 : std::stoi(part[1])) : LoadMesh();
  auto window = context.MakeWindow(size, size);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1, 1, 1);
  window->AddRenderer(renderer);
  SetCamera(renderer, 0, fire, zoom);
  window->Render();
  window->WaitForCompletion();

  if (kind == "floor")
  {
    return Floor(window, renderer, mesh, part[2], size);
  }

  if (kind == "reference" || fireReference)
  {
    vtkNew<vtkPlumeSheetReference> ref;
    ref->SetInputData(mesh);
    ref->SetDensity(density);
    ref->SetBlurRadius(blur);
    ref->SetThickness(thick);
    ref->SetPixelStride(stride);
    ref->SetPixelOffset(OffsetOf(stride));
    const double t0 = Now();
    ref->Compute(renderer, nullptr);
    const double seconds = Now() - t0;
    std::vector<double> out;
    for (int y = OffsetOf(stride); y < size; y += stride)
    {
      for (int x = OffsetOf(stride); x < size; x += stride)
      {
        out.push_back(ref->GetTransmittance()[3 * (static_cast<size_t>(y) * size + x)]);
      }
    }
    return { { "reference_s", seconds }, { "samples", out }, { "peak_rss_mb", PeakRSSMB() } };
  }

  // ours:SIZE:MODE:ARG, peer:SIZE:gpu|fixed:N; tris/cover:X:ours|peer (default settings / fixed 64^3)
  const std::string who = scaling ? part[2] : "";
  const bool isOurs = kind == "ours" || who == "ours" || who == "grid" || who == "gridi" || who == "grid0";
  const std::string mode = scaling
    ? (who == "ours" ? "A"
        : who == "grid" ? "V"
        : who == "gridi" ? "I"
        : who == "grid0" ? "M"
        : who == "gpu" ? "gpu"
                        : "fixed")
    : part[2];
  const Settings settings = ParseSettings(part, scaling ? 3 : 4);
  const std::string arg = scaling
    ? (who == "ours" ? "8" : who == "grid0" ? "0" : (isOurs ? (settings.Nodes > 0 ? std::to_string(settings.Nodes) : "2") : "64"))
    : part[3];
  // interactive frames: the rate vtkRenderWindowInteractor asks for while the camera moves
  window->SetDesiredUpdateRate(mode == "I" || settings.Auto ? 15.0 : 0.0001);
  vtkNew<vtkActor> actor;
  vtkNew<vtkVolume> volume;
  vtkSmartPointer<vtkPlumeSheetMapper> ours;
  vtkSmartPointer<vtkOpenGLGPUVolumeRayCastMapper> gpuPeer;
  vtkSmartPointer<vtkFixedPointVolumeRayCastMapper> fixedPeer;
  double prep = 0.0;
  const double start = Now();
  if (isOurs)
  {
    ours = vtkSmartPointer<vtkPlumeSheetMapper>::New();
    ours->SetInputData(mesh);
    ours->SetDensity(density);
    ours->SetBlurRadius(blur);
    ours->SetThickness(thick);
    if (mode == "V" || mode == "I")
    {
      // grid mode: the smoke on a grid of ARG nodes per sigma, raycast
      ours->SetRenderMode(vtkPlumeSheetMapper::RENDER_GRID);
      ours->SetGridSamplesPerSigma(std::stod(arg));
      if (settings.Isd > 0)
      {
        ours->SetInteractiveImageSampleDistance(settings.Isd);
      }
      if (settings.Step > 0)
      {
        ours->SetInteractiveGridSampleDistance(settings.Step);
      }
      if (settings.Tol >= 0)
      {
        ours->SetInteractiveLatticeTolerance(settings.Tol);
      }
    }
    else if (mode == "M")
    {
      // grid mode, default nodes per sigma, quadrature points merged in cells of ARG spacings (0: none)
      ours->SetRenderMode(vtkPlumeSheetMapper::RENDER_GRID);
      ours->SetGridMergeCellSize(std::stod(arg));
    }
    else if (mode == "A" || mode == "F")
    {
      ours->SetQuadrature(vtkPlumeSheetMapper::QUADRATURE_ANALYTIC);
      ours->SetGridA(std::stoi(arg));
      ours->SetAdaptiveSampling(mode == "A"); // F: fixed, every triangle in pieces
    }
    else
    {
      ours->SetQuadrature(vtkPlumeSheetMapper::QUADRATURE_GRID);
      ours->SetGridA(std::stoi(arg.substr(0, arg.find('x'))));
      ours->SetGridB(std::stoi(arg.substr(arg.find('x') + 1)));
    }
    actor->SetMapper(ours);
    renderer->AddActor(actor);
  }
  else
  {
    const int n = std::stoi(arg);
    auto grid = Splat(mesh, n, density, blur, thick);
    prep = Now() - start;
    double range[2];
    grid->GetPointData()->GetScalars()->GetRange(range);
    const double unit = std::min({ grid->GetSpacing()[0], grid->GetSpacing()[1], grid->GetSpacing()[2] });
    // extinction = density: opacity per unit distance u is 1 - exp(-rho u)
    vtkNew<vtkPiecewiseFunction> opacity;
    const int points = 64;
    for (int i = 0; i <= points; ++i)
    {
      const double s = range[1] * i / points;
      opacity->AddPoint(s, 1.0 - std::exp(-s * unit));
    }
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.0, 0, 0, 0);
    color->AddRGBPoint(std::max(range[1], 1e-6), 0, 0, 0);
    vtkNew<vtkVolumeProperty> property;
    property->SetScalarOpacity(opacity);
    property->SetColor(color);
    property->SetScalarOpacityUnitDistance(unit);
    property->SetInterpolationTypeToLinear();
    property->ShadeOff();
    volume->SetProperty(property);
    if (mode == "gpu")
    {
      vtkNew<vtkOpenGLGPUVolumeRayCastMapper> mapper;
      mapper->SetInputData(grid);
      mapper->SetAutoAdjustSampleDistances(settings.Auto);
      mapper->SetSampleDistance(0.5 * unit);
      mapper->SetImageSampleDistance(settings.Isd > 0 ? settings.Isd : 1.0);
      volume->SetMapper(mapper);
      gpuPeer = mapper;
    }
    else
    {
      vtkNew<vtkFixedPointVolumeRayCastMapper> mapper;
      mapper->SetInputData(grid);
      mapper->SetAutoAdjustSampleDistances(settings.Auto);
      mapper->SetSampleDistance(0.5 * unit);
      mapper->SetImageSampleDistance(settings.Isd > 0 ? settings.Isd : 1.0);
      volume->SetMapper(mapper);
      fixedPeer = mapper;
    }
    renderer->AddVolume(volume);
  }
  window->Render();
  window->WaitForCompletion();
  const double first = Now() - start;
  // the auto-adjusting peers settle their sample distances over a few frames
  for (int f = 0; settings.Auto && f < 8; ++f)
  {
    SetCamera(renderer, (f % 2) ? 1.0 : -1.0, fire, zoom);
    window->Render();
    window->WaitForCompletion();
  }
  std::vector<double> times;
  for (int f = 0; MoreFrames(times); ++f)
  {
    SetCamera(renderer, (f % 2) ? 1.0 : -1.0, fire, zoom); // a real re-render, as when a user rotates
    const double t0 = Now();
    window->Render();
    window->WaitForCompletion();
    times.push_back(Now() - t0);
  }
  SetCamera(renderer, 0, fire, zoom);
  window->Render();
  window->WaitForCompletion();
  nlohmann::json result = { { "first_s", first }, { "render_s", Median(times) },
    { "frames", times.size() }, { "prep_s", prep }, { "peak_rss_mb", PeakRSSMB() } };
  if (!scaling || fire)
  {
    result["samples"] = Samples(window, size, stride);
  }
  // the image sample distance the peer ended on (auto: what it adapted to)
  if (gpuPeer)
  {
    result["image_sample_distance"] = gpuPeer->GetImageSampleDistance();
  }
  if (fixedPeer)
  {
    result["image_sample_distance"] = fixedPeer->GetImageSampleDistance();
  }
  if (ours)
  {
    if (ours->GetRenderMode() == vtkPlumeSheetMapper::RENDER_GRID)
    {
      result["grid_s"] = ours->GetGridComputeSeconds();
      result["grid_quadrature_s"] = ours->GetDensityGrid()->GetQuadratureSeconds();
      result["grid_merge_s"] = ours->GetDensityGrid()->GetMergeSeconds();
      result["grid_splat_s"] = ours->GetDensityGrid()->GetSplatSeconds();
      result["grid_points"] = ours->GetDensityGrid()->GetPointCount();
      result["grid_gaussians"] = ours->GetDensityGrid()->GetGaussianCount();
      result["grid_merge_cell"] = ours->GetGridMergeCellSize();
      if (vtkImageData* grid = ours->GetDensityGrid()->GetOutput())
      {
        const int* dims = grid->GetDimensions();
        result["grid_nodes"] = double(dims[0]) * dims[1] * dims[2];
      }
      result["grid_spacing"] = ours->GetGridSpacing();
      result["grids"] = ours->GetGridComputeCount();
      result["interactive"] = ours->GetLastInteractive();
      result["grid_step"] = ours->GetLastGridSampleDistance();
      result["lattice"] = ours->GetLastImageSampleDistance();
    }
    result["uploads"] = ours->GetUploadCount();
    result["triangles"] = ours->GetTriangleCount();
    result["coverage"] = Coverage(window, size);
  }
  return result;
}

// the error runs: image sizes, our settings and peers per size
std::vector<int> Sizes(bool quick)
{
  return quick ? std::vector<int>{ 128 } : std::vector<int>{ 512, 1024 };
}

// the cheap end of the grid mode's time-vs-error curve, interactive frames:
// NODES[:SETTING...] (see Settings)
std::vector<std::string> InteractiveSettings()
{
  return { "2:isd4", "2:isd4:tol0.016", "2:isd8:tol0.016", "2:isd8:tol0.064", "2:isd8:step4:tol0.064",
    "2:isd16:tol0.064", "1:isd4:tol0.064", "1:isd8:tol0.064", "0.5:isd4", "0.5:isd8:tol0.064" };
}

// the peers' interactive settings (what a VTK user picks while moving the camera)
const char* const PeerInteractive[] = { ":isd2", ":isd4", ":auto" };

std::vector<std::string> OursJobs(bool quick, int size)
{
  const std::string p = "ours:" + std::to_string(size) + ":";
  if (quick)
  {
    // one job per code path: exact (A), the regular grid (G, its cheapest), grid mode (V)
    return { p + "A:8", p + "G:2x1", p + "V:0.5" };
  }
  if (size == 512)
  {
    std::vector<std::string> jobs = { p + "V:0.5", p + "V:1", p + "V:1.5", p + "V:2", p + "V:3", p + "M:0",
      p + "M:1", p + "M:4", p + "I:1", p + "I:2" };
    for (const auto& i : InteractiveSettings())
    {
      jobs.push_back(p + "I:" + i);
    }
    for (const char* j : { "A:2", "A:4", "A:8", "F:8", "G:2x1", "G:8x5", "G:16x10" })
    {
      jobs.push_back(p + j);
    }
    return jobs;
  }
  return { p + "A:2", p + "A:8", p + "G:2x1", p + "G:8x5" };
}

std::vector<std::string> PeerJobs(bool quick, int size)
{
  const std::string p = "peer:" + std::to_string(size) + ":";
  if (quick)
  {
    return { p + "fixed:32" };
  }
  std::vector<std::string> jobs = { p + "fixed:64", p + "fixed:128", p + "fixed:256", p + "gpu:64", p + "gpu:128",
    p + "gpu:256" };
  if (size == 512)
  {
    for (const char* peer : { "fixed:64", "fixed:128", "gpu:64" })
    {
      for (const char* i : PeerInteractive)
      {
        jobs.push_back(p + peer + i);
      }
    }
  }
  return jobs;
}

// the 1.3 M-triangle fire's interactive settings, ours and the peers'
std::vector<std::string> FireInteractiveJobs()
{
  std::vector<std::string> jobs;
  for (const auto& i : InteractiveSettings())
  {
    jobs.push_back("tris:5:gridi:n" + i);
  }
  for (const char* peer : { "peer", "gpu" })
  {
    for (const char* i : PeerInteractive)
    {
      jobs.push_back(std::string("tris:5:") + peer + i);
    }
  }
  return jobs;
}

// scaling: subdivision levels of the fire isosurface, zooms of the office sheet
std::vector<std::string> ScalingJobs(bool quick)
{
  std::vector<std::string> jobs;
  const std::vector<std::string> levels = quick ? std::vector<std::string>{ "0" }
                                                : std::vector<std::string>{ "0", "1", "2", "3", "4", "5" };
  const std::vector<std::string> zooms =
    quick ? std::vector<std::string>{} : std::vector<std::string>{ "0.5", "1", "2", "4" };
  for (const auto& l : levels)
  {
    jobs.push_back("tris:" + l + ":ours");
    jobs.push_back("tris:" + l + ":peer");
  }
  // the million-triangle case: every mode and both peers, with errors
  if (!quick)
  {
    jobs.push_back("tris:reference");
    for (const char* who : { "grid", "gridi", "grid0", "gpu" })
    {
      jobs.push_back(std::string("tris:5:") + who);
    }
    for (const auto& j : FireInteractiveJobs())
    {
      jobs.push_back(j);
    }
  }
  for (const auto& z : zooms)
  {
    jobs.push_back("cover:" + z + ":ours");
    jobs.push_back("cover:" + z + ":peer");
  }
  return jobs;
}

// the floors of a grid-mode frame (see Floor)
// (not in --quick: its error runs have no default grid-mode frame to compare with)
std::vector<std::string> FloorJobs(bool quick)
{
  if (quick)
  {
    return {};
  }
  const std::string p = "floor:512:";
  return { p + "clear", p + "quad", p + "faintI", p + "faintV" };
}

// RMS and max error as fractions of the reference's dynamic range
std::pair<double, double> Error(const nlohmann::json& ref, const nlohmann::json& got)
{
  const auto& r = ref["samples"];
  const auto& g = got["samples"];
  double lo = 1e300, hi = -1e300, sum = 0, worst = 0;
  size_t n = 0;
  for (size_t i = 0; i < r.size() && i < g.size(); ++i)
  {
    const double t = r[i].get<double>();
    lo = std::min(lo, t);
    hi = std::max(hi, t);
    const double e = std::fabs(g[i].get<double>() - t);
    sum += e * e;
    worst = std::max(worst, e);
    ++n;
  }
  const double range = std::max(hi - lo, 1e-12);
  return { n ? std::sqrt(sum / n) / range : 0.0, worst / range };
}

std::string Describe(const std::string& job)
{
  const std::vector<std::string> part = Split(job);
  if (part[0] == "ours")
  {
    const std::string& arg = part[3];
    if (part[2] == "V")
    {
      return "grid mode, " + arg + " nodes per sigma" + (arg == "2" ? " (default)" : "") + ", still frames";
    }
    if (part[2] == "I")
    {
      return "grid mode, " + arg + " nodes per sigma" + (arg == "2" && part.size() == 4 ? " (default)" : "") +
        ", interactive frames (DesiredUpdateRate 15)" + DescribeSettings(ParseSettings(part, 4), true);
    }
    if (part[2] == "M")
    {
      return "grid mode, 2 nodes per sigma, quadrature points merged per " + arg +
        "-spacing cell" + (arg == "0" ? " (none: every point splatted)" : "") + ", still frames";
    }
    if (part[2] == "F")
    {
      return "Gauss-Legendre " + arg + " nodes/piece + closed form across, adaptive sampling off";
    }
    if (part[2] == "A")
    {
      return "Gauss-Legendre " + arg + " nodes/piece + closed form across" + (arg == "8" ? " (default)" : "");
    }
    return "regular grid " + arg + " x2 (seed 000)";
  }
  const bool gpu = part[2] == "gpu";
  return std::string(gpu ? "vtkGPUVolumeRayCastMapper" : "vtkFixedPointVolumeRayCastMapper") +
    " on a splatted " + part[3] + "^3 grid" + DescribeSettings(ParseSettings(part, 4), false);
}

// the 1.3 M-triangle fire's jobs (tris:5:WHO[:SETTING...])
std::string DescribeFire(const std::string& job)
{
  const std::vector<std::string> part = Split(job);
  static const std::map<std::string, std::string> names = { { "ours", "exact mode (default settings)" },
    { "grid", "grid mode, still frames" }, { "gridi", "grid mode, interactive frames (DesiredUpdateRate 15)" },
    { "grid0", "grid mode without merging (every quadrature point splatted), still frames" },
    { "peer", "vtkFixedPointVolumeRayCastMapper on a splatted 64^3 grid" },
    { "gpu", "vtkGPUVolumeRayCastMapper on a splatted 64^3 grid" } };
  const bool ours = part[2] != "peer" && part[2] != "gpu";
  return names.at(part[2]) + DescribeSettings(ParseSettings(part, 3), ours);
}

// The comparison: for each peer setting, our fastest setting whose
// RMS and max error are both not above the peer's, and the speed ratio
// (goal: >= 3). `ours` and `peers` are job names; missing results are skipped.
void Compare(const std::map<std::string, nlohmann::json>& results, const nlohmann::json& ref,
  const std::vector<std::string>& ours, const std::vector<std::string>& peers, const std::string& where,
  const std::function<std::string(const std::string&)>& describe, std::vector<nlohmann::json>& lines)
{
  for (const auto& peerJob : peers)
  {
    const auto peer = results.find(peerJob);
    if (peer == results.end() || !peer->second.contains("samples"))
    {
      continue;
    }
    const auto perr = Error(ref, peer->second);
    // (if none is as accurate, our most accurate setting, said so)
    std::string best, accurate;
    double bestS = 1e300, accurateRMS = 1e300;
    for (const auto& job : ours)
    {
      const auto it = results.find(job);
      if (it == results.end() || !it->second.contains("samples"))
      {
        continue;
      }
      const auto err = Error(ref, it->second);
      const double t = it->second["render_s"].get<double>();
      if (err.first <= perr.first && err.second <= perr.second && t < bestS)
      {
        best = job;
        bestS = t;
      }
      if (err.first < accurateRMS)
      {
        accurate = job;
        accurateRMS = err.first;
      }
    }
    const bool equal = !best.empty();
    if (!equal)
    {
      best = accurate;
    }
    nlohmann::json line = { { "bench", "sheets" },
      { "case", "comparison: " + where + "our fastest setting at equal or lower RMS and max error than " +
          describe(peerJob) },
      { "peer", describe(peerJob) }, { "peer_job", peerJob }, { "peer_s", peer->second["render_s"] },
      { "peer_error", perr.first }, { "peer_error_max", perr.second } };
    if (peer->second.contains("image_sample_distance"))
    {
      line["peer_image_sample_distance"] = peer->second["image_sample_distance"];
    }
    if (best.empty())
    {
      continue; // none of ours run
    }
    const auto it = results.find(best);
    const auto err = Error(ref, it->second);
    line["ours"] = (equal ? "" : "none at equal or lower error; the most accurate: ") + describe(best);
    line["ours_job"] = best;
    line["ours_s"] = it->second["render_s"];
    line["error"] = err.first;
    line["error_max"] = err.second;
    line["ratio"] = peer->second["render_s"].get<double>() / it->second["render_s"].get<double>();
    line["goal_3x_met"] = equal && line["ratio"].get<double>() >= 3.0;
    line["peak_rss_mb"] = it->second["peak_rss_mb"];
    line["peer_peak_rss_mb"] = peer->second["peak_rss_mb"];
    lines.push_back(line);
  }
}

std::vector<nlohmann::json> Report(const std::map<std::string, nlohmann::json>& results, bool quick)
{
  std::vector<nlohmann::json> lines;
  for (int size : Sizes(quick))
  {
    const auto ref = results.find("reference:" + std::to_string(size));
    if (ref == results.end())
    {
      continue;
    }
    const std::string where = "office stream sheet " + std::to_string(size) + "^2, ";
    // the most accurate peer is the fair comparison
    std::string best;
    double bestErr = 1e300;
    for (const auto& job : PeerJobs(quick, size))
    {
      const auto it = results.find(job);
      if (it != results.end())
      {
        const double e = Error(ref->second, it->second).first;
        if (e < bestErr)
        {
          bestErr = e;
          best = job;
        }
      }
    }
    for (const auto& job : OursJobs(quick, size))
    {
      const auto it = results.find(job);
      if (it == results.end())
      {
        continue;
      }
      const auto err = Error(ref->second, it->second);
      nlohmann::json line = { { "bench", "sheets" }, { "case", where + Describe(job) },
        { "ours_s", it->second["render_s"] }, { "ours_first_s", it->second["first_s"] },
        { "frames", it->second["frames"] }, { "error", err.first }, { "error_max", err.second },
        { "peak_rss_mb", it->second["peak_rss_mb"] }, { "reference_s", ref->second["reference_s"] } };
      if (it->second.contains("grid_s"))
      {
        line["grid_s"] = it->second["grid_s"];
        line["grid_spacing"] = it->second["grid_spacing"];
      }
      const auto peer = results.find(best);
      if (peer != results.end())
      {
        const auto perr = Error(ref->second, peer->second);
        line["peer"] = Describe(best);
        line["peer_s"] = peer->second["render_s"];
        line["peer_prep_s"] = peer->second["prep_s"];
        line["peer_error"] = perr.first;
        line["peer_error_max"] = perr.second;
        line["ratio"] = peer->second["render_s"].get<double>() / it->second["render_s"].get<double>();
      }
      lines.push_back(line);
    }
    Compare(results, ref->second, OursJobs(quick, size), PeerJobs(quick, size), where, Describe, lines);
    // every peer on its own line, against the exact mode's default and the grid mode's default
    for (const std::string defJob : { ":A:8", ":V:2" })
    for (const auto& job : PeerJobs(quick, size))
    {
      const auto def = results.find("ours:" + std::to_string(size) + defJob);
      const auto it = results.find(job);
      if (it == results.end() || def == results.end())
      {
        continue;
      }
      const std::string ourName = defJob == ":V:2" ? "grid mode default" : "default";
      const auto perr = Error(ref->second, it->second);
      const auto oerr = Error(ref->second, def->second);
      lines.push_back({ { "bench", "sheets" }, { "case", where + ourName + " vs " + Describe(job) },
        { "ours_s", def->second["render_s"] }, { "error", oerr.first }, { "error_max", oerr.second },
        { "peer", Describe(job) },
        { "peer_s", it->second["render_s"] }, { "peer_prep_s", it->second["prep_s"] },
        { "peer_error", perr.first }, { "peer_error_max", perr.second },
        { "ratio", it->second["render_s"].get<double>() / def->second["render_s"].get<double>() },
        { "peak_rss_mb", def->second["peak_rss_mb"] }, { "peer_peak_rss_mb", it->second["peak_rss_mb"] } });
    }
  }
  // the density grid's build as its own case: merged (default) against every
  // quadrature point splatted (MergeCellSize 0, the build before merging),
  // both with their frame's error against the reference
  {
    const std::string s = quick ? "128" : "512";
    const auto fireRef0 = results.find("tris:reference");
    const auto ref512 = results.find("reference:" + s);
    struct Pair
    {
      std::string Ours, Before, Name;
      std::map<std::string, nlohmann::json>::const_iterator Ref;
    };
    const std::vector<Pair> pairs = { { "ours:" + s + ":V:2", "ours:" + s + ":M:0", "office stream sheet", ref512 },
      { "tris:5:grid", "tris:5:grid0", "fire mfrac isosurface split 5x (1.3 M triangles)", fireRef0 } };
    for (const auto& pr : pairs)
    {
      const auto it = results.find(pr.Ours);
      if (it == results.end() || !it->second.contains("grid_s") || pr.Ref == results.end())
      {
        continue;
      }
      const auto err = Error(pr.Ref->second, it->second);
      nlohmann::json line = { { "bench", "sheets" },
        { "case", "grid build: " + pr.Name + ", 2 nodes per sigma, points merged per 2-spacing cell (default)" },
        { "ours_s", it->second["grid_s"] }, { "error", err.first }, { "error_max", err.second },
        { "grid_quadrature_s", it->second["grid_quadrature_s"] }, { "grid_merge_s", it->second["grid_merge_s"] },
        { "grid_splat_s", it->second["grid_splat_s"] }, { "grid_points", it->second["grid_points"] },
        { "grid_gaussians", it->second["grid_gaussians"] }, { "grid_nodes", it->second["grid_nodes"] },
        { "peak_rss_mb", it->second["peak_rss_mb"] } };
      const auto before = results.find(pr.Before);
      if (before == results.end() || !before->second.contains("grid_s"))
      {
        continue; // (every line has a peer)
      }
      {
        const auto berr = Error(pr.Ref->second, before->second);
        line["peer"] = "same grid, every quadrature point splatted (MergeCellSize 0: the build before merging)";
        line["peer_s"] = before->second["grid_s"];
        line["peer_error"] = berr.first;
        line["peer_error_max"] = berr.second;
        line["ratio"] = before->second["grid_s"].get<double>() / std::max(1e-9, it->second["grid_s"].get<double>());
        line["peer_peak_rss_mb"] = before->second["peak_rss_mb"];
      }
      lines.push_back(line);
    }
  }
  // the floors of a grid-mode frame, next to the frame itself
  for (const auto& job : FloorJobs(quick))
  {
    const auto it = results.find(job);
    if (it == results.end())
    {
      continue;
    }
    const std::string what = Split(job)[2];
    static const std::map<std::string, std::string> names = {
      { "clear", "empty renderer (clear + swap)" }, { "quad", "one screen-filling rectangle, trivial shader" },
      { "faintI", "grid mode interactive frame, density x 1e-9 (same rays and skipping, no early termination)" },
      { "faintV", "grid mode still frame, density x 1e-9 (same rays and skipping, no early termination)" } };
    nlohmann::json line = { { "bench", "sheets" },
      { "case", "floor: office view " + Split(job)[1] + "^2, " + names.at(what) }, { "ours_s", it->second["render_s"] },
      { "frames", it->second["frames"] }, { "peak_rss_mb", it->second["peak_rss_mb"] } };
    // the "peer" is the real grid-mode frame: ratio = how far it is above this floor
    const std::string frameJob = std::string("ours:") + Split(job)[1] + (what == "faintV" ? ":V:2" : ":I:2");
    const auto frame = results.find(frameJob);
    if (frame == results.end())
    {
      continue;
    }
    line["peer"] = "the frame itself: " + Describe(frameJob);
    line["peer_s"] = frame->second["render_s"];
    line["ratio"] = frame->second["render_s"].get<double>() / std::max(1e-9, it->second["render_s"].get<double>());
    lines.push_back(line);
  }
  // scaling: default settings against splat + fixed-point 64^3 of the same mesh and view (no error)
  const int scaleSize = quick ? ScaleSizeQuick : ScaleSize;
  const auto fireRef = results.find("tris:reference");
  // the million-triangle fire: every mode and peer against the reference (no ratio: see the lines above)
  for (const auto& job : ScalingJobs(quick))
  {
    const auto part = Split(job);
    if (part[0] != "tris" || part[1] != "5" || fireRef == results.end())
    {
      continue;
    }
    const auto it = results.find(job);
    if (it == results.end() || !it->second.contains("samples"))
    {
      continue;
    }
    const auto err = Error(fireRef->second, it->second);
    nlohmann::json line = { { "bench", "sheets" },
      { "case", "fire mfrac isosurface split 5x (1.3 M triangles), " + std::to_string(scaleSize) + "^2, " +
          DescribeFire(job) },
      { "ours_s", it->second["render_s"] }, { "ours_first_s", it->second["first_s"] },
      { "frames", it->second["frames"] }, { "error", err.first }, { "error_max", err.second },
      { "peak_rss_mb", it->second["peak_rss_mb"] }, { "reference_s", fireRef->second["reference_s"] } };
    if (it->second.contains("grid_s"))
    {
      line["grid_s"] = it->second["grid_s"];
      line["grid_spacing"] = it->second["grid_spacing"];
    }
    if (it->second.contains("prep_s"))
    {
      line["prep_s"] = it->second["prep_s"];
    }
    lines.push_back(line);
  }
  // the comparison on the fire
  if (fireRef != results.end())
  {
    std::vector<std::string> ours, peers;
    for (const auto& job : ScalingJobs(quick))
    {
      const auto part = Split(job);
      if (part[0] == "tris" && part[1] == "5")
      {
        (part[2] == "peer" || part[2] == "gpu" ? peers : ours).push_back(job);
      }
    }
    Compare(results, fireRef->second, ours, peers,
      "fire mfrac isosurface split 5x (1.3 M triangles), " + std::to_string(scaleSize) + "^2, ", DescribeFire, lines);
  }
  for (const auto& job : ScalingJobs(quick))
  {
    if (job.size() < 5 || job.compare(job.size() - 5, 5, ":ours") != 0)
    {
      continue;
    }
    const auto it = results.find(job);
    const auto peer = results.find(job.substr(0, job.size() - 5) + ":peer");
    if (it == results.end() || peer == results.end())
    {
      continue;
    }
    const auto part = Split(job);
    const std::string what = part[0] == "tris"
      ? "fire mfrac isosurface split " + part[1] + "x, " +
        std::to_string(it->second["triangles"].get<long long>()) + " triangles"
      : "office stream sheet zoom " + part[1];
    char cover[64];
    std::snprintf(cover, sizeof(cover), ", %.0f%% of the frame", 100.0 * it->second["coverage"].get<double>());
    lines.push_back({ { "bench", "sheets" },
      { "case", "scaling: " + what + cover + ", " + std::to_string(scaleSize) + "^2, default settings" },
      { "ours_s", it->second["render_s"] }, { "ours_first_s", it->second["first_s"] },
      { "frames", it->second["frames"] }, { "triangles", it->second["triangles"] },
      { "coverage", it->second["coverage"] }, { "peer", "vtkFixedPointVolumeRayCastMapper on a splatted 64^3 grid" },
      { "peer_s", peer->second["render_s"] }, { "peer_prep_s", peer->second["prep_s"] },
      { "ratio", peer->second["render_s"].get<double>() / it->second["render_s"].get<double>() },
      { "peak_rss_mb", it->second["peak_rss_mb"] } });
  }
  return lines;
}
}

void RegisterSheets(std::map<std::string, Benchmark>& registry)
{
  Benchmark b;
  b.Description = "smoke sheets on a real stream sheet: time vs error per sample setting (512^2, 1024^2), vs "
                  "splat + vtkGPUVolumeRayCastMapper / vtkFixedPointVolumeRayCastMapper (64^3..256^3), errors vs "
                  "the CPU reference; scaling with triangle count and screen coverage";
  b.Jobs = [](bool quick) {
    std::vector<std::string> jobs;
    for (int size : Sizes(quick))
    {
      jobs.push_back("reference:" + std::to_string(size));
      for (const auto& j : OursJobs(quick, size))
      {
        jobs.push_back(j);
      }
      for (const auto& j : PeerJobs(quick, size))
      {
        jobs.push_back(j);
      }
    }
    for (const auto& j : ScalingJobs(quick))
    {
      jobs.push_back(j);
    }
    for (const auto& j : FloorJobs(quick))
    {
      jobs.push_back(j);
    }
    return jobs;
  };
  b.Run = RunJob;
  b.Report = Report;
  registry["sheets"] = b;
}

}
}
