#include "vtkPlumeSmokeSolver.h"

#include "vtkPlumeParameterTable.h"
#include "vtkPlumePressureSolver.h"

#include "plumeGridRows.h"
#include "plumeSmokeGPU.h"
#include "vtkPlumeQuietExecutive.h"
#include "vtkPlumeTextureHandOver.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSelectEnclosedPoints.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <cmath>
#include <limits>
#include <sstream>
#if __has_include(<unistd.h>)
#include <unistd.h> // sysconf: the physical memory
#endif

vtkStandardNewMacro(vtkPlumeSmokeSolver);

using plume::smoke::ForRows;

namespace
{
const char* const FaceNames[6] = { "xmin", "xmax", "ymin", "ymax", "zmin", "zmax" };

// Parses OpenFaces; returns "" or the offending word.
std::string ParseOpenFaces(const std::string& text, bool open[6])
{
  std::fill(open, open + 6, false);
  std::string word;
  std::string all = text;
  std::replace(all.begin(), all.end(), ',', ' ');
  std::istringstream words(all);
  while (words >> word)
  {
    if (word == "all")
    {
      std::fill(open, open + 6, true);
      continue;
    }
    const auto* it = std::find(FaceNames, FaceNames + 6, word);
    if (it == FaceNames + 6)
    {
      return word;
    }
    open[it - FaceNames] = true;
  }
  return "";
}

std::string Text(double v)
{
  std::ostringstream out;
  out << v;
  return out.str();
}

// Trilinear sample of a grid with m points per axis whose point (0,0,0) is
// at index-space position g = 0; positions outside are clamped to the grid.
double Trilinear(const std::vector<double>& f, const int m[3], glm::dvec3 g)
{
  int i0[3];
  double t[3];
  for (int a = 0; a < 3; ++a)
  {
    const double x = std::min(std::max(g[a], 0.0), double(m[a] - 1));
    const int i = std::min(int(x), std::max(m[a] - 2, 0));
    i0[a] = i;
    t[a] = m[a] > 1 ? x - i : 0.0;
  }
  const size_t sx = m[0] > 1 ? 1 : 0;
  const size_t sy = m[1] > 1 ? size_t(m[0]) : 0;
  const size_t sz = m[2] > 1 ? size_t(m[0]) * m[1] : 0;
  const size_t c = i0[0] + size_t(m[0]) * (i0[1] + size_t(m[1]) * i0[2]);
  const double c00 = f[c] * (1 - t[0]) + f[c + sx] * t[0];
  const double c10 = f[c + sy] * (1 - t[0]) + f[c + sy + sx] * t[0];
  const double c01 = f[c + sz] * (1 - t[0]) + f[c + sz + sx] * t[0];
  const double c11 = f[c + sz + sy] * (1 - t[0]) + f[c + sz + sy + sx] * t[0];
  const double c0 = c00 * (1 - t[1]) + c10 * t[1];
  const double c1 = c01 * (1 - t[1]) + c11 * t[1];
  return c0 * (1 - t[2]) + c1 * t[2];
}

// The point of `image` nearest to x, or -1 outside it.
vtkIdType NearestPoint(vtkImageData* image, const glm::dvec3& x)
{
  const double* io = image->GetOrigin();
  const double* is = image->GetSpacing();
  const int* ext = image->GetExtent();
  int idx[3];
  for (int a = 0; a < 3; ++a)
  {
    const double g = is[a] != 0 ? (x[a] - io[a]) / is[a] : double(ext[2 * a]);
    idx[a] = int(std::lround(g));
    if (idx[a] < ext[2 * a] || idx[a] > ext[2 * a + 1])
    {
      return -1;
    }
  }
  return image->ComputePointId(idx);
}

// The smallest and largest of the (up to 8) grid values Trilinear() would blend at g.
void MinMax(const std::vector<double>& f, const int m[3], glm::dvec3 g, double& lo, double& hi)
{
  int i0[3], i1[3];
  for (int a = 0; a < 3; ++a)
  {
    const double x = std::min(std::max(g[a], 0.0), double(m[a] - 1));
    i0[a] = std::min(int(x), std::max(m[a] - 2, 0));
    i1[a] = std::min(i0[a] + 1, m[a] - 1);
  }
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  for (int k : { i0[2], i1[2] })
    for (int j : { i0[1], i1[1] })
      for (int i : { i0[0], i1[0] })
      {
        const double v = f[i + size_t(m[0]) * (j + size_t(m[1]) * k)];
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
}
}

//------------------------------------------------------------------------------
const vtkPlumeParameterTable& vtkPlumeSmokeSolver::GetParameterTable()
{
  static const vtkPlumeParameterTable table = [] {
    using T = vtkPlumeSmokeSolver;
    vtkPlumeParameterTable t("vtkPlumeSmokeSolver", "smoke");
    // Integer 3-vector: the table's vectors are doubles, so bound by hand.
    auto& dims = t.Vector3("dimensions", "Dimensions", { 48, 48, 64 })
                   .Between(1, 4096)
                   .Panel("Grid")
                   .Doc("Grid points (simulation cells) along x, y, z; 1 along z for a 2D simulation.");
    dims.Setter = [](vtkObject* o, const vtkPlumeParameterTable::Value& v) {
      const auto d = std::get<std::array<double, 3>>(v);
      static_cast<T*>(o)->SetDimensions(int(std::lround(d[0])), int(std::lround(d[1])), int(std::lround(d[2])));
    };
    dims.Getter = [](vtkObject* o) -> vtkPlumeParameterTable::Value {
      const int* d = static_cast<T*>(o)->GetDimensions();
      return std::array<double, 3>{ double(d[0]), double(d[1]), double(d[2]) };
    };
    t.Vector3("origin", "Origin", { 0, 0, 0 })
      .Units("model units")
      .Panel("Grid")
      .Doc("Position of the first grid point.")
      .Bind(&T::SetOrigin, &T::GetOrigin);
    t.Vector3("spacing", "Spacing", { 0.02, 0.02, 0.02 })
      .Between(1e-30, 1e30)
      .Units("model units")
      .Panel("Grid")
      .Doc("Distance between grid points; the walls lie half a spacing outside the outermost points.")
      .Bind(&T::SetSpacing, &T::GetSpacing);
    t.Real("time_step", "TimeStep", 0.02)
      .Between(1e-30, 1e30)
      .Units("s")
      .Panel("Time")
      .Doc("Seconds per simulation step (stable at any CFL number).")
      .Bind(&T::SetTimeStep, &T::GetTimeStep);
    t.Integer("time_steps", "NumberOfTimeSteps", 200)
      .Between(1, 10000000)
      .Panel("Time")
      .Doc("Steps advertised to the pipeline (times k * time_step, k = 0 .. time_steps).")
      .Bind(&T::SetNumberOfTimeSteps, &T::GetNumberOfTimeSteps);
    t.Choice("advection", "AdvectionScheme", "semi_lagrangian")
      .Choice("semi_lagrangian", SEMI_LAGRANGIAN, "the seed's: trilinear sample at the back-traced point (first order, diffusive)")
      .Choice("maccormack", MACCORMACK,
        "MacCormack: a forward-and-back round trip corrects the semi-Lagrangian error (second order), clamped "
        "to the sampled values; about twice the advection cost")
      .Panel("Advection")
      .Doc("How density, temperature and velocity move with the flow.")
      .Bind(&T::SetAdvectionScheme, &T::GetAdvectionScheme);
    t.Choice("backend", "Backend", "cpu")
      .Choice("cpu", BACKEND_CPU, "vtkSMPTools threads; every feature")
      .Choice("gpu", BACKEND_GPU,
        "the seed's fragment-shader passes on float 3D textures (layered rendering), equal to the CPU's Jacobi "
        "path to float rounding; Jacobi for exactly pressure_max_iterations iterations; no MacCormack, "
        "confinement, conserve_mass, moving obstacles, given velocity or source points")
      .Panel("Advection")
      .Doc("Where the step runs.")
      .Bind(&T::SetBackend, &T::GetBackend);
    t.Real("buoyancy", "Buoyancy", 1.0)
      .Between(-1e30, 1e30)
      .Units("model units / s² per degree")
      .Panel("Forces")
      .Doc("Upward acceleration per unit of temperature above ambient (Harris' sigma).")
      .Bind(&T::SetBuoyancy, &T::GetBuoyancy);
    t.Real("smoke_weight", "SmokeWeight", 0.05)
      .Between(-1e30, 1e30)
      .Units("model units / s² per unit density")
      .Panel("Forces")
      .Doc("Downward acceleration per unit of smoke density (Harris' kappa).")
      .Bind(&T::SetSmokeWeight, &T::GetSmokeWeight);
    t.Real("ambient_temperature", "AmbientTemperature", 0.0)
      .Between(-1e30, 1e30)
      .Panel("Forces")
      .Doc("Temperature of the resting air: the initial temperature and buoyancy's reference.")
      .Bind(&T::SetAmbientTemperature, &T::GetAmbientTemperature);
    t.Vector3("up", "Up", { 0, 0, 1 })
      .Panel("Forces")
      .Doc("Direction buoyancy acts along (normalised; 2D grids use +y if it has no x-y part).")
      .Bind(&T::SetUp, &T::GetUp);
    t.Real("vorticity_confinement", "VorticityConfinement", 0.0)
      .Between(0.0, 1e6)
      .Panel("Forces")
      .Doc("Strength epsilon of vorticity confinement (Fedkiw et al. 2001), which puts back the small swirls "
           "numerical diffusion removes; 0 = off (the seed).")
      .Bind(&T::SetVorticityConfinement, &T::GetVorticityConfinement);
    t.Real("density_dissipation", "DensityDissipation", 0.0)
      .Between(0.0, 1e6)
      .Units("1/s")
      .Panel("Dissipation")
      .Doc("Decay rate of the smoke density (density *= exp(-rate * dt) each step).")
      .Bind(&T::SetDensityDissipation, &T::GetDensityDissipation);
    t.Real("temperature_dissipation", "TemperatureDissipation", 0.0)
      .Between(0.0, 1e6)
      .Units("1/s")
      .Panel("Dissipation")
      .Doc("Decay rate of the temperature towards ambient.")
      .Bind(&T::SetTemperatureDissipation, &T::GetTemperatureDissipation);
    t.Real("velocity_dissipation", "VelocityDissipation", 0.0)
      .Between(0.0, 1e6)
      .Units("1/s")
      .Panel("Dissipation")
      .Doc("Decay rate of the velocity.")
      .Bind(&T::SetVelocityDissipation, &T::GetVelocityDissipation);
    t.Boolean("conserve_mass", "ConserveMass", false)
      .Panel("Advection")
      .Doc("Scale the density after advection so that the smoke's total stays what it was (times the "
           "dissipation's decay): semi-Lagrangian and MacCormack advection are not conservative. Closed domains "
           "only (no open sides).")
      .Bind(&T::SetConserveMass, &T::GetConserveMass);
    t.Text("open_faces", "OpenFaces", "")
      .Panel("Boundaries")
      .Doc("Open domain sides (free outflow), e.g. \"zmax\" or \"xmin,xmax,zmax\" (names xmin xmax ymin ymax "
           "zmin zmax, or all); the others are closed walls.")
      .Bind(&T::SetOpenFaces, &T::GetOpenFaces);
    t.Text("obstacle_array", "ObstacleArrayName", "obstacle")
      .Panel("Boundaries")
      .Advanced()
      .Doc("Point array of the optional input image marking solid cells (> 0.5).")
      .Bind(&T::SetObstacleArrayName, &T::GetObstacleArrayName);
    t.Text("velocity_array", "VelocityArrayName", "")
      .Panel("Boundaries")
      .Doc("Point array (3 components) of the optional velocity image on input port 1, in which smoke is "
           "released passively (the velocity does not evolve); \"\" = its active vectors.")
      .Bind(&T::SetVelocityArrayName, &T::GetVelocityArrayName);
    t.Real("velocity_time_offset", "VelocityTimeOffset", 0.0)
      .Between(-1e30, 1e30)
      .Units("s")
      .Panel("Boundaries")
      .Doc("For a velocity time series: the flow's time at simulation time 0 (the smoke at time t moves with "
           "the flow of time t + offset, linear between written times).")
      .Bind(&T::SetVelocityTimeOffset, &T::GetVelocityTimeOffset);
    t.Boolean("project_velocity", "ProjectExternalVelocity", true)
      .Panel("Boundaries")
      .Advanced()
      .Doc("Project the given velocity once (remove the divergence its resampling leaves, make walls and "
           "obstacles tight).")
      .Bind(&T::SetProjectExternalVelocity, &T::GetProjectExternalVelocity);
    t.Text("source_rate_array", "SourceRateArrayName", "rate")
      .Panel("Sources")
      .Doc("Point array of the source points (input port 2) giving each point's smoke mass rate (density x "
           "volume per second); points without it use source_rate.")
      .Bind(&T::SetSourceRateArrayName, &T::GetSourceRateArrayName);
    t.Text("source_temperature_array", "SourceTemperatureArrayName", "temperature")
      .Panel("Sources")
      .Doc("Point array of the source points giving the temperature set around each point; points without it "
           "use source_temperature.")
      .Bind(&T::SetSourceTemperatureArrayName, &T::GetSourceTemperatureArrayName);
    t.Text("source_radius_array", "SourceRadiusArrayName", "radius")
      .Panel("Sources")
      .Doc("Point array of the source points giving each point's radius; points without it use source_radius.")
      .Bind(&T::SetSourceRadiusArrayName, &T::GetSourceRadiusArrayName);
    t.Text("source_velocity_array", "SourceVelocityArrayName", "velocity")
      .Panel("Sources")
      .Doc("Point array (3 components) of the source points giving the velocity injected around each point; "
           "points without it inject none.")
      .Bind(&T::SetSourceVelocityArrayName, &T::GetSourceVelocityArrayName);
    t.Real("source_rate", "SourceRate", 1.0)
      .Between(0.0, 1e30)
      .Units("density x model units^3 / s")
      .Panel("Sources")
      .Doc("Smoke mass per second each source point injects (spread over the fluid cells within its radius) "
           "when the points have no rate array.")
      .Bind(&T::SetSourceRate, &T::GetSourceRate);
    t.Real("source_temperature", "SourceTemperature", 1.0)
      .Between(-1e30, 1e30)
      .Panel("Sources")
      .Doc("Temperature set around each source point when the points have no temperature array.")
      .Bind(&T::SetSourceTemperature, &T::GetSourceTemperature);
    t.Real("source_radius", "SourceRadius", 0.0)
      .Between(0.0, 1e30)
      .Units("model units")
      .Panel("Sources")
      .Doc("Radius of each source point when the points have no radius array; 0 = the cell holding the point.")
      .Bind(&T::SetSourceRadius, &T::GetSourceRadius);
    // the pressure solve's parameters are declared once, by vtkPlumePressureSolver
    t.Include(vtkPlumePressureSolver::GetParameterTable(),
      [](vtkObject* o) -> vtkObject* { return static_cast<T*>(o)->GetPressureSolver(); }, "Pressure");
    return t;
  }();
  return table;
}

//------------------------------------------------------------------------------
vtkPlumeSmokeSolver::vtkPlumeSmokeSolver()
  : Pressure(vtkSmartPointer<vtkPlumePressureSolver>::New())
  , LastRequestedTime(std::numeric_limits<double>::quiet_NaN())
{
  this->HeldVelocityTime = std::numeric_limits<double>::quiet_NaN();
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(1);
  GetParameterTable().ApplyDefaults(this);
}

//------------------------------------------------------------------------------
class vtkPlumeSmokeSolver::GPUBackend
{
public:
  plume::smoke::SmokeGPU Engine;
  vtkWeakPointer<vtkRenderWindow> Window; // the user's, or none (not owned: see SetRenderWindow)
  unsigned long WindowObserver = 0;       // its DeleteEvent
  vtkSmartPointer<vtkPlumeTextureHandOver> DensityHandOver;
  vtkSmartPointer<vtkPlumeTextureHandOver> VelocityHandOver;
};

vtkPlumeSmokeSolver::~vtkPlumeSmokeSolver()
{
  if (this->GPU && this->GPU->Window)
  {
    this->GPU->Window->RemoveObserver(this->GPU->WindowObserver);
  }
  delete this->GPU;
}

void vtkPlumeSmokeSolver::OnRenderWindowDeleted()
{
  // the window is still whole here: read the state back into the CPU arrays
  // and free the textures in its context; later GPU steps use an own window
  this->ReleaseGraphicsResources();
  this->GPU->Window = nullptr;
  this->GPU->WindowObserver = 0;
}

void vtkPlumeSmokeSolver::SetRenderWindow(vtkRenderWindow* window)
{
  if (!this->GPU)
  {
    this->GPU = new GPUBackend;
  }
  if (this->GPU->Window != window)
  {
    this->SyncFromGPU(); // the state moves to the new context through the CPU
    this->RevokeHandOvers();
    this->GPU->Engine.Release();
    this->InvalidateGPUState();
    if (this->GPU->Window)
    {
      this->GPU->Window->RemoveObserver(this->GPU->WindowObserver);
      this->GPU->WindowObserver = 0;
    }
    this->GPU->Window = window;
    if (window)
    {
      this->GPU->WindowObserver =
        window->AddObserver(vtkCommand::DeleteEvent, this, &vtkPlumeSmokeSolver::OnRenderWindowDeleted);
    }
    this->Modified();
  }
}

vtkRenderWindow* vtkPlumeSmokeSolver::GetRenderWindow()
{
  return this->GPU ? this->GPU->Window.Get() : nullptr;
}

void vtkPlumeSmokeSolver::ReleaseGraphicsResources()
{
  if (!this->GPU)
  {
    return;
  }
  this->SyncFromGPU();
  this->RevokeHandOvers();
  this->GPU->Engine.Release();
  this->InvalidateGPUState();
}

void vtkPlumeSmokeSolver::RevokeHandOvers()
{
  if (!this->GPU)
  {
    return;
  }
  for (auto* handOver : { &this->GPU->DensityHandOver, &this->GPU->VelocityHandOver })
  {
    if (*handOver)
    {
      (*handOver)->Revoke();
      *handOver = nullptr;
    }
  }
}

void vtkPlumeSmokeSolver::InvalidateGPUState()
{
  this->GPUHoldsState = false;
  this->GPUUpToDate = false;
  this->RevokeHandOvers();
}

bool vtkPlumeSmokeSolver::SyncFromGPU()
{
  if (!this->GPUHoldsState || !this->GPU)
  {
    return true;
  }
  std::string error;
  if (!this->GPU->Engine.Download(this->U, this->Density, this->Temperature, this->Q, error))
  {
    this->LastError = "smoke solver (GPU backend): " + error;
    this->InvalidateGPUState();
    return false;
  }
  this->GPUHoldsState = false;
  if (std::none_of(this->Open, this->Open + 6, [](bool o) { return o; }))
  {
    // the CPU solve's last act in a closed box: the pressure's mean over the
    // cells of the system (fluid cells with a fluid neighbour) is zero
    const int* n = this->Cells;
    auto inSystem = [&](int i, int j, int k) {
      const int idx[3] = { i, j, k };
      const size_t c = i + size_t(n[0]) * (j + size_t(n[1]) * k);
      if (this->Solid[c])
      {
        return false;
      }
      const size_t stride[3] = { 1, size_t(n[0]), size_t(n[0]) * n[1] };
      for (int d = 0; d < 3; ++d)
      {
        if ((idx[d] > 0 && !this->Solid[c - stride[d]]) || (idx[d] < n[d] - 1 && !this->Solid[c + stride[d]]))
        {
          return true;
        }
      }
      return false;
    };
    double sum = 0;
    size_t count = 0;
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i)
          if (inSystem(i, j, k))
          {
            sum += this->Q[i + size_t(n[0]) * (j + size_t(n[1]) * k)];
            ++count;
          }
    const double mean = count ? sum / double(count) : 0.0;
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i)
        {
          double& q = this->Q[i + size_t(n[0]) * (j + size_t(n[1]) * k)];
          q = inSystem(i, j, k) ? q - mean : 0.0;
        }
  }
  return true;
}

