#include "vtkPlumeGaussianSplatter.h"

#include "vtkPlumeInputValidation.h"
#include "vtkPlumeParameterTable.h"

#include "plumeSplatCPU.h"
#include "plumeSplatGPU.h"
#include "plumeSplatKernel.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPlumeTextureHandOver.h"
#include "vtkRenderWindow.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <array>
#include <set>
#include <chrono>
#include <cmath>
#include <sstream>
#include <cstring>

using plume::splat::Grid;
using plume::splat::Kind;
using plume::splat::Settings;
using plume::splat::Splat;

namespace
{
bool Finite3(const double v[3])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

bool LinePointIsGhost(const vtkUnsignedCharArray* ghosts, vtkIdType id)
{
  return ghosts && id < ghosts->GetNumberOfValues() &&
    (ghosts->GetValue(id) & vtkDataSetAttributes::DUPLICATEPOINT) != 0;
}

bool LineCellIsGhost(const vtkUnsignedCharArray* ghosts, vtkIdType id)
{
  return ghosts && id < ghosts->GetNumberOfValues() &&
    (ghosts->GetValue(id) & (vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL)) != 0;
}

double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}

//------------------------------------------------------------------------------
class vtkPlumeGaussianSplatter::Internals
{
public:
  vtkSmartPointer<vtkImageData> Reference;
  vtkSmartPointer<vtkRenderWindow> Window;
  plume::splat::SplatGPU GPU;
  // the output's array, reused by the next execution if nobody else holds it
  vtkSmartPointer<vtkFloatArray> LastField;
  // the GPU texture handed over with the current output (GPUHandOver)
  vtkSmartPointer<vtkPlumeTextureHandOver> HandOver;

  // before the texture is overwritten or freed: arrays holding it upload instead
  void RevokeHandOver()
  {
    if (this->HandOver)
    {
      this->HandOver->Revoke();
      this->HandOver = nullptr;
    }
  }
  void ReleaseGPU()
  {
    this->RevokeHandOver();
    this->GPU.Release();
  }
};

vtkStandardNewMacro(vtkPlumeGaussianSplatter);

vtkPlumeGaussianSplatter::vtkPlumeGaussianSplatter()
  : Impl(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(1);
  // Measured crossover (Documentation/Splatting.md): on llvmpipe the CPU
  // backend wins at every size measured, so AUTO only picks the GPU above a
  // job no benchmark reached.
  this->AutoGPUThreshold = 1e30;
  GetParameterTable().ApplyDefaults(this);
}

const vtkPlumeParameterTable& vtkPlumeGaussianSplatter::GetParameterTable()
{
  static const vtkPlumeParameterTable table = [] {
    using T = vtkPlumeGaussianSplatter;
    vtkPlumeParameterTable t("vtkPlumeGaussianSplatter", "splat");
    t.Choice("mode", "Mode", "velocity")
      .Choice("velocity", VECTOR_SUM, "sum of the points' vectors (line segments: their velocity) times the Gaussian; output 'velocity'")
      .Choice("density", SCALAR_SUM, "sum of the points' scalars (line segments: their length) times the Gaussian; output 'density'")
      .Choice("distance", DISTANCE_MAX, "maximum over splats of the scalar times a linear falloff over the radius; output 'distance'")
      .Panel("Splat")
      .Doc("What is splatted.")
      .Bind(&T::SetMode, &T::GetMode);
    t.Real("sigma", "Radius", 0.1)
      .Between(0.0, 1e30)
      .Units("world units")
      .Panel("Splat")
      .Doc("Splat radius sigma (distance mode: the falloff radius).")
      .Bind(&T::SetRadius, &T::GetRadius);
    t.Text("radius_array", "RadiusArrayName", "")
      .Panel("Splat")
      .Advanced()
      .Doc("Point array with a per-point radius; empty or absent: the constant radius.")
      .Bind(&T::SetRadiusArrayName, &T::GetRadiusArrayName);
    t.Text("vectors", "VectorArrayName", "")
      .OnlyWith("mode", { "velocity" })
      .Panel("Splat")
      .Doc("Vector array of the points (velocity mode); empty: the active vectors.")
      .Bind(&T::SetVectorArrayName, &T::GetVectorArrayName);
    t.Text("scalars", "ScalarArrayName", "")
      .OnlyWith("mode", { "density", "distance" })
      .Panel("Splat")
      .Doc("Scalar array of the points (density, distance); empty: the active scalars, else 1.")
      .Bind(&T::SetScalarArrayName, &T::GetScalarArrayName);
    t.Real("scale", "LineScaleFactor", 1.0)
      .OnlyWith("mode", { "velocity" })
      .Between(-1e30, 1e30)
      .Panel("Splat")
      .Advanced()
      .Doc("Factor on the line velocities p[i+1] - p[i].")
      .Bind(&T::SetLineScaleFactor, &T::GetLineScaleFactor);
    t.Real("cutoff", "CutoffFactor", 4.0)
      .Between(0.5, 40.0)
      .Units("standard deviations")
      .Panel("Accuracy")
      .Advanced()
      .Doc("Splats touch voxels within cutoff x sigma per axis (error about exp(-cutoff^2/2) of the peak).")
      .Bind(&T::SetCutoffFactor, &T::GetCutoffFactor);
    t.Boolean("integrate", "IntegrateOverVoxel", true)
      .Panel("Accuracy")
      .Advanced()
      .Doc("Average each splat over the voxel (erf) instead of sampling it at the voxel's centre.")
      .Bind(&T::SetIntegrateOverVoxel, &T::GetIntegrateOverVoxel);
    t.Choice("backend", "Backend", "auto")
      .Choice("auto", BACKEND_AUTO, "the backend measured to be faster for the job")
      .Choice("cpu", BACKEND_CPU, "threads over z-slabs")
      .Choice("gpu", BACKEND_GPU, "layered instanced rendering into a float 3D texture")
      .Panel("Accuracy")
      .Advanced()
      .Doc("Where the splats are summed (same result within float rounding).")
      .Bind(&T::SetBackend, &T::GetBackend);
    return t;
  }();
  return table;
}