std::string vtkPlumeSmokeSolver::GPUUnsupported()
{
  if (this->AdvectionScheme != SEMI_LAGRANGIAN)
  {
    return "advection 'maccormack'";
  }
  if (this->VorticityConfinement > 0)
  {
    return "vorticity_confinement " + Text(this->VorticityConfinement);
  }
  if (this->ConserveMass && std::none_of(this->Open, this->Open + 6, [](bool o) { return o; }))
  {
    return "conserve_mass";
  }
  if (this->HasMovingObstacles())
  {
    return "moving obstacles";
  }
  if (this->HasExternalVelocity())
  {
    return "a velocity on input port 1";
  }
  if (this->GetNumberOfInputConnections(2) > 0)
  {
    return "source points on input port 2";
  }
  if (int(this->Sources.size()) > plume::smoke::SmokeGPU::MaxSources)
  {
    return std::to_string(this->Sources.size()) + " sources (at most " +
      std::to_string(plume::smoke::SmokeGPU::MaxSources) + ")";
  }
  return "";
}

bool vtkPlumeSmokeSolver::AdvanceGPU(double dt)
{
  const std::string unsupported = this->GPUUnsupported();
  if (!unsupported.empty())
  {
    this->LastError = "smoke solver: the GPU backend does not support " + unsupported + " (use backend 'cpu')";
    return false;
  }
  if (!this->GPU)
  {
    this->GPU = new GPUBackend;
  }
  this->RevokeHandOvers(); // the textures are about to be overwritten
  std::string error;
  if (!this->GPUUpToDate)
  {
    plume::smoke::GPUGrid grid;
    std::copy(this->Cells, this->Cells + 3, grid.Cells);
    std::copy(this->H, this->H + 3, grid.H);
    std::copy(this->Open, this->Open + 6, grid.Open);
    if (!this->GPU->Engine.Upload(
          this->GPU->Window, grid, this->U, this->Density, this->Temperature, this->Solid, error))
    {
      this->LastError = "smoke solver (GPU backend): " + error;
      return false;
    }
    this->GPUUpToDate = true;
    this->GPUHoldsState = false;
    this->GPUSourcesReady = false; // a new upload (grid, solid cells): the masks again
  }
  plume::smoke::GPUStepSettings settings;
  settings.Dt = dt;
  settings.DensityDecay = std::exp(-this->DensityDissipation * dt);
  settings.TemperatureDecay = std::exp(-this->TemperatureDissipation * dt);
  settings.VelocityDecay = std::exp(-this->VelocityDissipation * dt);
  settings.Ambient = this->AmbientTemperature;
  settings.Buoyancy = this->Buoyancy;
  settings.SmokeWeight = this->SmokeWeight;
  // the CPU's ApplyBuoyancy: along Up, normalised; a 2D grid's up lies in x-y (+y if none)
  glm::dvec3 up(this->Up[0], this->Up[1], this->Up[2]);
  if (this->Cells[2] == 1)
  {
    up.z = 0;
    if (glm::length(up) == 0)
    {
      up = glm::dvec3(0, 1, 0);
    }
  }
  up = glm::length(up) > 0 ? glm::normalize(up) : glm::dvec3(0.0);
  for (int a = 0; a < 3; ++a)
  {
    settings.Up[a] = up[a];
  }
  std::vector<double> sourceSignature;
  for (const Source& src : this->Sources)
  {
    plume::smoke::GPUSource g;
    for (int a = 0; a < 3; ++a)
    {
      g.Velocity[a] = src.Velocity[a];
      sourceSignature.push_back(src.Center[a]);
      sourceSignature.push_back(src.Velocity[a] != 0 ? 1 : 0);
    }
    sourceSignature.push_back(src.Radius);
    g.Density = src.Density;
    g.Temperature = src.Temperature;
    settings.Sources.push_back(g);
  }
  if (!this->GPUSourcesReady || sourceSignature != this->GPUSourceSignature)
  {
    // where each source acts, decided here by the CPU backend's own test (in
    // double: a cell at exactly the radius is in or out as on the CPU); the
    // last source covering a texel wins, as ApplySources' order gives
    const int* n = this->Cells;
    std::vector<float> cells, faces[3];
    for (size_t s = 0; s < this->Sources.size(); ++s)
    {
      const Source& src = this->Sources[s];
      if (cells.empty())
      {
        cells.assign(this->Solid.size(), 0.0f);
      }
      ForRows(n, [&](int j, int k) {
        for (int i = 0; i < n[0]; ++i)
        {
          if (this->SourceCoversCell(src, i, j, k))
          {
            cells[i + size_t(n[0]) * (j + size_t(n[1]) * k)] = float(s + 1);
          }
        }
      });
      if (src.Velocity[0] == 0 && src.Velocity[1] == 0 && src.Velocity[2] == 0)
      {
        continue;
      }
      for (int d = 0; d < 3; ++d)
      {
        int m[3] = { n[0], n[1], n[2] };
        ++m[d];
        if (faces[d].empty())
        {
          faces[d].assign(size_t(m[0]) * m[1] * m[2], 0.0f);
        }
        ForRows(m, [&](int j, int k) {
          for (int i = 0; i < m[0]; ++i)
          {
            if (this->SourceCoversFace(src, d, i, j, k))
            {
              faces[d][i + size_t(m[0]) * (j + size_t(m[1]) * k)] = float(s + 1);
            }
          }
        });
      }
    }
    if (!this->GPU->Engine.SetSourceMasks(cells, faces, error))
    {
      this->LastError = "smoke solver (GPU backend): " + error;
      return false;
    }
    this->GPUSourceSignature = sourceSignature;
    this->GPUSourcesReady = true;
  }
  settings.JacobiIterations = this->Pressure->GetMaximumIterations();
  settings.JacobiWeight = this->Pressure->GetJacobiWeight();
  if (!this->GPU->Engine.Step(settings, error))
  {
    this->LastError = "smoke solver (GPU backend): " + error;
    this->InvalidateGPUState();
    return false;
  }
  this->LastGPUPassCount = this->GPU->Engine.GetLastPassCount();
  this->GPUHoldsState = true;
  this->LastProjectionDt = dt;
  this->SimulationTime += dt;
  ++this->CurrentStep;
  ++this->StepsTaken;
  this->Modified();
  return true;
}