vtkPlumeGaussianSplatter::~vtkPlumeGaussianSplatter()
{
  this->ReleaseGraphicsResources();
}

void vtkPlumeGaussianSplatter::ReleaseGraphicsResources()
{
  this->Impl->ReleaseGPU();
}

void vtkPlumeGaussianSplatter::SetLinesData(vtkPolyData* lines)
{
  this->SetInputData(1, lines);
}

void vtkPlumeGaussianSplatter::SetLinesConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkPlumeGaussianSplatter::SetReferenceImage(vtkImageData* image)
{
  if (this->Impl->Reference != image)
  {
    this->Impl->Reference = image;
    this->Modified();
  }
}

vtkImageData* vtkPlumeGaussianSplatter::GetReferenceImage()
{
  return this->Impl->Reference;
}

void vtkPlumeGaussianSplatter::SetRenderWindow(vtkRenderWindow* window)
{
  if (this->Impl->Window != window)
  {
    this->Impl->ReleaseGPU();
    this->Impl->Window = window;
    this->Modified();
  }
}

vtkRenderWindow* vtkPlumeGaussianSplatter::GetRenderWindow()
{
  return this->Impl->Window;
}

vtkMTimeType vtkPlumeGaussianSplatter::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->Impl->Reference)
  {
    t = std::max(t, this->Impl->Reference->GetMTime());
  }
  return t;
}

int vtkPlumeGaussianSplatter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkPointSet" : "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkPlumeGaussianSplatter::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int dims[3] = { this->Dimensions[0], this->Dimensions[1], this->Dimensions[2] };
  if (this->Impl->Reference)
  {
    this->Impl->Reference->GetDimensions(dims);
    outInfo->Set(vtkDataObject::ORIGIN(), this->Impl->Reference->GetOrigin(), 3);
    outInfo->Set(vtkDataObject::SPACING(), this->Impl->Reference->GetSpacing(), 3);
  }
  for (int& d : dims)
  {
    d = std::max(1, d);
  }
  const int extent[6] = { 0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  const int comps = this->Mode == VECTOR_SUM ? 3 : 1;
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, comps);
  return 1;
}