void vtkPlumeSmokeSolver::FinishGPU()
{
  if (this->GPU)
  {
    this->GPU->Engine.Finish();
  }
}

bool vtkPlumeSmokeSolver::RunTrivialGPUPasses(int passes)
{
  std::string error;
  if (!this->GPU || !this->GPUUpToDate || !this->GPU->Engine.TrivialPasses(passes, error))
  {
    this->LastError = "smoke solver (GPU backend): " + (error.empty() ? std::string("no GPU state (step first)") : error);
    return false;
  }
  return true;
}

int vtkPlumeSmokeSolver::FillInputPortInformation(int port, vtkInformation* info)
{
  // ports 0 (obstacles) and 1 (velocity) are images, port 2 the source points
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 2 ? "vtkPointSet" : "vtkImageData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

vtkExecutive* vtkPlumeSmokeSolver::CreateDefaultExecutive()
{
  return plume::NewQuietExecutive(); // RequestData reports the one error itself
}

//------------------------------------------------------------------------------
vtkPlumePressureSolver* vtkPlumeSmokeSolver::GetPressureSolver()
{
  return this->Pressure;
}

void vtkPlumeSmokeSolver::SetPressureMethod(int method)
{
  if (method != this->Pressure->GetMethod())
  {
    this->Pressure->SetMethod(method);
    this->Modified();
  }
}
int vtkPlumeSmokeSolver::GetPressureMethod()
{
  return this->Pressure->GetMethod();
}
void vtkPlumeSmokeSolver::SetPressureTolerance(double tolerance)
{
  if (tolerance != this->Pressure->GetTolerance())
  {
    this->Pressure->SetTolerance(tolerance);
    this->Modified();
  }
}
double vtkPlumeSmokeSolver::GetPressureTolerance()
{
  return this->Pressure->GetTolerance();
}
void vtkPlumeSmokeSolver::SetPressureMaximumIterations(int iterations)
{
  if (iterations != this->Pressure->GetMaximumIterations())
  {
    this->Pressure->SetMaximumIterations(iterations);
    this->Modified();
  }
}
int vtkPlumeSmokeSolver::GetPressureMaximumIterations()
{
  return this->Pressure->GetMaximumIterations();
}
void vtkPlumeSmokeSolver::SetPressureJacobiWeight(double weight)
{
  if (weight != this->Pressure->GetJacobiWeight())
  {
    this->Pressure->SetJacobiWeight(weight);
    this->Modified();
  }
}
double vtkPlumeSmokeSolver::GetPressureJacobiWeight()
{
  return this->Pressure->GetJacobiWeight();
}
void vtkPlumeSmokeSolver::SetPressureSmoothingSweeps(int sweeps)
{
  if (sweeps != this->Pressure->GetSmoothingSweeps())
  {
    this->Pressure->SetSmoothingSweeps(sweeps);
    this->Modified();
  }
}
int vtkPlumeSmokeSolver::GetPressureSmoothingSweeps()
{
  return this->Pressure->GetSmoothingSweeps();
}

//------------------------------------------------------------------------------
void vtkPlumeSmokeSolver::AddSource(
  const double center[3], double radius, double density, double temperature, const double velocity[3])
{
  Source s;
  std::copy(center, center + 3, s.Center);
  s.Radius = radius;
  s.Density = density;
  s.Temperature = temperature;
  std::copy(velocity, velocity + 3, s.Velocity);
  this->Sources.push_back(s);
  this->Modified();
}

void vtkPlumeSmokeSolver::RemoveAllSources()
{
  if (!this->Sources.empty())
  {
    this->Sources.clear();
    this->Modified();
  }
}

void vtkPlumeSmokeSolver::AddObstacleSphere(const double center[3], double radius, const double velocity[3])
{
  Obstacle o{ SPHERE, { center[0], center[1], center[2], radius, 0, 0 }, { 0, 0, 0 }, nullptr };
  if (velocity)
  {
    std::copy(velocity, velocity + 3, o.Velocity);
  }
  this->Obstacles.push_back(o);
  ++this->ObstacleVersion;
  this->Modified();
}

void vtkPlumeSmokeSolver::AddObstacleBox(const double bounds[6], const double velocity[3])
{
  Obstacle o{ BOX, { bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5] }, { 0, 0, 0 }, nullptr };
  if (velocity)
  {
    std::copy(velocity, velocity + 3, o.Velocity);
  }
  this->Obstacles.push_back(o);
  ++this->ObstacleVersion;
  this->Modified();
}

void vtkPlumeSmokeSolver::AddObstacleSurface(vtkPolyData* surface, const double velocity[3])
{
  Obstacle o{ SURFACE, { 0, 0, 0, 0, 0, 0 }, { 0, 0, 0 }, vtkSmartPointer<vtkPolyData>::New() };
  if (surface)
  {
    o.Surface->DeepCopy(surface); // later edits of the caller's surface do not move it
  }
  else
  {
    o.Surface = nullptr; // refused by Validate()
  }
  if (velocity)
  {
    std::copy(velocity, velocity + 3, o.Velocity);
  }
  this->Obstacles.push_back(o);
  ++this->ObstacleVersion;
  this->Modified();
}

bool vtkPlumeSmokeSolver::HasMovingObstacles() const
{
  return std::any_of(this->Obstacles.begin(), this->Obstacles.end(),
    [](const Obstacle& o) { return o.Velocity[0] != 0 || o.Velocity[1] != 0 || o.Velocity[2] != 0; });
}

void vtkPlumeSmokeSolver::RemoveAllObstacles()
{
  if (!this->Obstacles.empty())
  {
    this->Obstacles.clear();
    ++this->ObstacleVersion;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
std::string vtkPlumeSmokeSolver::Validate() const
{
  const char* axes = "xyz";
  for (int a = 0; a < 3; ++a)
  {
    const int minimum = a < 2 ? 2 : 1;
    if (this->Dimensions[a] < minimum)
    {
      return std::string("smoke solver: dimensions along ") + axes[a] + " must be at least " +
        std::to_string(minimum) + ", got " + std::to_string(this->Dimensions[a]);
    }
    if (!(this->Spacing[a] > 0) || !std::isfinite(this->Spacing[a]))
    {
      return std::string("smoke solver: spacing along ") + axes[a] + " must be positive and finite, got " +
        Text(this->Spacing[a]);
    }
    if (!std::isfinite(this->Origin[a]))
    {
      return std::string("smoke solver: origin along ") + axes[a] + " must be finite, got " + Text(this->Origin[a]);
    }
  }
  // Memory: about 384 bytes a cell (velocity and its advected copy, scalars
  // and theirs, pressure, right-hand side, hypre's matrix and multigrid
  // hierarchy; measured peaks: 697 MB at 128^3 = 332 B, 6.0 GB at 256^3 =
  // 360 B). Refused above half the RAM.
  const double bytesPerCell = 384.0;
  const double cells = double(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2];
#if defined(_SC_PHYS_PAGES) && defined(_SC_PAGE_SIZE)
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
#else
  const long pages = 0, pageSize = 0; // unknown: assume 8 GB of RAM
#endif
  const double budget = pages > 0 && pageSize > 0 ? 0.5 * double(pages) * double(pageSize) : 4.0 * (1 << 30);
  if (cells * bytesPerCell > budget)
  {
    return "smoke solver: " + Text(cells) + " cells need about " + Text(std::ceil(cells * bytesPerCell / (1 << 20))) +
      " MB, more than half the memory (" + Text(std::floor(budget / (1 << 20))) + " MB)";
  }
  if (!(this->TimeStep > 0) || !std::isfinite(this->TimeStep))
  {
    return "smoke solver: time_step must be positive and finite, got " + Text(this->TimeStep);
  }
  for (double v : { this->Buoyancy, this->SmokeWeight, this->AmbientTemperature, this->Up[0], this->Up[1],
         this->Up[2] })
  {
    if (!std::isfinite(v))
    {
      return "smoke solver: buoyancy, smoke_weight, ambient_temperature and up must be finite, got " + Text(v);
    }
  }
  bool open[6];
  const std::string bad = ParseOpenFaces(this->OpenFaces, open);
  if (!bad.empty())
  {
    return "smoke solver: open_faces: unknown side '" + bad + "' in '" + this->OpenFaces +
      "' (names: xmin xmax ymin ymax zmin zmax all)";
  }
  for (size_t s = 0; s < this->Sources.size(); ++s)
  {
    const Source& src = this->Sources[s];
    const double values[] = { src.Center[0], src.Center[1], src.Center[2], src.Radius, src.Density,
      src.Temperature, src.Velocity[0], src.Velocity[1], src.Velocity[2] };
    for (double v : values)
    {
      if (!std::isfinite(v))
      {
        return "smoke solver: source " + std::to_string(s) + " has a non-finite value (" + Text(v) + ")";
      }
    }
    if (src.Radius < 0)
    {
      return "smoke solver: source " + std::to_string(s) + " has a negative radius (" + Text(src.Radius) + ")";
    }
  }
  for (size_t o = 0; o < this->Obstacles.size(); ++o)
  {
    const Obstacle& ob = this->Obstacles[o];
    for (double v : { ob.Values[0], ob.Values[1], ob.Values[2], ob.Values[3], ob.Values[4], ob.Values[5],
           ob.Velocity[0], ob.Velocity[1], ob.Velocity[2] })
    {
      if (!std::isfinite(v))
      {
        return "smoke solver: obstacle " + std::to_string(o) + " has a non-finite value (" + Text(v) + ")";
      }
    }
    if (ob.Kind == SURFACE && (!ob.Surface || ob.Surface->GetNumberOfPolys() + ob.Surface->GetNumberOfStrips() == 0))
    {
      return "smoke solver: obstacle " + std::to_string(o) + " is a surface without polygons (" +
        std::to_string(ob.Surface ? ob.Surface->GetNumberOfPolys() : 0) + ")";
    }
    if (ob.Kind == SURFACE)
    {
      double bounds[6];
      ob.Surface->GetBounds(bounds);
      for (double b : bounds)
      {
        if (!std::isfinite(b))
        {
          return "smoke solver: obstacle " + std::to_string(o) + " is a surface with a non-finite point (" +
            Text(b) + ")";
        }
      }
    }
  }
  return "";
}

//------------------------------------------------------------------------------
bool vtkPlumeSmokeSolver::EnsureState()
{
  this->LastError = this->Validate();
  if (!this->LastError.empty())
  {
    return false;
  }
  std::vector<double> signature = { double(this->Dimensions[0]), double(this->Dimensions[1]),
    double(this->Dimensions[2]), this->Origin[0], this->Origin[1], this->Origin[2], this->Spacing[0],
    this->Spacing[1], this->Spacing[2], double(this->ObstacleVersion) };
  bool open[6];
  ParseOpenFaces(this->OpenFaces, open);
  if (this->Dimensions[2] == 1)
  {
    open[4] = open[5] = false;
  }
  for (bool o : open)
  {
    signature.push_back(o ? 1 : 0);
  }
  vtkDataArray* mask = nullptr;
  if (this->ObstacleInput)
  {
    mask = this->ObstacleInput->GetPointData()->GetArray(this->ObstacleArrayName.c_str());
    if (!mask)
    {
      this->LastError = "smoke solver: the input image has no point array '" + this->ObstacleArrayName +
        "' (obstacle_array)";
      return false;
    }
    signature.push_back(double(this->ObstacleInput->GetMTime()));
    signature.push_back(double(mask->GetMTime()));
    signature.push_back(double(reinterpret_cast<uintptr_t>(mask)));
  }
  vtkDataArray* external = nullptr;
  vtkDataArray* valid = nullptr;
  if (this->VelocityInput)
  {
    external = this->VelocityArrayName.empty() ? this->VelocityInput->GetPointData()->GetVectors()
                                               : this->VelocityInput->GetPointData()->GetArray(this->VelocityArrayName.c_str());
    if (!external || external->GetNumberOfComponents() != 3)
    {
      this->LastError = "smoke solver: the velocity image has no 3-component point array '" +
        (this->VelocityArrayName.empty() ? std::string("(active vectors)") : this->VelocityArrayName) +
        "' (velocity_array)";
      return false;
    }
    valid = this->VelocityInput->GetPointData()->GetArray("vtkValidPointMask");
    if (this->IsVelocityTimeSeries())
    {
      // the input's data changes with every written time fetched: a new
      // simulation only when the series (its algorithm or its times) does
      vtkAlgorithm* upstream = this->GetNumberOfInputConnections(1) > 0 ? this->GetInputAlgorithm(1, 0) : nullptr;
      signature.push_back(double(reinterpret_cast<uintptr_t>(upstream)));
      signature.push_back(upstream ? double(upstream->GetMTime()) : 0.0);
      signature.insert(signature.end(), this->VelocityTimes.begin(), this->VelocityTimes.end());
      signature.push_back(this->VelocityTimeOffset);
    }
    else
    {
      signature.push_back(double(this->VelocityInput->GetMTime()));
      signature.push_back(double(external->GetMTime()));
      signature.push_back(double(reinterpret_cast<uintptr_t>(external)));
    }
  }
  if (signature == this->Signature)
  {
    return true;
  }

  // (Re)allocate: a new simulation.
  std::copy(this->Dimensions, this->Dimensions + 3, this->Cells);
  std::copy(this->Spacing, this->Spacing + 3, this->H);
  std::copy(this->Origin, this->Origin + 3, this->O);
  std::copy(open, open + 6, this->Open);
  const int* n = this->Cells;
  const size_t count = size_t(n[0]) * n[1] * n[2];
  // the input images' solid cells (static); the obstacles are added by VoxeliseObstacles
  this->StaticSolid.assign(count, 0);
  ForRows(n, [&](int j, int k) {
    for (int i = 0; i < n[0]; ++i)
    {
      const glm::dvec3 p(this->O[0] + i * this->H[0], this->O[1] + j * this->H[1], this->O[2] + k * this->H[2]);
      bool solid = false;
      if (!solid && valid)
      {
        // points a resampled CFD field marks as outside its mesh are solid
        const vtkIdType id = NearestPoint(this->VelocityInput, p);
        solid = id >= 0 && valid->GetComponent(id, 0) == 0;
      }
      if (!solid && mask)
      {
        // nearest input point, if inside the input image
        const double* io = this->ObstacleInput->GetOrigin();
        const double* is = this->ObstacleInput->GetSpacing();
        const int* ext = this->ObstacleInput->GetExtent();
        int idx[3];
        bool inside = true;
        for (int a = 0; a < 3; ++a)
        {
          const double g = is[a] != 0 ? (p[a] - io[a]) / is[a] : 0.0;
          idx[a] = int(std::lround(g));
          inside = inside && idx[a] >= ext[2 * a] && idx[a] <= ext[2 * a + 1];
        }
        if (inside)
        {
          const vtkIdType id = this->ObstacleInput->ComputePointId(idx);
          solid = mask->GetComponent(id, 0) > 0.5;
        }
      }
      this->StaticSolid[i + size_t(n[0]) * (j + size_t(n[1]) * k)] = solid ? 1 : 0;
    }
  });
  if (!this->VoxeliseObstacles(0.0))
  {
    this->Signature.clear();
    return false;
  }
  if (std::all_of(this->Solid.begin(), this->Solid.end(), [](unsigned char s) { return s != 0; }))
  {
    this->LastError = "smoke solver: the obstacles cover every one of the " + std::to_string(count) +
      " cells: there is no fluid to simulate";
    this->Signature.clear();
    return false;
  }
  for (int d = 0; d < 3; ++d)
  {
    int m[3] = { n[0], n[1], n[2] };
    ++m[d];
    this->U[d].assign(size_t(m[0]) * m[1] * m[2], 0.0);
  }
  this->Density.assign(count, 0.0);
  this->Temperature.assign(count, 0.0);
  this->Q.assign(count, 0.0);
  this->Pressure->SetProblem(this->Cells, this->H, this->Solid.data(), this->Open);
  for (auto& u : this->ExternalU)
  {
    u.clear();
  }
  for (VelocityFrame& frame : this->Frames)
  {
    frame.Index = -1;
  }
  if (external)
  {
    if (!this->SampleExternalVelocity(this->VelocityInput, external, this->ExternalU))
    {
      this->Signature.clear();
      return false;
    }
    if (this->IsVelocityTimeSeries())
    {
      // the frame the input holds now is kept (no second read of it)
      const double held = this->HeldVelocityTime;
      const auto at = std::find(this->VelocityTimes.begin(), this->VelocityTimes.end(), held);
      if (at != this->VelocityTimes.end())
      {
        this->Frames[0].Index = int(at - this->VelocityTimes.begin());
        for (int d = 0; d < 3; ++d)
        {
          this->Frames[0].U[d] = this->ExternalU[d];
        }
        ++this->NumberOfVelocityFramesRead;
      }
    }
  }
  this->Signature = signature;
  this->Reset();
  return true;
}

bool vtkPlumeSmokeSolver::VoxeliseObstacles(double t)
{
  const int* n = this->Cells;
  this->Solid = this->StaticSolid;
  this->SolidOwner.assign(this->Solid.size(), 0);
  for (size_t o = 0; o < this->Obstacles.size(); ++o)
  {
    const Obstacle& ob = this->Obstacles[o];
    const glm::dvec3 shift = t * glm::dvec3(ob.Velocity[0], ob.Velocity[1], ob.Velocity[2]);
    const int owner = int(o) + 1;
    auto mark = [&](size_t c) {
      this->Solid[c] = 1;
      this->SolidOwner[c] = owner; // the last obstacle listed wins where they overlap
    };
    if (ob.Kind == SURFACE)
    {
      // the surface at rest, tested at the cell centres moved back by the
      // shift (vtkSelectEnclosedPoints' ray casting; only the cells within
      // its bounds, serially: the test is not thread-safe)
      double bounds[6];
      ob.Surface->GetBounds(bounds);
      int lo[3], hi[3];
      for (int a = 0; a < 3; ++a)
      {
        lo[a] = std::max(0, int(std::floor((bounds[2 * a] + shift[a] - this->O[a]) / this->H[a])));
        hi[a] = std::min(n[a] - 1, int(std::ceil((bounds[2 * a + 1] + shift[a] - this->O[a]) / this->H[a])));
      }
      vtkNew<vtkSelectEnclosedPoints> enclosed;
      enclosed->SetTolerance(1e-6);
      enclosed->Initialize(ob.Surface);
      for (int k = lo[2]; k <= hi[2]; ++k)
        for (int j = lo[1]; j <= hi[1]; ++j)
          for (int i = lo[0]; i <= hi[0]; ++i)
          {
            double p[3] = { this->O[0] + i * this->H[0] - shift.x, this->O[1] + j * this->H[1] - shift.y,
              this->O[2] + k * this->H[2] - shift.z };
            if (enclosed->IsInsideSurface(p))
            {
              mark(i + size_t(n[0]) * (j + size_t(n[1]) * k));
            }
          }
      enclosed->Complete();
      continue;
    }
    ForRows(n, [&](int j, int k) {
      for (int i = 0; i < n[0]; ++i)
      {
        const glm::dvec3 p =
          glm::dvec3(this->O[0] + i * this->H[0], this->O[1] + j * this->H[1], this->O[2] + k * this->H[2]) - shift;
        const bool inside = ob.Kind == SPHERE
          ? glm::length(p - glm::dvec3(ob.Values[0], ob.Values[1], ob.Values[2])) <= ob.Values[3]
          : (p.x >= ob.Values[0] && p.x <= ob.Values[1] && p.y >= ob.Values[2] && p.y <= ob.Values[3] &&
              p.z >= ob.Values[4] && p.z <= ob.Values[5]);
        if (inside)
        {
          mark(i + size_t(n[0]) * (j + size_t(n[1]) * k));
        }
      }
    });
  }
  return true;
}

void vtkPlumeSmokeSolver::ApplyObstacleVelocity()
{
  const int* n = this->Cells;
  for (int d = 0; d < 3; ++d)
  {
    int m[3] = { n[0], n[1], n[2] };
    ++m[d];
    ForRows(m, [&](int j, int k) {
      for (int i = 0; i < m[0]; ++i)
      {
        if (!this->IsWallFace(d, i, j, k))
        {
          continue;
        }
        int idx[3] = { i, j, k };
        double value = 0;
        // a closed domain side stays 0; else the velocity of a moving neighbour's obstacle
        const bool side = (idx[d] == 0 && !this->Open[2 * d]) || (idx[d] == n[d] && !this->Open[2 * d + 1]);
        if (!side)
        {
          for (int s = 0; s < 2; ++s)
          {
            int c[3] = { idx[0], idx[1], idx[2] };
            c[d] -= s;
            if (c[d] < 0 || c[d] >= n[d])
            {
              continue;
            }
            const size_t cell = c[0] + size_t(n[0]) * (c[1] + size_t(n[1]) * c[2]);
            if (this->Solid[cell] && this->SolidOwner[cell] > 0)
            {
              value = this->Obstacles[size_t(this->SolidOwner[cell] - 1)].Velocity[d];
            }
          }
        }
        this->U[d][i + size_t(m[0]) * (j + size_t(m[1]) * k)] = value;
      }
    });
  }
}

bool vtkPlumeSmokeSolver::SampleExternalVelocity(
  vtkImageData* image, vtkDataArray* velocity, std::vector<double> faces[3])
{
  // Each face takes its component of the velocity image, trilinear between
  // the image's points (zero outside the image); walls stay zero. The field
  // is then projected once: resampling leaves some divergence, which would
  // make passive smoke gather or thin out.
  const int* n = this->Cells;
  const double* io = image->GetOrigin();
  const double* is = image->GetSpacing();
  const int* ext = image->GetExtent();
  for (int d = 0; d < 3; ++d)
  {
    int m[3] = { n[0], n[1], n[2] };
    ++m[d];
    this->U[d].assign(size_t(m[0]) * m[1] * m[2], 0.0);
    std::vector<double>& u = this->U[d];
    ForRows(m, [&](int j, int k) {
      for (int i = 0; i < m[0]; ++i)
      {
        if (this->IsWallFace(d, i, j, k))
        {
          continue;
        }
        glm::dvec3 x(this->O[0] + i * this->H[0], this->O[1] + j * this->H[1], this->O[2] + k * this->H[2]);
        x[d] -= 0.5 * this->H[d];
        int i0[3], i1[3];
        double t[3];
        bool inside = true;
        for (int a = 0; a < 3; ++a)
        {
          const double g = is[a] != 0 ? (x[a] - io[a]) / is[a] : double(ext[2 * a]);
          const double lo = ext[2 * a], hi = ext[2 * a + 1];
          inside = inside && g >= lo - 1e-9 && g <= hi + 1e-9;
          const double gc = std::min(std::max(g, lo), hi);
          i0[a] = std::min(int(std::floor(gc)), std::max(int(hi) - 1, int(lo)));
          i1[a] = std::min(i0[a] + 1, int(hi));
          t[a] = i1[a] > i0[a] ? gc - i0[a] : 0.0;
        }
        if (!inside)
        {
          continue;
        }
        double value = 0;
        for (int c = 0; c < 8; ++c)
        {
          int idx[3];
          double w = 1;
          for (int a = 0; a < 3; ++a)
          {
            const bool upper = (c >> a) & 1;
            idx[a] = upper ? i1[a] : i0[a];
            w *= upper ? t[a] : 1 - t[a];
          }
          if (w != 0)
          {
            value += w * velocity->GetComponent(image->ComputePointId(idx), d);
          }
        }
        u[i + size_t(m[0]) * (j + size_t(m[1]) * k)] = std::isfinite(value) ? value : 0.0;
      }
    });
  }
  if (this->ProjectExternalVelocity && !this->Project())
  {
    return false;
  }
  for (int d = 0; d < 3; ++d)
  {
    faces[d] = this->U[d];
  }
  std::fill(this->Q.begin(), this->Q.end(), 0.0);
  return true;
}

const vtkPlumeSmokeSolver::VelocityFrame* vtkPlumeSmokeSolver::GetVelocityFrame(int index, int keep)
{
  for (const VelocityFrame& frame : this->Frames)
  {
    if (frame.Index == index)
    {
      return &frame;
    }
  }
  VelocityFrame& slot = this->Frames[0].Index == keep ? this->Frames[1] : this->Frames[0];
  vtkAlgorithmOutput* connection =
    this->GetNumberOfInputConnections(1) > 0 ? this->GetInputConnection(1, 0) : nullptr;
  if (!connection || !connection->GetProducer())
  {
    this->LastError = "smoke solver: the velocity time series has no input connection to read time " +
      Text(this->VelocityTimes[size_t(index)]) + " from";
    return nullptr;
  }
  // An update of the upstream algorithm at that time: the pipeline asks our
  // input for one time per request, a step may need another one.
  vtkAlgorithm* upstream = connection->GetProducer();
  const int port = connection->GetIndex();
  const double time = this->VelocityTimes[size_t(index)];
  vtkNew<vtkInformationVector> requests;
  requests->SetNumberOfInformationObjects(port + 1);
  requests->GetInformationObject(port)->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), time);
  vtkImageData* image = upstream->Update(port, requests) ? vtkImageData::SafeDownCast(upstream->GetOutputDataObject(port)) : nullptr;
  vtkDataArray* velocity = !image ? nullptr
    : this->VelocityArrayName.empty() ? image->GetPointData()->GetVectors()
                                      : image->GetPointData()->GetArray(this->VelocityArrayName.c_str());
  if (!velocity || velocity->GetNumberOfComponents() != 3)
  {
    this->LastError = "smoke solver: the velocity time series gave no image with a 3-component point array '" +
      (this->VelocityArrayName.empty() ? std::string("(active vectors)") : this->VelocityArrayName) +
      "' at time " + Text(time);
    return nullptr;
  }
  this->HeldVelocityTime = time;
  // sampling projects through U and Q: keep the state
  std::vector<double> saved[3];
  for (int d = 0; d < 3; ++d)
  {
    saved[d] = this->U[d];
  }
  const std::vector<double> savedQ = this->Q;
  const bool ok = this->SampleExternalVelocity(image, velocity, slot.U);
  for (int d = 0; d < 3; ++d)
  {
    this->U[d].swap(saved[d]);
  }
  this->Q = savedQ;
  if (!ok)
  {
    slot.Index = -1;
    return nullptr;
  }
  slot.Index = index;
  ++this->NumberOfVelocityFramesRead;
  return &slot;
}