int vtkPlumeGaussianSplatter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  ++this->ExecuteCount;
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  vtkPointSet* points = vtkPointSet::GetData(inputVector[0], 0);
  vtkPolyData* lines = vtkPolyData::GetData(inputVector[1], 0);
  this->LastError.clear();
  auto refuse = [this](const std::string& message) {
    this->LastError = message;
    vtkErrorMacro(<< message);
    return 0;
  };
  // the line ids and per-point arrays are read unchecked below
  for (vtkDataSet* input : { static_cast<vtkDataSet*>(points), static_cast<vtkDataSet*>(lines) })
  {
    const std::string invalid = vtkPlumeInputValidation::CheckDataObject(input);
    if (!invalid.empty())
    {
      return refuse(std::string(input == lines ? "lines" : "points") + ": invalid input: " + invalid);
    }
  }

  const bool sum = this->Mode != DISTANCE_MAX;
  Settings settings;
  settings.Mode = sum ? Kind::Sum : Kind::Distance;
  settings.Components = this->Mode == VECTOR_SUM ? 3 : 1;
  settings.Cutoff = this->CutoffFactor;
  settings.Integrate = this->IntegrateOverVoxel;

  // ---- splats from the inputs
  std::vector<Splat> splats;
  vtkIdType skipped = 0;
  auto radiusArray = [&](vtkDataSet* ds) -> vtkDataArray* {
    if (this->RadiusArrayName.empty())
    {
      return nullptr;
    }
    return ds->GetPointData()->GetArray(this->RadiusArrayName.c_str());
  };
  auto add = [&](const double c[3], const double v[3], double radius) {
    if (!Finite3(c) || !Finite3(v) || !std::isfinite(radius) || !(radius > 0))
    {
      ++skipped;
      return;
    }
    Splat s;
    std::copy(c, c + 3, s.Center);
    std::copy(v, v + 3, s.Value);
    s.Radius = radius;
    splats.push_back(s);
  };

  if (points && points->GetNumberOfPoints() > 0)
  {
    vtkPointData* pd = points->GetPointData();
    vtkDataArray* values = nullptr;
    if (this->Mode == VECTOR_SUM)
    {
      values = this->VectorArrayName.empty() ? pd->GetVectors() : pd->GetArray(this->VectorArrayName.c_str());
      if (!values)
      {
        vtkErrorMacro(<< "points: no vector array "
                      << (this->VectorArrayName.empty() ? "(no active vectors)" : "'" + this->VectorArrayName + "'")
                      << " for VECTOR_SUM");
        return 0;
      }
      if (values->GetNumberOfComponents() != 3)
      {
        vtkErrorMacro(<< "points: array '" << (values->GetName() ? values->GetName() : "") << "' has "
                      << values->GetNumberOfComponents() << " components, expected 3");
        return 0;
      }
    }
    else
    {
      values = this->ScalarArrayName.empty() ? pd->GetScalars() : pd->GetArray(this->ScalarArrayName.c_str());
      if (!values && !this->ScalarArrayName.empty())
      {
        vtkErrorMacro(<< "points: no scalar array '" << this->ScalarArrayName << "'");
        return 0;
      }
      if (values && values->GetNumberOfComponents() != 1)
      {
        vtkErrorMacro(<< "points: array '" << (values->GetName() ? values->GetName() : "") << "' has "
                      << values->GetNumberOfComponents() << " components, expected 1");
        return 0;
      }
    }
    vtkDataArray* radii = radiusArray(points);
    // Points another piece owns (DUPLICATEPOINT in vtkGhostType: ParaView
    // ranks, D3) are splatted there; counting them here too would double them.
    // Both backends splat this list.
    const vtkUnsignedCharArray* ghosts =
      vtkUnsignedCharArray::SafeDownCast(pd->GetArray(vtkDataSetAttributes::GhostArrayName()));
    const vtkIdType n = points->GetNumberOfPoints();
    splats.reserve(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (ghosts && i < ghosts->GetNumberOfValues() &&
        (ghosts->GetValue(i) & vtkDataSetAttributes::DUPLICATEPOINT) != 0)
      {
        continue;
      }
      double c[3], v[3] = { 1, 0, 0 };
      points->GetPoint(i, c);
      if (values)
      {
        if (settings.Components == 3)
        {
          values->GetTuple(i, v);
        }
        else
        {
          v[0] = values->GetComponent(i, 0);
        }
      }
      add(c, v, radii ? radii->GetComponent(i, 0) : this->Radius);
    }
  }

  if (lines && lines->GetNumberOfLines() > 0)
  {
    vtkDataArray* radii = radiusArray(lines);
    // Where a line continues in another cell (here or, through
    // LineContinuations, on another rank), the vertex it ends on is that
    // cell's first vertex: splatted there, with the forward difference.
    std::vector<double> starts;
    vtkPlumeGaussianSplatter::CollectLineStarts(lines, starts);
    starts.insert(starts.end(), this->LineContinuations.begin(), this->LineContinuations.end());
    std::set<std::array<double, 3>> continued;
    for (size_t k = 0; k + 2 < starts.size(); k += 3)
    {
      continued.insert({ starts[k], starts[k + 1], starts[k + 2] });
    }
    const vtkUnsignedCharArray* pointGhosts = lines->GetPointGhostArray();
    const vtkUnsignedCharArray* cellGhosts = lines->GetCellGhostArray();
    const vtkIdType firstLineId = lines->GetNumberOfVerts(); // cell ids: verts, then lines
    vtkCellArray* cells = lines->GetLines();
    vtkIdType npts;
    const vtkIdType* ids;
    vtkIdType cellIndex = -1;
    for (cells->InitTraversal(); cells->GetNextCell(npts, ids);)
    {
      ++cellIndex;
      if (npts < 1 || LineCellIsGhost(cellGhosts, firstLineId + cellIndex))
      {
        continue; // another piece owns the whole cell
      }
      double first[3], last[3];
      lines->GetPoint(ids[0], first);
      lines->GetPoint(ids[npts - 1], last);
      const bool closed = npts > 1 && (ids[0] == ids[npts - 1] ||
        (first[0] == last[0] && first[1] == last[1] && first[2] == last[2]));
      const vtkIdType m = closed ? npts - 1 : npts;
      const bool continues = !closed && npts > 1 && continued.count({ last[0], last[1], last[2] }) > 0;
      for (vtkIdType i = 0; i < m; ++i)
      {
        if (LinePointIsGhost(pointGhosts, ids[i]) || (continues && i == m - 1))
        {
          continue; // splatted by the piece or cell that owns the vertex
        }
        double p[3], q[3];
        lines->GetPoint(ids[i], p);
        double d[3] = { 0, 0, 0 };
        if (i + 1 < m || closed)
        {
          lines->GetPoint(ids[(i + 1) % m], q);
          vtkMath::Subtract(q, p, d);
        }
        else if (i > 0)
        {
          lines->GetPoint(ids[i - 1], q);
          vtkMath::Subtract(p, q, d);
        }
        double v[3] = { 1, 0, 0 };
        if (this->Mode == VECTOR_SUM)
        {
          for (int c = 0; c < 3; ++c)
          {
            v[c] = this->LineScaleFactor * d[c];
          }
        }
        else if (this->Mode == SCALAR_SUM)
        {
          v[0] = std::fabs(this->LineScaleFactor) * vtkMath::Norm(d);
        }
        if (sum && !Finite3(d))
        {
          ++skipped; // a non-finite neighbour
          continue;
        }
        if (sum && v[0] == 0 && v[1] == 0 && v[2] == 0)
        {
          continue; // zero-length segment: contributes nothing
        }
        add(p, v, radii ? radii->GetComponent(ids[i], 0) : this->Radius);
      }
    }
  }
  if (skipped > 0)
  {
    vtkWarningMacro(<< skipped << " splat(s) skipped: non-finite position, value or radius, or radius <= 0");
  }
  this->SkippedCount = skipped;

  // ---- the grid
  Grid grid;
  if (this->Impl->Reference)
  {
    this->Impl->Reference->GetOrigin(grid.Origin);
    this->Impl->Reference->GetSpacing(grid.Spacing);
    this->Impl->Reference->GetDimensions(grid.Dims);
  }
  else
  {
    double b[6];
    std::copy(this->ModelBounds, this->ModelBounds + 6, b);
    const bool valid = b[0] < b[1] && b[2] < b[3] && b[4] < b[5] && std::isfinite(b[0] + b[1] + b[2] + b[3] + b[4] + b[5]);
    if (!valid)
    {
      double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
      double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
      for (const Splat& s : splats)
      {
        const double reach = sum ? this->CutoffFactor * s.Radius : s.Radius;
        for (int a = 0; a < 3; ++a)
        {
          lo[a] = std::min(lo[a], s.Center[a] - reach);
          hi[a] = std::max(hi[a], s.Center[a] + reach);
        }
      }
      for (int a = 0; a < 3; ++a)
      {
        if (!(lo[a] < hi[a]) || !std::isfinite(hi[a] - lo[a]))
        {
          lo[a] = splats.empty() ? 0.0 : std::min(lo[a], hi[a]);
          hi[a] = lo[a] + 1.0;
        }
        b[2 * a] = lo[a];
        b[2 * a + 1] = hi[a];
      }
    }
    for (int a = 0; a < 3; ++a)
    {
      grid.Dims[a] = std::max(1, this->Dimensions[a]);
      grid.Origin[a] = grid.Dims[a] == 1 ? 0.5 * (b[2 * a] + b[2 * a + 1]) : b[2 * a];
      grid.Spacing[a] = grid.Dims[a] == 1 ? 1.0 : (b[2 * a + 1] - b[2 * a]) / (grid.Dims[a] - 1);
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    if (!(grid.Spacing[a] > 0) || !std::isfinite(grid.Spacing[a]) || !std::isfinite(grid.Origin[a]))
    {
      vtkErrorMacro(<< "output grid: spacing along axis " << a << " is " << grid.Spacing[a]
                    << " (needs a positive, finite spacing and origin)");
      return 0;
    }
  }
  // Bound what grows with the parameters before allocating or splatting: the grid's memory
  // and the voxels all footprints touch (a sigma huge next to the spacing is millions each).
  {
    std::string tooMuch = vtkPlumeInputValidation::CheckMemory(
      grid.Voxels() * 4.0 * settings.Components, "the splat grid (" + std::to_string(grid.Dims[0]) + "x" +
        std::to_string(grid.Dims[1]) + "x" + std::to_string(grid.Dims[2]) + ")");
    if (!tooMuch.empty())
    {
      return refuse(tooMuch);
    }
    double voxels = 0;
    for (const Splat& s : splats)
    {
      const double reach = sum ? this->CutoffFactor * s.Radius : s.Radius;
      double box = 1;
      for (int a = 0; a < 3; ++a)
      {
        box *= std::min<double>(grid.Dims[a], 2 * reach / grid.Spacing[a] + 1);
      }
      voxels += box;
    }
    std::ostringstream what;
    what << "splatting " << splats.size() << " splats (radius " << this->Radius << ", cutoff "
         << this->CutoffFactor << ") onto " << grid.Dims[0] << "x" << grid.Dims[1] << "x" << grid.Dims[2]
         << " voxels";
    tooMuch = vtkPlumeInputValidation::CheckWork(voxels, what.str());
    if (!tooMuch.empty())
    {
      return refuse(tooMuch + "; use a smaller radius or a coarser grid");
    }
  }
  // Reuse the previous output's array when nobody else holds it and it has
  // the right size (as vtkImageData::AllocateScalars does; the executive
  // keeps only an image's scalars for that, so we keep our own reference): a
  // fresh 256³ grid costs more in page faults than splatting a thousand points.
  output->Initialize(); // drop the previous mode's array
  output->SetExtent(0, grid.Dims[0] - 1, 0, grid.Dims[1] - 1, 0, grid.Dims[2] - 1);
  output->SetOrigin(grid.Origin);
  output->SetSpacing(grid.Spacing);
  vtkSmartPointer<vtkFloatArray> field = this->Impl->LastField;
  if (!field || field->GetReferenceCount() != 2 || // ours: the smart pointer here and LastField
    field->GetNumberOfComponents() != settings.Components ||
    field->GetNumberOfTuples() != static_cast<vtkIdType>(grid.Voxels()))
  {
    field = vtkSmartPointer<vtkFloatArray>::New();
    field->SetNumberOfComponents(settings.Components);
    field->SetNumberOfTuples(static_cast<vtkIdType>(grid.Voxels()));
    this->Impl->LastField = field;
  }
  else if (field->HasInformation())
  {
    field->GetInformation()->Remove(vtkPlumeTextureHandOver::TEXTURE()); // new values follow
  }
  field->SetName(this->Mode == VECTOR_SUM ? "velocity" : this->Mode == SCALAR_SUM ? "density" : "distance");
  float* out = field->GetPointer(0); // every value is written by the backend (the CPU zeroes in its threads)

  // ---- which backend
  int backend = this->Backend;
  if (backend == BACKEND_AUTO)
  {
    double touches = 0;
    for (const Splat& s : splats)
    {
      const double reach = sum ? this->CutoffFactor * s.Radius : s.Radius;
      double box = 1;
      for (int a = 0; a < 3; ++a)
      {
        box *= std::min<double>(grid.Dims[a], 2 * reach / grid.Spacing[a] + 1);
      }
      touches += box;
    }
    backend = touches > this->AutoGPUThreshold ? BACKEND_GPU : BACKEND_CPU;
  }

  const double t0 = Now();
  size_t touched = 0;
  bool done = false;
  if (backend == BACKEND_GPU && !splats.empty())
  {
    std::string error;
    this->Impl->RevokeHandOver(); // the texture is about to be overwritten
    done = this->Impl->GPU.Run(this->Impl->Window, grid, settings, splats, out, touched, error);
    if (!done)
    {
      if (this->Backend == BACKEND_GPU)
      {
        vtkErrorMacro(<< "GPU backend: " << error);
        return 0;
      }
      vtkWarningMacro(<< "GPU backend failed (" << error << "); using the CPU");
    }
  }
  if (!done)
  {
    backend = BACKEND_CPU;
    touched = plume::splat::SplatCPU(grid, settings, splats, out);
  }
  this->LastSplatSeconds = Now() - t0;
  this->LastBackend = backend;
  this->SplatCount = static_cast<vtkIdType>(touched);
  this->CulledCount = static_cast<vtkIdType>(splats.size() - touched);

  field->Modified(); // reused or not, these are new values
  if (settings.Components == 3)
  {
    output->GetPointData()->SetVectors(field);
  }
  else
  {
    output->GetPointData()->SetScalars(field);
  }
  // hand the GPU's texture over to Plume's mappers in the caller's window
  // (useless in our own offscreen window, whose context nobody else renders in)
  if (done && this->GPUHandOver && settings.Components == 3 && this->Impl->Window)
  {
    vtkOpenGLRenderWindow* window = nullptr;
    vtkTextureObject* texture = this->Impl->GPU.GetResult(window);
    this->Impl->HandOver = vtkPlumeTextureHandOver::Attach(field, texture, window);
  }
  return 1;
}