bool vtkPlumeSmokeSolver::SetVelocityAtTime(double t)
{
  const std::vector<double>& times = this->VelocityTimes;
  const double flowTime = t + this->VelocityTimeOffset;
  // the written times around flowTime (held before the first, after the last)
  const auto upper = std::upper_bound(times.begin(), times.end(), flowTime);
  int hi = int(upper - times.begin());
  int lo = hi - 1;
  double w = 0;
  if (lo < 0)
  {
    lo = hi = 0;
  }
  else if (hi >= int(times.size()))
  {
    hi = lo = int(times.size()) - 1;
  }
  else
  {
    w = (flowTime - times[size_t(lo)]) / (times[size_t(hi)] - times[size_t(lo)]);
  }
  const VelocityFrame* a = this->GetVelocityFrame(lo, hi);
  const VelocityFrame* b = a ? this->GetVelocityFrame(hi, lo) : nullptr;
  if (!a || !b)
  {
    return false;
  }
  for (int d = 0; d < 3; ++d)
  {
    std::vector<double>& u = this->U[d];
    const std::vector<double>& ua = a->U[d];
    const std::vector<double>& ub = b->U[d];
    vtkSMPTools::For(0, vtkIdType(u.size()), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType f = begin; f < end; ++f)
      {
        u[f] = (1 - w) * ua[f] + w * ub[f];
      }
    });
    this->ExternalU[d] = u;
  }
  return true;
}

void vtkPlumeSmokeSolver::Reset()
{
  for (int d = 0; d < 3; ++d)
  {
    if (this->ExternalU[d].size() == this->U[d].size())
    {
      this->U[d] = this->ExternalU[d]; // passive smoke: the given field
    }
    else
    {
      std::fill(this->U[d].begin(), this->U[d].end(), 0.0);
    }
  }
  if (this->IsVelocityTimeSeries() && this->HasExternalVelocity())
  {
    this->SetVelocityAtTime(0.0); // a failure shows at the next step
  }
  if (this->HasMovingObstacles() && !this->HasExternalVelocity() && !this->StaticSolid.empty())
  {
    this->VoxeliseObstacles(0.0);
    this->Pressure->SetProblem(this->Cells, this->H, this->Solid.data(), this->Open);
    this->ApplyObstacleVelocity();
  }
  std::fill(this->Density.begin(), this->Density.end(), 0.0);
  std::fill(this->Temperature.begin(), this->Temperature.end(), this->AmbientTemperature);
  std::fill(this->Q.begin(), this->Q.end(), 0.0);
  this->InvalidateGPUState();
  this->LastProjectionDt = 0;
  this->SimulationTime = 0;
  this->CurrentStep = 0;
  this->LastRequestedTime = std::numeric_limits<double>::quiet_NaN();
  this->Modified();
}

bool vtkPlumeSmokeSolver::Initialize()
{
  return this->EnsureState();
}

double* vtkPlumeSmokeSolver::GetFaceVelocityData(int axis)
{
  // writable: the caller may change the state, which the GPU then uploads again
  this->SyncFromGPU();
  this->InvalidateGPUState();
  return axis >= 0 && axis < 3 && !this->U[axis].empty() ? this->U[axis].data() : nullptr;
}
double* vtkPlumeSmokeSolver::GetDensityData()
{
  // writable: the caller may change the state, which the GPU then uploads again
  this->SyncFromGPU();
  this->InvalidateGPUState();
  return this->Density.empty() ? nullptr : this->Density.data();
}
double* vtkPlumeSmokeSolver::GetTemperatureData()
{
  // writable: the caller may change the state, which the GPU then uploads again
  this->SyncFromGPU();
  this->InvalidateGPUState();
  return this->Temperature.empty() ? nullptr : this->Temperature.data();
}
double* vtkPlumeSmokeSolver::GetPressureData()
{
  // writable: the caller may change the state, which the GPU then uploads again
  this->SyncFromGPU();
  this->InvalidateGPUState();
  return this->Q.empty() ? nullptr : this->Q.data();
}
const unsigned char* vtkPlumeSmokeSolver::GetSolidData()
{
  return this->Solid.empty() ? nullptr : this->Solid.data();
}

//------------------------------------------------------------------------------
bool vtkPlumeSmokeSolver::IsWallFace(int axis, int i, int j, int k) const
{
  const int* n = this->Cells;
  int idx[3] = { i, j, k };
  if (idx[axis] == 0)
  {
    return !this->Open[2 * axis] ||
      this->Solid[idx[0] + size_t(n[0]) * (idx[1] + size_t(n[1]) * idx[2])];
  }
  if (idx[axis] == n[axis])
  {
    --idx[axis];
    return !this->Open[2 * axis + 1] ||
      this->Solid[idx[0] + size_t(n[0]) * (idx[1] + size_t(n[1]) * idx[2])];
  }
  const size_t plus = idx[0] + size_t(n[0]) * (idx[1] + size_t(n[1]) * idx[2]);
  --idx[axis];
  const size_t minus = idx[0] + size_t(n[0]) * (idx[1] + size_t(n[1]) * idx[2]);
  return this->Solid[plus] || this->Solid[minus];
}

void vtkPlumeSmokeSolver::ComputeDivergence(double* divergence) const
{
  const int* n = this->Cells;
  const int mx = n[0] + 1, my = n[1] + 1;
  ForRows(n, [&](int j, int k) {
    for (int i = 0; i < n[0]; ++i)
    {
      const size_t c = i + size_t(n[0]) * (j + size_t(n[1]) * k);
      if (this->Solid[c])
      {
        divergence[c] = 0;
        continue;
      }
      const size_t fx = i + size_t(mx) * (j + size_t(n[1]) * k);
      const size_t fy = i + size_t(n[0]) * (j + size_t(my) * k);
      const size_t fz = c;
      divergence[c] = (this->U[0][fx + 1] - this->U[0][fx]) / this->H[0] +
        (this->U[1][fy + n[0]] - this->U[1][fy]) / this->H[1] +
        (this->U[2][fz + size_t(n[0]) * n[1]] - this->U[2][fz]) / this->H[2];
    }
  });
}

//------------------------------------------------------------------------------
bool vtkPlumeSmokeSolver::Project()
{
  if (this->Solid.empty() && !this->EnsureState())
  {
    return false;
  }
  if (!this->SyncFromGPU())
  {
    return false;
  }
  this->InvalidateGPUState();
  const int* n = this->Cells;
  const size_t count = this->Solid.size();
  std::vector<double> b(count);
  this->ComputeDivergence(b.data());
  for (double& v : b)
  {
    v = -v;
  }
  if (!this->Pressure->Solve(b.data(), this->Q.data()))
  {
    this->LastError = std::string("smoke solver: ") + this->Pressure->GetLastError();
    return false;
  }
  // Subtract the gradient on every face that is not a wall (ghost q = 0
  // beyond an open side).
  for (int d = 0; d < 3; ++d)
  {
    int m[3] = { n[0], n[1], n[2] };
    ++m[d];
    const size_t stride[3] = { 1, size_t(n[0]), size_t(n[0]) * n[1] };
    std::vector<double>& u = this->U[d];
    ForRows(m, [&](int j, int k) {
      for (int i = 0; i < m[0]; ++i)
      {
        if (this->IsWallFace(d, i, j, k))
        {
          continue;
        }
        int idx[3] = { i, j, k };
        const size_t f = i + size_t(m[0]) * (j + size_t(m[1]) * k);
        double qPlus = 0, qMinus = 0;
        if (idx[d] < n[d])
        {
          qPlus = this->Q[idx[0] * stride[0] + idx[1] * stride[1] + idx[2] * stride[2]];
        }
        if (idx[d] > 0)
        {
          --idx[d];
          qMinus = this->Q[idx[0] * stride[0] + idx[1] * stride[1] + idx[2] * stride[2]];
        }
        u[f] -= (qPlus - qMinus) / this->H[d];
      }
    });
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkPlumeSmokeSolver::Advect(const std::vector<double>& source, int axis, double dt, double rate, double target,
  std::vector<double>& result) const
{
  // The grid of `source`: cells (axis < 0) or the faces normal to `axis`;
  // point (i, j, k) lies at Origin + ((i, j, k) − shift)·Spacing.
  const int* n = this->Cells;
  int m[3] = { n[0], n[1], n[2] };
  glm::dvec3 shift(0.0);
  if (axis >= 0)
  {
    ++m[axis];
    shift[axis] = 0.5;
  }
  int faces[3][3];
  for (int d = 0; d < 3; ++d)
  {
    for (int a = 0; a < 3; ++a)
    {
      faces[d][a] = n[a] + (a == d ? 1 : 0);
    }
  }
  const glm::dvec3 origin(this->O[0], this->O[1], this->O[2]);
  const glm::dvec3 h(this->H[0], this->H[1], this->H[2]);
  // Velocity at a world position, each component from its face grid.
  auto velocity = [&](const glm::dvec3& p) {
    glm::dvec3 v;
    for (int d = 0; d < 3; ++d)
    {
      glm::dvec3 g = (p - origin) / h;
      g[d] += 0.5;
      v[d] = Trilinear(this->U[d], faces[d], g);
    }
    return v;
  };
  // Where a point came from over `step` seconds (midpoint rule); a negative
  // step traces forward.
  auto trace = [&](const glm::dvec3& x, double step) {
    const glm::dvec3 mid = x - 0.5 * step * velocity(x);
    return x - step * velocity(mid);
  };
  auto isFixed = [&](int i, int j, int k) {
    return axis >= 0 ? this->IsWallFace(axis, i, j, k)
                     : this->Solid[i + size_t(n[0]) * (j + size_t(n[1]) * k)] != 0;
  };
  const double fixedValue = axis >= 0 ? 0.0 : target; // static walls; solid cells
  const bool maccormack = this->AdvectionScheme == MACCORMACK;
  std::vector<double> forward;
  std::vector<double>& first = maccormack ? forward : result;
  first.assign(source.size(), fixedValue);
  ForRows(m, [&](int j, int k) {
    for (int i = 0; i < m[0]; ++i)
    {
      if (isFixed(i, j, k))
      {
        continue;
      }
      const glm::dvec3 x = origin + (glm::dvec3(i, j, k) - shift) * h;
      first[i + size_t(m[0]) * (j + size_t(m[1]) * k)] = Trilinear(source, m, (trace(x, dt) - origin) / h + shift);
    }
  });
  if (maccormack)
  {
    // MacCormack (Selle et al. 2008): advect the result back, correct by half
    // the round trip's error, and clamp to the values the first
    // interpolation used (without the clamp the scheme is not stable).
    result.assign(source.size(), fixedValue);
    ForRows(m, [&](int j, int k) {
      for (int i = 0; i < m[0]; ++i)
      {
        if (isFixed(i, j, k))
        {
          continue;
        }
        const size_t c = i + size_t(m[0]) * (j + size_t(m[1]) * k);
        const glm::dvec3 x = origin + (glm::dvec3(i, j, k) - shift) * h;
        const double back = Trilinear(forward, m, (trace(x, -dt) - origin) / h + shift);
        double lo, hi;
        MinMax(source, m, (trace(x, dt) - origin) / h + shift, lo, hi);
        result[c] = std::min(std::max(forward[c] + 0.5 * (source[c] - back), lo), hi);
      }
    });
  }
  if (rate > 0)
  {
    const double decay = std::exp(-rate * dt);
    for (double& v : result)
    {
      v = target + decay * (v - target);
    }
  }
}

void vtkPlumeSmokeSolver::ApplyBuoyancy(double dt)
{
  glm::dvec3 up(this->Up[0], this->Up[1], this->Up[2]);
  if (this->Cells[2] == 1)
  {
    up.z = 0;
    if (glm::length(up) == 0)
    {
      up = glm::dvec3(0, 1, 0);
    }
  }
  if (glm::length(up) == 0)
  {
    return;
  }
  up = glm::normalize(up);
  const int* n = this->Cells;
  for (int d = 0; d < 3; ++d)
  {
    if (up[d] == 0)
    {
      continue;
    }
    int m[3] = { n[0], n[1], n[2] };
    ++m[d];
    const size_t stride[3] = { 1, size_t(n[0]), size_t(n[0]) * n[1] };
    std::vector<double>& u = this->U[d];
    ForRows(m, [&](int j, int k) {
      for (int i = 0; i < m[0]; ++i)
      {
        if (this->IsWallFace(d, i, j, k))
        {
          continue;
        }
        // average of the cells on both sides (one at an open side)
        int idx[3] = { i, j, k };
        double t = 0, s = 0;
        int cells = 0;
        if (idx[d] < n[d])
        {
          const size_t c = idx[0] * stride[0] + idx[1] * stride[1] + idx[2] * stride[2];
          t += this->Temperature[c];
          s += this->Density[c];
          ++cells;
        }
        if (idx[d] > 0)
        {
          --idx[d];
          const size_t c = idx[0] * stride[0] + idx[1] * stride[1] + idx[2] * stride[2];
          t += this->Temperature[c];
          s += this->Density[c];
          ++cells;
        }
        t /= cells;
        s /= cells;
        const double force = this->Buoyancy * (t - this->AmbientTemperature) - this->SmokeWeight * s;
        u[i + size_t(m[0]) * (j + size_t(m[1]) * k)] += dt * force * up[d];
      }
    });
  }
}

//------------------------------------------------------------------------------
void vtkPlumeSmokeSolver::ApplyVorticityConfinement(double dt)
{
  if (this->VorticityConfinement <= 0)
  {
    return;
  }
  const int* n = this->Cells;
  const size_t count = this->Solid.size();
  const size_t stride[3] = { 1, size_t(n[0]), size_t(n[0]) * n[1] };
  // cell-centred velocity
  std::vector<glm::dvec3> uc(count);
  ForRows(n, [&](int j, int k) {
    for (int i = 0; i < n[0]; ++i)
    {
      const size_t c = i + stride[1] * j + stride[2] * k;
      const size_t fx = i + size_t(n[0] + 1) * (j + size_t(n[1]) * k);
      const size_t fy = i + size_t(n[0]) * (j + size_t(n[1] + 1) * k);
      uc[c] = glm::dvec3(0.5 * (this->U[0][fx] + this->U[0][fx + 1]),
        0.5 * (this->U[1][fy] + this->U[1][fy + n[0]]), 0.5 * (this->U[2][c] + this->U[2][c + stride[2]]));
    }
  });
  // central differences (one-sided at the domain sides); d/da of a cell array
  auto derivative = [&](auto&& value, int i, int j, int k, int a) {
    int lo[3] = { i, j, k }, hi[3] = { i, j, k };
    if (n[a] == 1)
    {
      return decltype(value(0)) {};
    }
    lo[a] = std::max(lo[a] - 1, 0);
    hi[a] = std::min(hi[a] + 1, n[a] - 1);
    const size_t cl = lo[0] * stride[0] + lo[1] * stride[1] + lo[2] * stride[2];
    const size_t ch = hi[0] * stride[0] + hi[1] * stride[1] + hi[2] * stride[2];
    return (value(ch) - value(cl)) / ((hi[a] - lo[a]) * this->H[a]);
  };
  std::vector<glm::dvec3> omega(count);
  std::vector<double> magnitude(count);
  ForRows(n, [&](int j, int k) {
    for (int i = 0; i < n[0]; ++i)
    {
      const size_t c = i + stride[1] * j + stride[2] * k;
      auto u = [&](size_t cell) { return uc[cell]; };
      const glm::dvec3 dx = derivative(u, i, j, k, 0), dy = derivative(u, i, j, k, 1), dz = derivative(u, i, j, k, 2);
      omega[c] = glm::dvec3(dy.z - dz.y, dz.x - dx.z, dx.y - dy.x);
      magnitude[c] = glm::length(omega[c]);
    }
  });
  const double scale = this->VorticityConfinement * std::min({ this->H[0], this->H[1], n[2] > 1 ? this->H[2] : this->H[0] });
  std::vector<glm::dvec3> force(count, glm::dvec3(0.0));
  ForRows(n, [&](int j, int k) {
    for (int i = 0; i < n[0]; ++i)
    {
      const size_t c = i + stride[1] * j + stride[2] * k;
      if (this->Solid[c])
      {
        continue;
      }
      auto m = [&](size_t cell) { return magnitude[cell]; };
      const glm::dvec3 g(derivative(m, i, j, k, 0), derivative(m, i, j, k, 1), derivative(m, i, j, k, 2));
      const double length = glm::length(g);
      if (length > 1e-12 * (magnitude[c] + 1e-300) / this->H[0] && length > 0)
      {
        force[c] = scale * glm::cross(g / length, omega[c]);
      }
    }
  });
  for (int d = 0; d < 3; ++d)
  {
    int m[3] = { n[0], n[1], n[2] };
    ++m[d];
    ForRows(m, [&](int j, int k) {
      for (int i = 0; i < m[0]; ++i)
      {
        if (this->IsWallFace(d, i, j, k))
        {
          continue;
        }
        int idx[3] = { i, j, k };
        double f = 0;
        int cells = 0;
        if (idx[d] < n[d])
        {
          f += force[idx[0] * stride[0] + idx[1] * stride[1] + idx[2] * stride[2]][d];
          ++cells;
        }
        if (idx[d] > 0)
        {
          --idx[d];
          f += force[idx[0] * stride[0] + idx[1] * stride[1] + idx[2] * stride[2]][d];
          ++cells;
        }
        this->U[d][i + size_t(m[0]) * (j + size_t(m[1]) * k)] += dt * f / cells;
      }
    });
  }
}

bool vtkPlumeSmokeSolver::SourceCoversCell(const Source& s, int i, int j, int k) const
{
  const int* n = this->Cells;
  const glm::dvec3 origin(this->O[0], this->O[1], this->O[2]);
  const glm::dvec3 h(this->H[0], this->H[1], this->H[2]);
  const glm::dvec3 center(s.Center[0], s.Center[1], s.Center[2]);
  // the cell containing the centre always emits (sources smaller than a cell)
  glm::ivec3 home;
  for (int a = 0; a < 3; ++a)
  {
    home[a] = std::min(std::max(int(std::lround((center[a] - origin[a]) / h[a])), 0), n[a] - 1);
  }
  const size_t c = i + size_t(n[0]) * (j + size_t(n[1]) * k);
  const glm::dvec3 x = origin + glm::dvec3(i, j, k) * h;
  return !this->Solid[c] && (glm::length(x - center) <= s.Radius || glm::ivec3(i, j, k) == home);
}

bool vtkPlumeSmokeSolver::SourceCoversFace(const Source& s, int d, int i, int j, int k) const
{
  const glm::dvec3 origin(this->O[0], this->O[1], this->O[2]);
  const glm::dvec3 h(this->H[0], this->H[1], this->H[2]);
  const glm::dvec3 center(s.Center[0], s.Center[1], s.Center[2]);
  glm::dvec3 x = origin + glm::dvec3(i, j, k) * h;
  x[d] -= 0.5 * h[d];
  return glm::length(x - center) <= std::max(s.Radius, 0.5 * h[d]) && !this->IsWallFace(d, i, j, k);
}

void vtkPlumeSmokeSolver::ApplySources()
{
  const int* n = this->Cells;
  for (const Source& s : this->Sources)
  {
    ForRows(n, [&](int j, int k) {
      for (int i = 0; i < n[0]; ++i)
      {
        if (this->SourceCoversCell(s, i, j, k))
        {
          const size_t c = i + size_t(n[0]) * (j + size_t(n[1]) * k);
          this->Density[c] = s.Density;
          this->Temperature[c] = s.Temperature;
        }
      }
    });
    if ((s.Velocity[0] == 0 && s.Velocity[1] == 0 && s.Velocity[2] == 0) || this->HasExternalVelocity())
    {
      continue;
    }
    for (int d = 0; d < 3; ++d)
    {
      int m[3] = { n[0], n[1], n[2] };
      ++m[d];
      ForRows(m, [&](int j, int k) {
        for (int i = 0; i < m[0]; ++i)
        {
          if (this->SourceCoversFace(s, d, i, j, k))
          {
            this->U[d][i + size_t(m[0]) * (j + size_t(m[1]) * k)] = s.Velocity[d];
          }
        }
      });
    }
  }
}

//------------------------------------------------------------------------------
bool vtkPlumeSmokeSolver::ApplyPointSources(double dt)
{
  this->LastInjectedMass = 0;
  vtkPointSet* points =
    this->GetNumberOfInputConnections(2) > 0 ? vtkPointSet::SafeDownCast(this->GetInputDataObject(2, 0)) : nullptr;
  if (!points || points->GetNumberOfPoints() == 0)
  {
    return true;
  }
  vtkPointData* pd = points->GetPointData();
  // a named array that is missing gives the default; a present one must fit
  auto find = [&](const std::string& name, int components, const char* what, vtkDataArray*& array) {
    array = name.empty() ? nullptr : pd->GetArray(name.c_str());
    if (array && array->GetNumberOfComponents() != components)
    {
      this->LastError = "smoke solver: source points: the " + std::string(what) + " array '" + name + "' has " +
        std::to_string(array->GetNumberOfComponents()) + " components, expected " + std::to_string(components);
      return false;
    }
    return true;
  };
  vtkDataArray *rates, *temperatures, *radii, *velocities;
  if (!find(this->SourceRateArrayName, 1, "rate", rates) ||
    !find(this->SourceTemperatureArrayName, 1, "temperature", temperatures) ||
    !find(this->SourceRadiusArrayName, 1, "radius", radii) ||
    !find(this->SourceVelocityArrayName, 3, "velocity", velocities))
  {
    return false;
  }
  const int* n = this->Cells;
  const glm::dvec3 origin(this->O[0], this->O[1], this->O[2]);
  const glm::dvec3 h(this->H[0], this->H[1], this->H[2]);
  const double cellVolume = h.x * h.y * h.z;
  const bool injectVelocity = velocities && !this->HasExternalVelocity();
  std::vector<size_t> cells;
  double injected = 0;
  // points one after the other, cells in a fixed order: the same bits whatever the threads
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    double x[3], velocity[3] = { 0, 0, 0 };
    points->GetPoint(p, x);
    const double rate = rates ? rates->GetComponent(p, 0) : this->SourceRate;
    const double temperature = temperatures ? temperatures->GetComponent(p, 0) : this->SourceTemperature;
    const double radius = radii ? radii->GetComponent(p, 0) : this->SourceRadius;
    if (velocities)
    {
      velocities->GetTuple(p, velocity);
    }
    for (double v : { x[0], x[1], x[2], rate, temperature, radius, velocity[0], velocity[1], velocity[2] })
    {
      if (!std::isfinite(v))
      {
        this->LastError = "smoke solver: source point " + std::to_string(p) + " has a non-finite value (" + Text(v) + ")";
        return false;
      }
    }
    if (rate < 0 || radius < 0)
    {
      this->LastError = "smoke solver: source point " + std::to_string(p) + " has a negative " +
        (rate < 0 ? "rate (" + Text(rate) + ")" : "radius (" + Text(radius) + ")");
      return false;
    }
    // a 2D grid: the point's z does not matter (it is moved into the plane)
    const glm::dvec3 center(x[0], x[1], n[2] == 1 ? origin.z : x[2]);
    const glm::dvec3 g = (center - origin) / h; // in cells; walls at -0.5 and n - 0.5
    bool inside = true;
    glm::ivec3 home, lo, hi;
    for (int a = 0; a < 3; ++a)
    {
      if (g[a] < -0.5 || g[a] > n[a] - 0.5)
      {
        inside = false;
      }
      home[a] = std::min(std::max(int(std::lround(g[a])), 0), n[a] - 1);
      lo[a] = std::max(0, int(std::ceil(g[a] - radius / h[a])));
      hi[a] = std::min(n[a] - 1, int(std::floor(g[a] + radius / h[a])));
    }
    if (!inside)
    {
      continue;
    }
    cells.clear();
    const size_t homeCell = home.x + size_t(n[0]) * (home.y + size_t(n[1]) * home.z);
    for (int k = lo.z; k <= hi.z; ++k)
      for (int j = lo.y; j <= hi.y; ++j)
        for (int i = lo.x; i <= hi.x; ++i)
        {
          const size_t c = i + size_t(n[0]) * (j + size_t(n[1]) * k);
          if (c != homeCell && !this->Solid[c] &&
            glm::length(origin + glm::dvec3(i, j, k) * h - center) <= radius)
          {
            cells.push_back(c);
          }
        }
    if (!this->Solid[homeCell])
    {
      cells.push_back(homeCell);
    }
    if (cells.empty())
    {
      continue;
    }
    const double added = rate * dt / (double(cells.size()) * cellVolume);
    for (size_t c : cells)
    {
      this->Density[c] += added;
      this->Temperature[c] = temperature;
    }
    injected += rate * dt;
    if (!injectVelocity || (velocity[0] == 0 && velocity[1] == 0 && velocity[2] == 0))
    {
      continue;
    }
    for (int d = 0; d < 3; ++d)
    {
      int m[3] = { n[0], n[1], n[2] };
      ++m[d];
      const double reach = std::max(radius, 0.5 * h[d]);
      glm::ivec3 flo, fhi;
      for (int a = 0; a < 3; ++a)
      {
        const double ga = g[a] + (a == d ? 0.5 : 0.0); // face i of axis d lies at i - 1/2
        flo[a] = std::max(0, int(std::ceil(ga - reach / h[a])));
        fhi[a] = std::min(m[a] - 1, int(std::floor(ga + reach / h[a])));
      }
      for (int k = flo.z; k <= fhi.z; ++k)
        for (int j = flo.y; j <= fhi.y; ++j)
          for (int i = flo.x; i <= fhi.x; ++i)
          {
            glm::dvec3 f = origin + glm::dvec3(i, j, k) * h;
            f[d] -= 0.5 * h[d];
            if (glm::length(f - center) <= reach && !this->IsWallFace(d, i, j, k))
            {
              this->U[d][i + size_t(m[0]) * (j + size_t(m[1]) * k)] = velocity[d];
            }
          }
    }
  }
  this->LastInjectedMass = injected;
  return true;
}

//------------------------------------------------------------------------------
namespace
{
const char CheckpointMagic[16] = "PLUMESMOKE1";
}

bool vtkPlumeSmokeSolver::WriteCheckpoint(const char* path)
{
  if (!this->EnsureState() || !this->SyncFromGPU())
  {
    return false;
  }
  std::ofstream out(path ? path : "", std::ios::binary);
  if (!out)
  {
    this->LastError = std::string("smoke solver: cannot write the checkpoint '") + (path ? path : "") + "'";
    return false;
  }
  auto write = [&](const void* data, size_t bytes) { out.write(static_cast<const char*>(data), bytes); };
  write(CheckpointMagic, sizeof(CheckpointMagic));
  write(this->Cells, sizeof(this->Cells));
  write(this->O, sizeof(this->O));
  write(this->H, sizeof(this->H));
  write(this->Open, sizeof(this->Open));
  const long long step = this->CurrentStep;
  write(&step, sizeof(step));
  write(&this->SimulationTime, sizeof(double));
  write(&this->LastProjectionDt, sizeof(double));
  for (const auto& u : this->U)
  {
    write(u.data(), u.size() * sizeof(double));
  }
  write(this->Density.data(), this->Density.size() * sizeof(double));
  write(this->Temperature.data(), this->Temperature.size() * sizeof(double));
  write(this->Q.data(), this->Q.size() * sizeof(double));
  write(this->Solid.data(), this->Solid.size());
  if (!out)
  {
    this->LastError = std::string("smoke solver: writing the checkpoint '") + path + "' failed";
    return false;
  }
  return true;
}

bool vtkPlumeSmokeSolver::ReadCheckpoint(const char* path)
{
  if (!this->EnsureState() || !this->SyncFromGPU())
  {
    return false;
  }
  this->InvalidateGPUState(); // the state read replaces the GPU's
  const std::string name = path ? path : "";
  std::ifstream in(name, std::ios::binary);
  if (!in)
  {
    this->LastError = "smoke solver: cannot read the checkpoint '" + name + "'";
    return false;
  }
  auto read = [&](void* data, size_t bytes) { return bool(in.read(static_cast<char*>(data), bytes)); };
  char magic[16] = {};
  int cells[3];
  double origin[3], spacing[3];
  bool open[6];
  long long step = 0;
  double time = 0, projectionDt = 0;
  if (!read(magic, sizeof(magic)) || std::memcmp(magic, CheckpointMagic, sizeof(magic)) != 0)
  {
    this->LastError = "smoke solver: '" + name + "' is not a smoke solver checkpoint";
    return false;
  }
  if (!read(cells, sizeof(cells)) || !read(origin, sizeof(origin)) || !read(spacing, sizeof(spacing)) ||
    !read(open, sizeof(open)) || !read(&step, sizeof(step)) || !read(&time, sizeof(time)) ||
    !read(&projectionDt, sizeof(projectionDt)))
  {
    this->LastError = "smoke solver: the checkpoint '" + name + "' is truncated";
    return false;
  }
  if (!std::equal(cells, cells + 3, this->Cells) || !std::equal(origin, origin + 3, this->O) ||
    !std::equal(spacing, spacing + 3, this->H) || !std::equal(open, open + 6, this->Open))
  {
    this->LastError = "smoke solver: the checkpoint '" + name + "' is of a " + std::to_string(cells[0]) + "x" +
      std::to_string(cells[1]) + "x" + std::to_string(cells[2]) +
      " grid with other origin, spacing or open sides than this solver's " + std::to_string(this->Cells[0]) + "x" +
      std::to_string(this->Cells[1]) + "x" + std::to_string(this->Cells[2]);
    return false;
  }
  std::vector<double> u[3], density(this->Density.size()), temperature(this->Temperature.size()),
    q(this->Q.size());
  std::vector<unsigned char> solid(this->Solid.size());
  bool ok = true;
  for (int d = 0; d < 3; ++d)
  {
    u[d].resize(this->U[d].size());
    ok = ok && read(u[d].data(), u[d].size() * sizeof(double));
  }
  ok = ok && read(density.data(), density.size() * sizeof(double)) &&
    read(temperature.data(), temperature.size() * sizeof(double)) && read(q.data(), q.size() * sizeof(double)) &&
    read(solid.data(), solid.size());
  if (!ok)
  {
    this->LastError = "smoke solver: the checkpoint '" + name + "' is truncated";
    return false;
  }
  if (this->HasMovingObstacles() && !this->HasExternalVelocity())
  {
    this->VoxeliseObstacles(time); // where they were at the checkpoint
  }
  if (solid != this->Solid)
  {
    if (this->HasMovingObstacles() && !this->HasExternalVelocity())
    {
      this->VoxeliseObstacles(this->SimulationTime);
    }
    this->LastError = "smoke solver: the checkpoint '" + name + "' has other obstacles than this solver";
    return false;
  }
  if (this->HasMovingObstacles() && !this->HasExternalVelocity())
  {
    this->Pressure->SetProblem(this->Cells, this->H, this->Solid.data(), this->Open);
  }
  for (int d = 0; d < 3; ++d)
  {
    this->U[d].swap(u[d]);
  }
  this->Density.swap(density);
  this->Temperature.swap(temperature);
  this->Q.swap(q);
  this->CurrentStep = vtkIdType(step);
  this->SimulationTime = time;
  this->LastProjectionDt = projectionDt;
  this->LastRequestedTime = std::numeric_limits<double>::quiet_NaN();
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkPlumeSmokeSolver::Step()
{
  return this->Advance(this->TimeStep);
}

bool vtkPlumeSmokeSolver::Advance(double dt)
{
  if (!this->EnsureState())
  {
    return false;
  }
  if (!(dt > 0) || !std::isfinite(dt))
  {
    this->LastError = "smoke solver: a step must be positive and finite, got " + Text(dt);
    return false;
  }
  if (this->Backend == BACKEND_GPU)
  {
    return this->AdvanceGPU(dt);
  }
  this->LastGPUPassCount = 0;
  if (!this->SyncFromGPU())
  {
    return false;
  }
  this->InvalidateGPUState(); // the CPU moves on
  const bool series = this->HasExternalVelocity() && this->IsVelocityTimeSeries();
  if (series && !this->SetVelocityAtTime(this->SimulationTime + 0.5 * dt))
  {
    return false; // the flow of the step's middle
  }
  // All advected quantities move with the velocity of the start of the step
  // (the scalars first: the velocity advection replaces it).
  std::vector<double> next;
  const bool closed = std::none_of(this->Open, this->Open + 6, [](bool o) { return o; });
  const bool conserve = this->ConserveMass && closed;
  // sums in a fixed order: the same bits whatever the number of threads
  auto total = [](const std::vector<double>& v) {
    double sum = 0;
    for (double x : v)
    {
      sum += x;
    }
    return sum;
  };
  const double massBefore = conserve ? total(this->Density) * std::exp(-this->DensityDissipation * dt) : 0.0;
  this->Advect(this->Density, -1, dt, this->DensityDissipation, 0.0, next);
  if (conserve)
  {
    const double massAfter = total(next);
    if (massAfter > 0 && massBefore > 0)
    {
      const double scale = massBefore / massAfter;
      for (double& v : next)
      {
        v *= scale;
      }
    }
  }
  this->Density.swap(next);
  this->Advect(this->Temperature, -1, dt, this->TemperatureDissipation, this->AmbientTemperature, next);
  this->Temperature.swap(next);
  if (this->HasExternalVelocity())
  {
    // passive smoke in a given flow: the velocity does not evolve
    this->ApplySources();
    if (!this->ApplyPointSources(dt))
    {
      return false;
    }
  }
  else
  {
    std::vector<double> velocity[3];
    for (int d = 0; d < 3; ++d)
    {
      this->Advect(this->U[d], d, dt, this->VelocityDissipation, 0.0, velocity[d]);
    }
    for (int d = 0; d < 3; ++d)
    {
      this->U[d].swap(velocity[d]);
    }
    if (this->HasMovingObstacles())
    {
      // the obstacles at the end of the step: the cells they cover hold no
      // smoke, their faces move with them, the pressure sees the new walls
      this->VoxeliseObstacles(this->SimulationTime + dt);
      if (std::all_of(this->Solid.begin(), this->Solid.end(), [](unsigned char s) { return s != 0; }))
      {
        this->LastError = "smoke solver: at t = " + Text(this->SimulationTime + dt) +
          " the moving obstacles cover every cell: there is no fluid to simulate";
        return false;
      }
      for (size_t c = 0; c < this->Solid.size(); ++c)
      {
        if (this->Solid[c])
        {
          this->Density[c] = 0;
          this->Temperature[c] = this->AmbientTemperature;
        }
      }
      this->ApplyObstacleVelocity();
      this->Pressure->SetProblem(this->Cells, this->H, this->Solid.data(), this->Open);
    }
    this->ApplyBuoyancy(dt);
    this->ApplyVorticityConfinement(dt);
    this->ApplySources();
    if (!this->ApplyPointSources(dt))
    {
      return false;
    }
    if (!this->Project())
    {
      return false;
    }
    this->LastProjectionDt = dt;
  }
  this->SimulationTime += dt;
  ++this->CurrentStep;
  ++this->StepsTaken;
  this->Modified();
  // the output shows the flow of the new time
  return !series || this->SetVelocityAtTime(this->SimulationTime);
}

//------------------------------------------------------------------------------
int vtkPlumeSmokeSolver::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // a velocity input with written times is a time series
  std::vector<double> times;
  if (vtkInformation* inInfo = inputVector[1]->GetInformationObject(0))
  {
    if (inInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
    {
      const double* t = inInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
      times.assign(t, t + inInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
    }
  }
  if (times != this->VelocityTimes)
  {
    this->VelocityTimes = times;
    this->HeldVelocityTime = std::numeric_limits<double>::quiet_NaN();
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6] = { 0, std::max(this->Dimensions[0], 1) - 1, 0, std::max(this->Dimensions[1], 1) - 1, 0,
    std::max(this->Dimensions[2], 1) - 1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), this->Origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), this->Spacing, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 1);
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  if (this->TimeStep > 0 && std::isfinite(this->TimeStep))
  {
    std::vector<double> times(size_t(this->NumberOfTimeSteps) + 1);
    for (size_t k = 0; k < times.size(); ++k)
    {
      times[k] = double(k) * this->TimeStep;
    }
    outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), int(times.size()));
    double range[2] = { 0.0, times.back() };
    outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }
  return 1;
}