void vtkPlumeGaussianSplatter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->Mode << "\n";
  os << indent << "Backend: " << this->Backend << " (last " << this->LastBackend << ")\n";
  os << indent << "Dimensions: " << this->Dimensions[0] << " " << this->Dimensions[1] << " " << this->Dimensions[2]
     << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "RadiusArrayName: " << this->RadiusArrayName << "\n";
  os << indent << "VectorArrayName: " << this->VectorArrayName << "\n";
  os << indent << "ScalarArrayName: " << this->ScalarArrayName << "\n";
  os << indent << "LineScaleFactor: " << this->LineScaleFactor << "\n";
  os << indent << "CutoffFactor: " << this->CutoffFactor << "\n";
  os << indent << "IntegrateOverVoxel: " << this->IntegrateOverVoxel << "\n";
  os << indent << "AutoGPUThreshold: " << this->AutoGPUThreshold << "\n";
  os << indent << "GPUHandOver: " << this->GPUHandOver << "\n";
}

//------------------------------------------------------------------------------
void vtkPlumeGaussianSplatter::CollectLineStarts(vtkPolyData* lines, std::vector<double>& starts)
{
  if (!lines || lines->GetNumberOfLines() == 0)
  {
    return;
  }
  const vtkUnsignedCharArray* pointGhosts = lines->GetPointGhostArray();
  const vtkUnsignedCharArray* cellGhosts = lines->GetCellGhostArray();
  const vtkIdType firstLineId = lines->GetNumberOfVerts();
  vtkCellArray* cells = lines->GetLines();
  vtkIdType npts;
  const vtkIdType* ids;
  vtkIdType cellIndex = -1;
  for (cells->InitTraversal(); cells->GetNextCell(npts, ids);)
  {
    ++cellIndex;
    // only a start that is splatted here takes the vertex over from the line ending on it
    if (npts < 2 || ids[0] == ids[npts - 1] || LineCellIsGhost(cellGhosts, firstLineId + cellIndex) ||
      LinePointIsGhost(pointGhosts, ids[0]))
    {
      continue;
    }
    double first[3], last[3];
    lines->GetPoint(ids[0], first);
    lines->GetPoint(ids[npts - 1], last);
    if (first[0] == last[0] && first[1] == last[1] && first[2] == last[2])
    {
      continue; // a closed loop
    }
    starts.insert(starts.end(), first, first + 3);
  }
}