int vtkPlumeSmokeSolver::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The obstacle and velocity images are read whole, whatever part of the
  // output is asked for; a static field (no time request upstream). A
  // velocity time series is asked for the written time it holds already
  // (the first at the start): the steps fetch the others they need.
  for (int port = 0; port < 2; ++port)
  {
    if (vtkInformation* inInfo = inputVector[port]->GetInformationObject(0))
    {
      if (inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
      {
        inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
          inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
      }
      if (port == 1 && this->IsVelocityTimeSeries())
      {
        if (std::find(this->VelocityTimes.begin(), this->VelocityTimes.end(), this->HeldVelocityTime) ==
          this->VelocityTimes.end())
        {
          this->HeldVelocityTime = this->VelocityTimes.front();
        }
        inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), this->HeldVelocityTime);
      }
      else
      {
        inInfo->Remove(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
      }
    }
  }
  return 1;
}

int vtkPlumeSmokeSolver::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  this->ObstacleInput = inputVector[0]->GetNumberOfInformationObjects() > 0
    ? vtkImageData::GetData(inputVector[0]->GetInformationObject(0))
    : nullptr;
  this->VelocityInput = inputVector[1]->GetNumberOfInformationObjects() > 0
    ? vtkImageData::GetData(inputVector[1]->GetInformationObject(0))
    : nullptr;
  if (this->VelocityInput && this->IsVelocityTimeSeries() &&
    this->VelocityInput->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP()))
  {
    this->HeldVelocityTime = this->VelocityInput->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP());
  }
  if (!this->EnsureState())
  {
    vtkErrorMacro(<< this->LastError);
    return 0;
  }
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    const double t = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    if (!std::isfinite(t))
    {
      vtkErrorMacro(<< "smoke solver: the requested time is not finite (" << t << ")");
      return 0;
    }
    if (!(t == this->LastRequestedTime))
    {
      const vtkIdType target = std::max<vtkIdType>(0, vtkIdType(std::llround(t / this->TimeStep)));
      if (target < this->CurrentStep)
      {
        this->Reset();
      }
      const vtkIdType first = this->CurrentStep;
      while (this->CurrentStep < target)
      {
        this->UpdateProgress(double(this->CurrentStep - first) / double(target - first));
        if (this->GetAbortExecute())
        {
          break;
        }
        if (!this->Step())
        {
          vtkErrorMacro(<< this->LastError);
          return 0;
        }
      }
      this->LastRequestedTime = t;
    }
  }
  this->FillOutput(output);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), this->SimulationTime);
  return 1;
}

void vtkPlumeSmokeSolver::FillOutput(vtkImageData* output)
{
  if (!this->SyncFromGPU())
  {
    vtkErrorMacro(<< this->LastError);
  }
  const int* n = this->Cells;
  output->SetExtent(0, n[0] - 1, 0, n[1] - 1, 0, n[2] - 1);
  output->SetOrigin(this->O);
  output->SetSpacing(this->H);
  const vtkIdType count = vtkIdType(this->Solid.size());
  auto makeArray = [&](const char* name, int components) {
    vtkNew<vtkFloatArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(count);
    return vtkSmartPointer<vtkFloatArray>(a.Get());
  };
  auto velocity = makeArray("velocity", 3);
  auto density = makeArray("density", 1);
  auto temperature = makeArray("temperature", 1);
  auto pressure = makeArray("pressure", 1);
  auto divergence = makeArray("divergence", 1);
  vtkNew<vtkUnsignedCharArray> obstacle;
  obstacle->SetName("obstacle");
  obstacle->SetNumberOfTuples(count);
  std::vector<double> div(this->Solid.size());
  this->ComputeDivergence(div.data());
  const double pressureScale = this->LastProjectionDt > 0 ? 1.0 / this->LastProjectionDt : 0.0;
  const int mx = n[0] + 1, my = n[1] + 1;
  float* v = velocity->GetPointer(0);
  ForRows(n, [&](int j, int k) {
    for (int i = 0; i < n[0]; ++i)
    {
      const size_t c = i + size_t(n[0]) * (j + size_t(n[1]) * k);
      const size_t fx = i + size_t(mx) * (j + size_t(n[1]) * k);
      const size_t fy = i + size_t(n[0]) * (j + size_t(my) * k);
      v[3 * c + 0] = float(0.5 * (this->U[0][fx] + this->U[0][fx + 1]));
      v[3 * c + 1] = float(0.5 * (this->U[1][fy] + this->U[1][fy + n[0]]));
      v[3 * c + 2] = float(0.5 * (this->U[2][c] + this->U[2][c + size_t(n[0]) * n[1]]));
      density->SetValue(vtkIdType(c), float(this->Density[c]));
      temperature->SetValue(vtkIdType(c), float(this->Temperature[c]));
      pressure->SetValue(vtkIdType(c), float(this->Q[c] * pressureScale));
      divergence->SetValue(vtkIdType(c), float(div[c]));
      obstacle->SetValue(vtkIdType(c), this->Solid[c]);
    }
  });
  // GPU backend: the velocity is the GPU's cell-centred texture read back
  // (the same bits a hand-over gives the glyph mapper), and with GPUHandOver
  // the density and velocity textures travel with the arrays
  const bool gpu = this->Backend == BACKEND_GPU && this->GPUUpToDate && this->GPU;
  if (gpu)
  {
    this->RevokeHandOvers();
    std::vector<float> rgba(4 * size_t(count));
    std::string error;
    if (this->GPU->Engine.CellVelocity(rgba.data(), error))
    {
      for (vtkIdType c = 0; c < count; ++c)
      {
        std::copy(&rgba[4 * c], &rgba[4 * c] + 3, v + 3 * c);
      }
      auto* window = this->GPU->Engine.GetWindow();
      if (this->GPUHandOver && this->GPU->Window && static_cast<vtkRenderWindow*>(window) == this->GPU->Window.Get())
      {
        this->GPU->DensityHandOver =
          vtkPlumeTextureHandOver::Attach(density, this->GPU->Engine.GetDensityTexture(), window);
        this->GPU->VelocityHandOver =
          vtkPlumeTextureHandOver::Attach(velocity, this->GPU->Engine.GetCellVelocityTexture(), window);
      }
    }
    else
    {
      vtkErrorMacro(<< "smoke solver (GPU backend): " << error);
    }
  }
  vtkPointData* pd = output->GetPointData();
  pd->Initialize();
  pd->SetScalars(density);
  pd->SetVectors(velocity);
  pd->AddArray(temperature);
  pd->AddArray(pressure);
  pd->AddArray(divergence);
  pd->AddArray(obstacle);
}

//------------------------------------------------------------------------------
void vtkPlumeSmokeSolver::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Dimensions: " << this->Dimensions[0] << " " << this->Dimensions[1] << " "
     << this->Dimensions[2] << "\n";
  os << indent << "TimeStep: " << this->TimeStep << "\n";
  os << indent << "Sources: " << this->Sources.size() << "\n";
  os << indent << "Obstacles: " << this->Obstacles.size() << "\n";
  os << indent << "OpenFaces: " << this->OpenFaces << "\n";
  os << indent << "SimulationTime: " << this->SimulationTime << "\n";
  os << indent << "CurrentStep: " << this->CurrentStep << "\n";
  os << indent << "Backend: " << this->Backend << "\n";
  os << indent << "GPUHandOver: " << this->GPUHandOver << "\n";
}
