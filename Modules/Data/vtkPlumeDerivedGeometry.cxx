#include "vtkPlumeDerivedGeometry.h"

#include "vtkPlumeInputValidation.h"
#include "vtkPlumeParameterTable.h"

#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCellDataToPointData.h"
#include "vtkContourFilter.h"
#include "vtkCutter.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLineSource.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlane.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRibbonFilter.h"
#include "vtkSmartPointer.h"
#include "vtkStreamSurface.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStreamTracer.h"
#include "vtkTableBasedClipDataSet.h"
#include "vtkThreshold.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/glm.hpp>

vtkStandardNewMacro(vtkPlumeDerivedGeometry);

namespace
{
const char* const OperationKeys[] = { "contour", "slice", "streamlines", "stream_surface", "ribbon",
  "threshold", "clip" };

std::string Num(double x)
{
  std::ostringstream s;
  s << x;
  return s.str();
}

std::string Vec(const double v[3])
{
  return "[" + Num(v[0]) + ", " + Num(v[1]) + ", " + Num(v[2]) + "]";
}

bool Internal(const char* name)
{
  const std::string n = name ? name : "";
  return n.empty() || n == "vtkValidPointMask" || n == "vtkGhostType";
}

std::string ListArrays(vtkDataSet* data)
{
  std::string out;
  for (vtkDataSetAttributes* a : { static_cast<vtkDataSetAttributes*>(data->GetPointData()),
         static_cast<vtkDataSetAttributes*>(data->GetCellData()) })
  {
    std::string names;
    for (int i = 0; i < a->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* array = a->GetArray(i);
      if (array && !Internal(array->GetName()))
      {
        names += (names.empty() ? "" : ", ") + std::string(array->GetName());
      }
    }
    out += (out.empty() ? "point arrays: " : "; cell arrays: ") + (names.empty() ? "none" : names);
  }
  return out;
}

/**
 * The named array, first as point data, then as cell data (cell data first when
 * `preferCells`: a finite-volume reader's point copy is interpolated); `cell` says which.
 */
vtkDataArray* FindArray(vtkDataSet* data, const std::string& name, bool& cell, bool preferCells)
{
  if (preferCells)
  {
    if (vtkDataArray* a = data->GetCellData()->GetArray(name.c_str()))
    {
      cell = true;
      return a;
    }
  }
  cell = false;
  if (vtkDataArray* a = data->GetPointData()->GetArray(name.c_str()))
  {
    return a;
  }
  cell = true;
  return data->GetCellData()->GetArray(name.c_str());
}

/** A default array: the active attribute, else the first point (then cell) array with `components`. */
vtkDataArray* DefaultArray(vtkDataSet* data, bool vectors, bool& cell)
{
  const int components = vectors ? 3 : 1;
  cell = false;
  vtkDataArray* active = vectors ? data->GetPointData()->GetVectors() : data->GetPointData()->GetScalars();
  if (active && !Internal(active->GetName()))
  {
    return active;
  }
  int pass = 0;
  for (vtkDataSetAttributes* a : { static_cast<vtkDataSetAttributes*>(data->GetPointData()),
         static_cast<vtkDataSetAttributes*>(data->GetCellData()) })
  {
    cell = pass++ == 1;
    for (int i = 0; i < a->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* array = a->GetArray(i);
      if (array && !Internal(array->GetName()) && array->GetNumberOfComponents() == components)
      {
        return array;
      }
    }
  }
  return nullptr;
}

// Operations (in the work budget's units, a few ns each) one point copy of
// vtkStreamSurface's iterative loop costs: 5.7e6 copied points took 22 s on the
// office (VTK 9.1, one core), about 4 us each, with the step's tracing included.
constexpr double kCopyOperations = 1000;
// Bytes a point of the iterative surface holds (coordinates, its two double
// arrays, two triangles) times two: the append filter's copy beside the surface.
constexpr double kIterativeBytesPerPoint = 2 * (3 * 4 + 2 * 8 + 2 * 4 * 8);

/**
 * Ends vtkStreamSurface's iterative loop before it passes the memory or work
 * budget. The loop rebuilds the whole surface once a step (a ModifiedEvent on
 * the filter's output) and reads its MaximumNumberOfSteps on every pass, so
 * setting that to 0 stops it after the step just done; Message says why.
 */
struct IterativeSurfaceGuard
{
  std::string Message;
  int Steps = 0;
  double Seeds = 0;
  double CopiedPoints = 0;  // every direction so far
  double EarlierPoints = 0; // surfaces of the directions already traced
  double LastPoints = 0;
  int StepsDone = 0;
  vtkStreamSurface* Surface = nullptr;

  void Watch(vtkStreamSurface* surface, int steps)
  {
    this->EarlierPoints += this->LastPoints;
    this->LastPoints = 0;
    this->StepsDone = 0;
    this->Steps = steps;
    this->Surface = surface;
    surface->GetOutput()->AddObserver(vtkCommand::ModifiedEvent, this, &IterativeSurfaceGuard::OnModified);
  }

  void OnModified(vtkObject* caller, unsigned long, void*)
  {
    auto* surface = vtkPolyData::SafeDownCast(caller);
    const double points = surface ? static_cast<double>(surface->GetNumberOfPoints()) : 0;
    if (!this->Message.empty() || points == this->LastPoints)
    {
      return;
    }
    const double strip = std::max(0.0, points - this->LastPoints);
    this->LastPoints = points;
    this->CopiedPoints += points;
    ++this->StepsDone;
    // the next step: the front (half the strip's points) may double
    const double next = points + 2 * strip;
    std::ostringstream what;
    what << "the next step of the iterative stream surface (iterative_seeding; grown to " << Num(points)
         << " points, a front of about " << Num(std::round(strip / 2)) << " seeds from the " << Num(this->Seeds)
         << " given, after " << this->StepsDone << " of " << this->Steps << " steps)";
    this->Message = vtkPlumeInputValidation::CheckMemory(
      (this->EarlierPoints + next) * kIterativeBytesPerPoint, what.str());
    if (this->Message.empty())
    {
      this->Message =
        vtkPlumeInputValidation::CheckWork((this->CopiedPoints + next) * kCopyOperations, what.str());
    }
    if (!this->Message.empty() && this->Surface)
    {
      this->Surface->SetMaximumNumberOfSteps(0); // ends the loop after this step
    }
  }
};

/** |array| as a new one-component array named "|name|" (contours of a vector's magnitude). */
vtkSmartPointer<vtkDataArray> Magnitude(vtkDataArray* array)
{
  vtkNew<vtkDoubleArray> out;
  out->SetName(("|" + std::string(array->GetName()) + "|").c_str());
  out->SetNumberOfTuples(array->GetNumberOfTuples());
  const int nc = array->GetNumberOfComponents();
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    double sum = 0;
    for (int c = 0; c < nc; ++c)
    {
      const double x = array->GetComponent(i, c);
      sum += x * x;
    }
    out->SetValue(i, std::sqrt(sum));
  }
  return out;
}
}

const vtkPlumeParameterTable& vtkPlumeDerivedGeometry::GetParameterTable()
{
  static const vtkPlumeParameterTable table = [] {
    using T = vtkPlumeDerivedGeometry;
    vtkPlumeParameterTable t("vtkPlumeDerivedGeometry", "derived");
    t.Choice("source", "Operation", "contour")
      .Doc("What is derived from the `input` dataset.")
      .Choice("contour", CONTOUR, "isosurfaces of `array` at `values` (vtkContourFilter)")
      .Choice("slice", SLICE, "the cut by the plane `origin`/`normal` (vtkCutter)")
      .Choice("streamlines", STREAMLINES, "streamlines (vtkStreamTracer, RK4) from the seed line or plane, or `seeds`")
      .Choice("stream_surface", STREAM_SURFACE, "a stream surface from the seed line (vtkStreamSurface)")
      .Choice("ribbon", RIBBON, "streamlines widened into ribbons of `ribbon_width` (vtkRibbonFilter)")
      .Choice("threshold", THRESHOLD, "the cells whose `array` lies in `values` [lower, upper] (vtkThreshold)")
      .Choice("clip", CLIP, "the half on the `normal`'s side of the plane `origin`/`normal` (vtkTableBasedClipDataSet)")
      .Bind(&T::SetOperation, &T::GetOperation);
    t.Text("array", "ArrayName", "")
      .Doc("Scalar array (point or cell) of contour and threshold; a vector is taken by magnitude; empty: the "
           "active scalars, else the first one-component array.")
      .Bind(&T::SetArrayName, &T::GetArrayName);
    t.Text("vectors", "VectorArrayName", "")
      .Doc("Vector array of streamlines, stream_surface and ribbon; empty: the active vectors, else the first "
           "3-component array.")
      .Bind(&T::SetVectorArrayName, &T::GetVectorArrayName);
    t.Choice("coordinates", "Coordinates", "relative")
      .Doc("How `origin` and the seed points are given.")
      .Choice("relative", RELATIVE, "fractions of the input's bounds (0 = minimum, 1 = maximum on each axis)")
      .Choice("world", WORLD, "model coordinates")
      .Bind(&T::SetCoordinates, &T::GetCoordinates);
    t.Vector3("origin", "Origin", { 0.5, 0.5, 0.5 })
      .Doc("A point of the slice or clip plane (default: the centre).")
      .Bind(&T::SetOrigin, &T::GetOrigin);
    t.Vector3("normal", "Normal", { 1, 0, 0 })
      .Doc("Normal of the slice or clip plane (not zero).")
      .Bind(&T::SetNormal, &T::GetNormal);
    t.Vector3("seed_point1", "SeedPoint1", { 0.5, 0.1, 0.5 })
      .Doc("First end of the seed line (default: across the centre along y).")
      .Bind(&T::SetSeedPoint1, &T::GetSeedPoint1);
    t.Vector3("seed_point2", "SeedPoint2", { 0.5, 0.9, 0.5 })
      .Doc("Second end of the seed line.")
      .Bind(&T::SetSeedPoint2, &T::GetSeedPoint2);
    t.Integer("seed_resolution", "SeedResolution", 20)
      .Between(1, 100000)
      .Doc("Segments of the seed line (seeds: one more).")
      .Bind(&T::SetSeedResolution, &T::GetSeedResolution);
    t.Choice("seed_type", "SeedType", "line")
      .Doc("Where streamlines and ribbons start without `seeds`.")
      .Choice("line", SEED_LINE, "`seed_resolution` + 1 seeds from `seed_point1` to `seed_point2`")
      .Choice("plane", SEED_PLANE,
        "a lattice on the parallelogram with corner `seed_point1` and sides to `seed_point2` "
        "(`seed_resolution` segments) and `seed_point3` (`seed_resolution2` segments)")
      .Bind(&T::SetSeedType, &T::GetSeedType);
    t.Vector3("seed_point3", "SeedPoint3", { 0.5, 0.1, 0.9 })
      .Doc("Plane seeds: end of the second side from `seed_point1`.")
      .Bind(&T::SetSeedPoint3, &T::GetSeedPoint3);
    t.Integer("seed_resolution2", "SeedResolution2", 10)
      .Between(1, 100000)
      .Doc("Plane seeds: segments along the second side (seeds: one more).")
      .Bind(&T::SetSeedResolution2, &T::GetSeedResolution2);
    t.Choice("direction", "IntegrationDirection", "both")
      .Doc("Direction streamlines and stream surfaces are traced in.")
      .Choice("forward", FORWARD, "along the flow")
      .Choice("backward", BACKWARD, "against the flow")
      .Choice("both", BOTH, "both ways from each seed")
      .Bind(&T::SetIntegrationDirection, &T::GetIntegrationDirection);
    t.Real("maximum_length", "MaximumLength", 0.0)
      .Between(0.0, 1e30)
      .Units("model units")
      .Doc("Longest streamline; 0: the diagonal of the input's bounds.")
      .Bind(&T::SetMaximumLength, &T::GetMaximumLength);
    t.Real("step", "StepLength", 0.25)
      .Between(0.001, 100.0)
      .Units("cell lengths")
      .Doc("Integration step of streamlines and stream surfaces.")
      .Bind(&T::SetStepLength, &T::GetStepLength);
    t.Real("terminal_speed", "TerminalSpeed", 1e-12)
      .Between(0.0, 1e30)
      .Doc("Streamlines stop below this speed.")
      .Bind(&T::SetTerminalSpeed, &T::GetTerminalSpeed);
    t.Real("ribbon_width", "RibbonWidth", 0.0)
      .Between(0.0, 1e30)
      .Units("model units")
      .Doc("Full width of ribbons; 0: 1 % of the diagonal of the input's bounds.")
      .Bind(&T::SetRibbonWidth, &T::GetRibbonWidth);
    t.Boolean("iterative_seeding", "IterativeSeeding", false)
      .Doc("vtkStreamSurface's iterative version: adds seeds where the surface spreads (better surface, slower: "
           "refused, or stopped while tracing, with an error once it would pass the memory or work budget).")
      .Bind(&T::SetIterativeSeeding, &T::GetIterativeSeeding);
    t.Boolean("inside_out", "InsideOut", false)
      .Doc("Clip: keep the half against the normal instead.")
      .Bind(&T::SetInsideOut, &T::GetInsideOut);
    return t;
  }();
  return table;
}

vtkPlumeDerivedGeometry::vtkPlumeDerivedGeometry()
{
  this->SetNumberOfInputPorts(2);
  GetParameterTable().ApplyDefaults(this);
}

vtkPlumeDerivedGeometry::~vtkPlumeDerivedGeometry()
{
  this->SetArrayName(nullptr);
  this->SetVectorArrayName(nullptr);
}

void vtkPlumeDerivedGeometry::SetValues(const std::vector<double>& values)
{
  if (values != this->Values)
  {
    this->Values = values;
    this->Modified();
  }
}

int vtkPlumeDerivedGeometry::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkPlumeDerivedGeometry::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Every input whole: the executive would otherwise pass the dataset's
  // structured extent on to structured seeds of another size (an error
  // "outside the whole extent" for an image of seed points).
  for (int port = 0; port < this->GetNumberOfInputPorts(); ++port)
  {
    for (int i = 0; i < inputVector[port]->GetNumberOfInformationObjects(); ++i)
    {
      vtkInformation* info = inputVector[port]->GetInformationObject(i);
      if (info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
      {
        info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
          info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
      }
    }
  }
  return 1;
}

int vtkPlumeDerivedGeometry::RequestDataObject(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const bool grid = this->Operation == THRESHOLD || this->Operation == CLIP;
  vtkInformation* info = outputVector->GetInformationObject(0);
  vtkDataObject* output = info->Get(vtkDataObject::DATA_OBJECT());
  if (!output || (grid ? !vtkUnstructuredGrid::SafeDownCast(output) : !vtkPolyData::SafeDownCast(output)))
  {
    vtkSmartPointer<vtkDataObject> made;
    if (grid)
    {
      made = vtkSmartPointer<vtkUnstructuredGrid>::New();
    }
    else
    {
      made = vtkSmartPointer<vtkPolyData>::New();
    }
    info->Set(vtkDataObject::DATA_OBJECT(), made);
  }
  return 1;
}

std::string vtkPlumeDerivedGeometry::CheckContourWork(vtkIdType cells, size_t values)
{
  // Every cell is visited once per value. Memory has no useful bound before
  // the filter (most cells are not cut), so it is checked after.
  std::ostringstream what;
  what << "the contour of " << cells << " cells at " << values << " values";
  return vtkPlumeInputValidation::CheckWork(static_cast<double>(cells) * static_cast<double>(values), what.str());
}

double vtkPlumeDerivedGeometry::Median(vtkDataArray* array, vtkDataArray* mask)
{
  std::vector<double> values;
  values.reserve(static_cast<size_t>(array->GetNumberOfTuples()));
  const int nc = array->GetNumberOfComponents();
  const bool useMask = mask && mask->GetNumberOfTuples() == array->GetNumberOfTuples();
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    if (useMask && mask->GetComponent(i, 0) == 0)
    {
      continue;
    }
    double x = 0;
    if (nc == 1)
    {
      x = array->GetComponent(i, 0);
    }
    else
    {
      for (int c = 0; c < nc; ++c)
      {
        x += array->GetComponent(i, c) * array->GetComponent(i, c);
      }
      x = std::sqrt(x);
    }
    if (std::isfinite(x))
    {
      values.push_back(x);
    }
  }
  if (values.empty())
  {
    return std::nan("");
  }
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  return values[mid];
}

int vtkPlumeDerivedGeometry::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->LastError.clear();
  this->UsedValues.clear();
  this->UsedArrayName.clear();
  this->UsedCellData = false;
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0], 0);
  vtkDataSet* seeds = inputVector[1]->GetNumberOfInformationObjects() > 0 ? vtkDataSet::GetData(inputVector[1], 0) : nullptr;
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  if (!input || !output)
  {
    this->LastError = "no input dataset";
    return 0;
  }
  this->Estimate.clear();
  if (!this->Derive(input, seeds, output))
  {
    output->Initialize();
    return 0;
  }
  // What the filter made, against the memory budget: VTK's filters have no
  // bound of their own, and the renderers copy the result again.
  auto* result = vtkDataSet::SafeDownCast(output);
  if (result)
  {
    std::ostringstream what;
    what << OperationKeys[this->Operation] << ": the result's " << result->GetNumberOfCells() << " cells and "
         << result->GetNumberOfPoints() << " points";
    if (!this->Estimate.empty())
    {
      what << " (estimated before the filter: " << this->Estimate << ")";
    }
    const std::string tooBig =
      vtkPlumeInputValidation::CheckMemory(1024.0 * static_cast<double>(result->GetActualMemorySize()), what.str());
    if (!tooBig.empty())
    {
      this->LastError = tooBig;
      output->Initialize();
      return 0;
    }
  }
  return 1;
}

bool vtkPlumeDerivedGeometry::Derive(vtkDataSet* input, vtkDataSet* seeds, vtkDataObject* output)
{
  const std::string operation = OperationKeys[this->Operation];
  auto fail = [this, &operation](const std::string& why) {
    this->LastError = operation + ": " + why;
    return false;
  };
  if (input->GetNumberOfPoints() < 1 || input->GetNumberOfCells() < 1)
  {
    return fail("the input has no cells");
  }
  double bounds[6];
  input->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) + (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  // relative coordinates are fractions of the bounds
  auto place = [this, &bounds](const double in[3], double out[3]) {
    for (int a = 0; a < 3; ++a)
    {
      out[a] = this->Coordinates == RELATIVE ? bounds[2 * a] + in[a] * (bounds[2 * a + 1] - bounds[2 * a]) : in[a];
    }
  };
  const std::string coordinatesNote =
    this->Coordinates == RELATIVE ? " (relative: fractions of the bounds; 'coordinates': \"world\" for model coordinates)" : "";
  auto inside = [&bounds, diagonal](const double p[3]) {
    const double tolerance = 1e-6 * diagonal;
    for (int a = 0; a < 3; ++a)
    {
      if (!(p[a] >= bounds[2 * a] - tolerance && p[a] <= bounds[2 * a + 1] + tolerance))
      {
        return false;
      }
    }
    return true;
  };
  std::ostringstream boundsText;
  boundsText << "[" << bounds[0] << ", " << bounds[1] << ", " << bounds[2] << ", " << bounds[3] << ", " << bounds[4]
             << ", " << bounds[5] << "]";

  const bool scalarOperation = this->Operation == CONTOUR || this->Operation == THRESHOLD;
  const bool flowOperation =
    this->Operation == STREAMLINES || this->Operation == STREAM_SURFACE || this->Operation == RIBBON;

  // the array the operation works on
  vtkSmartPointer<vtkDataSet> data = input;
  bool cell = false;
  vtkDataArray* array = nullptr;
  if (scalarOperation || flowOperation)
  {
    const std::string key = scalarOperation ? "array" : "vectors";
    const char* given = scalarOperation ? this->ArrayName : this->VectorArrayName;
    if (given && *given)
    {
      array = FindArray(input, given, cell, this->Operation == THRESHOLD);
      if (!array)
      {
        return fail("parameter '" + key + "': no array '" + given + "' in the input (" + ListArrays(input) + ")");
      }
    }
    else
    {
      array = DefaultArray(input, flowOperation, cell);
      if (!array)
      {
        return fail(std::string("the input has no ") + (flowOperation ? "3-component (vector)" : "scalar") +
          " array to use (" + ListArrays(input) + ")");
      }
    }
    if (flowOperation && array->GetNumberOfComponents() != 3)
    {
      return fail("parameter 'vectors': array '" + std::string(array->GetName()) + "' has " +
        std::to_string(array->GetNumberOfComponents()) + " components, not 3");
    }
    this->UsedArrayName = array->GetName();
  }
  // Cell arrays: threshold uses them as they are (no boundary values interpolated
  // in); the others need point values, so every cell array is interpolated.
  if (this->Operation != THRESHOLD && input->GetCellData()->GetNumberOfArrays() > 0 &&
    (cell || (!scalarOperation && !flowOperation)))
  {
    vtkNew<vtkCellDataToPointData> toPoints;
    toPoints->SetInputData(input);
    toPoints->PassCellDataOn();
    toPoints->ProcessAllArraysOn();
    toPoints->Update();
    data = toPoints->GetOutput();
    if (array)
    {
      array = data->GetPointData()->GetArray(array->GetName());
      cell = false;
    }
  }
  std::string arrayName = array ? array->GetName() : "";
  if (scalarOperation && array->GetNumberOfComponents() != 1)
  {
    // the magnitude of a vector, as a new array of the same association
    vtkSmartPointer<vtkDataSet> copy;
    copy.TakeReference(data->NewInstance());
    copy->ShallowCopy(data);
    vtkSmartPointer<vtkDataArray> magnitude = Magnitude(array);
    (cell ? static_cast<vtkDataSetAttributes*>(copy->GetCellData())
          : static_cast<vtkDataSetAttributes*>(copy->GetPointData()))
      ->AddArray(magnitude);
    data = copy;
    array = magnitude;
    arrayName = magnitude->GetName();
  }
  this->UsedArrayName = arrayName;
  this->UsedCellData = cell;
  const int association = cell ? vtkDataObject::FIELD_ASSOCIATION_CELLS : vtkDataObject::FIELD_ASSOCIATION_POINTS;

  if (scalarOperation)
  {
    vtkDataArray* mask = cell ? nullptr : data->GetPointData()->GetArray("vtkValidPointMask");
    double range[2];
    array->GetRange(range, -1);
    this->UsedValues = this->Values;
    if (this->UsedValues.empty())
    {
      const double median = Median(array, mask);
      if (!std::isfinite(median))
      {
        return fail("parameter 'array': '" + arrayName + "' has no finite values");
      }
      this->UsedValues.push_back(median);
    }
    for (double v : this->UsedValues)
    {
      if (!std::isfinite(v))
      {
        return fail("parameter 'values': " + Num(v) + " is not a finite number");
      }
    }
    if (this->Operation == THRESHOLD && this->UsedValues.size() > 2)
    {
      return fail("parameter 'values': give [lower] or [lower, upper], got " +
        std::to_string(this->UsedValues.size()) + " values");
    }
    if (this->Operation == THRESHOLD && this->UsedValues.size() == 2 && this->UsedValues[0] > this->UsedValues[1])
    {
      return fail("parameter 'values': lower " + Num(this->UsedValues[0]) + " is above upper " +
        Num(this->UsedValues[1]));
    }
    if (this->Operation == CONTOUR)
    {
      const std::string tooMuch = CheckContourWork(data->GetNumberOfCells(), this->UsedValues.size());
      if (!tooMuch.empty())
      {
        return fail(tooMuch);
      }
      const double visits =
        static_cast<double>(data->GetNumberOfCells()) * static_cast<double>(this->UsedValues.size());
      this->Estimate = "at most " + Num(5 * visits) + " triangles, 5 per cell and value";
      vtkNew<vtkContourFilter> contour;
      contour->SetInputData(data);
      contour->SetInputArrayToProcess(0, 0, 0, association, arrayName.c_str());
      for (size_t i = 0; i < this->UsedValues.size(); ++i)
      {
        contour->SetValue(static_cast<int>(i), this->UsedValues[i]);
      }
      contour->ComputeScalarsOn();
      contour->ComputeNormalsOn();
      contour->Update();
      if (contour->GetOutput()->GetNumberOfCells() == 0)
      {
        std::string values;
        for (double v : this->UsedValues)
        {
          values += (values.empty() ? "" : ", ") + Num(v);
        }
        return fail("parameter 'values': the contour of '" + arrayName + "' at [" + values +
          "] is empty (its values range over [" + Num(range[0]) + ", " + Num(range[1]) + "])");
      }
      output->ShallowCopy(contour->GetOutput());
      return true;
    }
    vtkNew<vtkThreshold> threshold;
    threshold->SetInputData(data);
    threshold->SetInputArrayToProcess(0, 0, 0, association, arrayName.c_str());
    threshold->SetLowerThreshold(this->UsedValues[0]);
    threshold->SetUpperThreshold(this->UsedValues.size() > 1 ? this->UsedValues[1] : VTK_DOUBLE_MAX);
    threshold->SetThresholdFunction(vtkThreshold::THRESHOLD_BETWEEN);
    threshold->Update();
    if (threshold->GetOutput()->GetNumberOfCells() == 0)
    {
      return fail("parameter 'values': no cell of '" + arrayName + "' lies in [" + Num(this->UsedValues[0]) + ", " +
        (this->UsedValues.size() > 1 ? Num(this->UsedValues[1]) : std::string("inf")) + "] (its values range over [" +
        Num(range[0]) + ", " + Num(range[1]) + "])");
    }
    output->ShallowCopy(threshold->GetOutput());
    return true;
  }

  if (this->Operation == SLICE || this->Operation == CLIP)
  {
    if (!(vtkMath::Norm(this->Normal) > 0))
    {
      return fail("parameter 'normal' " + Vec(this->Normal) + " is zero: a plane needs a direction");
    }
    double origin[3];
    place(this->Origin, origin);
    if (!inside(origin))
    {
      return fail("parameter 'origin' " + Vec(this->Origin) + " lies outside the input's bounds " +
        boundsText.str() + coordinatesNote);
    }
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(origin);
    plane->SetNormal(this->Normal);
    if (this->Operation == SLICE)
    {
      vtkNew<vtkCutter> cutter;
      cutter->SetInputData(data);
      cutter->SetCutFunction(plane);
      cutter->Update();
      if (cutter->GetOutput()->GetNumberOfCells() == 0)
      {
        return fail("the plane through " + Vec(origin) + " with normal " + Vec(this->Normal) + " cuts no cell");
      }
      output->ShallowCopy(cutter->GetOutput());
      return true;
    }
    vtkNew<vtkTableBasedClipDataSet> clip;
    clip->SetInputData(data);
    clip->SetClipFunction(plane);
    clip->SetInsideOut(this->InsideOut);
    clip->Update();
    if (clip->GetOutput()->GetNumberOfCells() == 0)
    {
      return fail("the plane through " + Vec(origin) + " with normal " + Vec(this->Normal) +
        " leaves no cell on the kept side (inside_out " + (this->InsideOut ? "true" : "false") + ")");
    }
    output->ShallowCopy(clip->GetOutput());
    return true;
  }

  // streamlines, stream surface, ribbon
  vtkSmartPointer<vtkDataSet> seedData = seeds;
  double p1[3], p2[3];
  place(this->SeedPoint1, p1);
  place(this->SeedPoint2, p2);
  if (!seedData)
  {
    if (!inside(p1))
    {
      return fail("parameter 'seed_point1' " + Vec(this->SeedPoint1) + " lies outside the input's bounds " +
        boundsText.str() + coordinatesNote);
    }
    if (!inside(p2))
    {
      return fail("parameter 'seed_point2' " + Vec(this->SeedPoint2) + " lies outside the input's bounds " +
        boundsText.str() + coordinatesNote);
    }
    if (this->Operation == STREAM_SURFACE && !(std::sqrt(vtkMath::Distance2BetweenPoints(p1, p2)) > 0))
    {
      return fail("parameters 'seed_point1' and 'seed_point2' are the same point " + Vec(p1) +
        ": a stream surface needs a seed line");
    }
    if (this->SeedType == SEED_PLANE)
    {
      if (this->Operation == STREAM_SURFACE)
      {
        return fail("parameter 'seed_type' \"plane\": a stream surface grows from a seed line (\"line\")");
      }
      double p3[3];
      place(this->SeedPoint3, p3);
      if (!inside(p3))
      {
        return fail("parameter 'seed_point3' " + Vec(this->SeedPoint3) + " lies outside the input's bounds " +
          boundsText.str() + coordinatesNote);
      }
      // the two sides must span a plane (vtkPlaneSource would silently fail)
      const glm::dvec3 side1 = glm::dvec3(p2[0], p2[1], p2[2]) - glm::dvec3(p1[0], p1[1], p1[2]);
      const glm::dvec3 side2 = glm::dvec3(p3[0], p3[1], p3[2]) - glm::dvec3(p1[0], p1[1], p1[2]);
      if (!(glm::length(glm::cross(side1, side2)) > 1e-12 * diagonal * diagonal))
      {
        return fail("parameters 'seed_point1' " + Vec(this->SeedPoint1) + ", 'seed_point2' " +
          Vec(this->SeedPoint2) + " and 'seed_point3' " + Vec(this->SeedPoint3) +
          " lie on one line: plane seeds need two sides");
      }
      vtkNew<vtkPlaneSource> plane;
      plane->SetOrigin(p1);
      plane->SetPoint1(p2);
      plane->SetPoint2(p3);
      plane->SetResolution(this->SeedResolution, this->SeedResolution2);
      plane->Update();
      seedData = plane->GetOutput();
    }
    else
    {
      vtkNew<vtkLineSource> line;
      line->SetPoint1(p1);
      line->SetPoint2(p2);
      line->SetResolution(this->SeedResolution);
      line->Update();
      seedData = line->GetOutput();
    }
  }
  else if (seedData->GetNumberOfPoints() < (this->Operation == STREAM_SURFACE ? 2 : 1))
  {
    return fail("the seeds dataset has " + std::to_string(seedData->GetNumberOfPoints()) + " points");
  }
  else if (!vtkPolyData::SafeDownCast(seedData))
  {
    // Only the seeds' points matter. Structured seeds (an image, a grid) on the
    // tracer's source port get the input's update extent requested of them,
    // which VTK reports as errors ("outside the whole extent"): pass the points.
    vtkNew<vtkPolyData> points;
    vtkNew<vtkPoints> copy;
    copy->SetDataTypeToDouble();
    copy->SetNumberOfPoints(seedData->GetNumberOfPoints());
    for (vtkIdType i = 0; i < seedData->GetNumberOfPoints(); ++i)
    {
      copy->SetPoint(i, seedData->GetPoint(i));
    }
    points->SetPoints(copy);
    seedData = points;
  }
  const double length = this->MaximumLength > 0 ? this->MaximumLength : diagonal;
  // Steps to reach the length with cells of the mean size. vtkStreamSurface also
  // resamples every streamline to this many points (its ruled surface), so the
  // default 2000 made 1.6 M points on the office.
  const double meanCell = std::cbrt(std::max(1e-300, (bounds[1] - bounds[0]) * (bounds[3] - bounds[2]) *
                                      std::max(bounds[5] - bounds[4], 1e-6 * diagonal) /
                                      std::max<vtkIdType>(1, data->GetNumberOfCells())));
  const int maximumSteps = static_cast<int>(
    std::min(std::max(std::ceil(length / (this->StepLength * meanCell)), 10.0), 20000.0));
  {
    // Bound the result before tracing: at most seeds x steps x directions points
    // (a stream surface resamples every line to exactly `steps` points; a ribbon
    // doubles them), each with its coordinates, the interpolated point arrays and
    // about two triangles' connectivity. Iterative seeding may add seeds; the
    // check after the filter catches what it adds.
    const double seedCount = static_cast<double>(seedData->GetNumberOfPoints());
    const double directions = this->IntegrationDirection == BOTH ? 2 : 1;
    const double points = seedCount * maximumSteps * directions * (this->Operation == RIBBON ? 2 : 1);
    double bytesPerPoint = 3 * sizeof(float) + 8.0 * sizeof(vtkIdType);
    for (int i = 0; i < data->GetPointData()->GetNumberOfArrays(); ++i)
    {
      if (vtkDataArray* a = data->GetPointData()->GetArray(i))
      {
        bytesPerPoint += a->GetNumberOfComponents() * a->GetDataTypeSize();
      }
    }
    std::ostringstream what;
    what << "the lines traced from " << seedData->GetNumberOfPoints() << " seeds x " << maximumSteps
         << " steps (maximum_length / step_length) x " << directions << " directions (" << Num(points)
         << " points)";
    std::string tooMuch = vtkPlumeInputValidation::CheckMemory(points * bytesPerPoint, what.str());
    if (tooMuch.empty())
    {
      tooMuch = vtkPlumeInputValidation::CheckWork(seedCount * maximumSteps * directions, what.str());
    }
    if (tooMuch.empty() && this->Operation == STREAM_SURFACE && this->IterativeSeeding)
    {
      // vtkStreamSurface's iterative version appends each step's strip to a
      // copy of the whole surface so far: seeds x steps^2 point copies per
      // direction even when it adds no seed (measured: about 4 us a copied
      // point, so each counts as kCopyOperations)
      std::ostringstream iterative;
      iterative << "the iterative stream surface (iterative_seeding) from " << seedData->GetNumberOfPoints()
                << " seeds x " << maximumSteps << " steps x " << directions
                << " directions, which copies its whole surface once a step (" << Num(points * maximumSteps)
                << " point copies before it adds any seed)";
      tooMuch = vtkPlumeInputValidation::CheckWork(points * maximumSteps * kCopyOperations, iterative.str());
    }
    if (!tooMuch.empty())
    {
      return fail(tooMuch);
    }
    this->Estimate = "at most " + Num(points) + " points";
  }
  // The iterative version adds seeds where the front spreads (it may double
  // every step) and VTK 9.1 gives it no abort hook: watch the surface it
  // rebuilds once a step (its output's ModifiedEvent) and end the loop (its
  // step count, read on every pass) once the next step would pass a budget.
  IterativeSurfaceGuard guard;
  guard.Seeds = static_cast<double>(seedData->GetNumberOfPoints());
  auto makeTracer = [&](int direction) {
    vtkSmartPointer<vtkStreamTracer> tracer;
    if (this->Operation == STREAM_SURFACE)
    {
      auto surface = vtkSmartPointer<vtkStreamSurface>::New();
      surface->SetUseIterativeSeeding(this->IterativeSeeding);
      if (this->IterativeSeeding)
      {
        guard.Watch(surface, maximumSteps);
      }
      tracer = surface;
    }
    else
    {
      tracer = vtkSmartPointer<vtkStreamTracer>::New();
    }
    tracer->SetInputData(data);
    tracer->SetSourceData(seedData);
    tracer->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, arrayName.c_str());
    tracer->SetIntegratorTypeToRungeKutta4();
    tracer->SetIntegrationStepUnit(vtkStreamTracer::CELL_LENGTH_UNIT);
    tracer->SetInitialIntegrationStep(this->StepLength);
    tracer->SetMaximumPropagation(length);
    tracer->SetMaximumNumberOfSteps(maximumSteps);
    tracer->SetTerminalSpeed(this->TerminalSpeed);
    tracer->SetIntegrationDirection(direction);
    tracer->SetComputeVorticity(this->Operation == RIBBON);
    if (guard.Message.empty())
    {
      tracer->Update();
    }
    return tracer;
  };
  vtkSmartPointer<vtkPolyData> tracedData;
  if (this->Operation == STREAM_SURFACE && this->IntegrationDirection == BOTH)
  {
    // the ruled surface joins consecutive lines: trace each way on its own
    vtkNew<vtkAppendPolyData> append;
    for (int direction : { vtkStreamTracer::FORWARD, vtkStreamTracer::BACKWARD })
    {
      auto tracer = makeTracer(direction);
      auto* part = vtkPolyData::SafeDownCast(tracer->GetOutputDataObject(0));
      if (part && part->GetNumberOfCells() > 0)
      {
        vtkNew<vtkPolyData> copy;
        copy->ShallowCopy(part);
        append->AddInputData(copy);
      }
    }
    if (append->GetNumberOfInputConnections(0) > 0)
    {
      append->Update();
      tracedData = append->GetOutput();
    }
  }
  else
  {
    auto tracer = makeTracer(this->IntegrationDirection == FORWARD ? vtkStreamTracer::FORWARD
        : this->IntegrationDirection == BACKWARD                   ? vtkStreamTracer::BACKWARD
                                                                   : vtkStreamTracer::BOTH);
    tracedData = vtkPolyData::SafeDownCast(tracer->GetOutputDataObject(0));
  }
  if (!guard.Message.empty())
  {
    return fail(guard.Message + "; set iterative_seeding false, a larger step or a shorter maximum_length");
  }
  vtkPolyData* traced = tracedData;
  const std::string seedText = seeds ? "the seeds dataset (" + std::to_string(seeds->GetNumberOfPoints()) + " points)"
    : this->SeedType == SEED_PLANE ? "the seed plane at " + Vec(p1) + " (" + std::to_string(seedData->GetNumberOfPoints()) + " seeds)"
                                   : "the seed line " + Vec(p1) + " - " + Vec(p2);
  if (!traced || traced->GetNumberOfCells() == 0 ||
    (this->Operation == STREAM_SURFACE && traced->GetNumberOfPolys() + traced->GetNumberOfStrips() == 0))
  {
    return fail("nothing traced from " + seedText + " through '" + arrayName +
      "': the seeds lie outside the data or where the flow is slower than terminal_speed " + Num(this->TerminalSpeed));
  }
  if (this->Operation == RIBBON)
  {
    vtkNew<vtkRibbonFilter> ribbon;
    ribbon->SetInputData(traced);
    ribbon->SetWidth(0.5 * (this->RibbonWidth > 0 ? this->RibbonWidth : 0.01 * diagonal)); // half width
    ribbon->Update();
    if (ribbon->GetOutput()->GetNumberOfCells() == 0)
    {
      return fail("the streamlines from " + seedText + " are too short to make ribbons");
    }
    output->ShallowCopy(ribbon->GetOutput());
    return true;
  }
  output->ShallowCopy(traced);
  return true;
}

void vtkPlumeDerivedGeometry::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Operation: " << OperationKeys[this->Operation] << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "") << "\n";
  os << indent << "VectorArrayName: " << (this->VectorArrayName ? this->VectorArrayName : "") << "\n";
  os << indent << "Coordinates: " << (this->Coordinates == RELATIVE ? "relative" : "world") << "\n";
  os << indent << "Origin: " << Vec(this->Origin) << "\n";
  os << indent << "Normal: " << Vec(this->Normal) << "\n";
  os << indent << "SeedPoint1: " << Vec(this->SeedPoint1) << "\n";
  os << indent << "SeedPoint2: " << Vec(this->SeedPoint2) << "\n";
  os << indent << "SeedResolution: " << this->SeedResolution << "\n";
  os << indent << "SeedType: " << (this->SeedType == SEED_PLANE ? "plane" : "line") << "\n";
  os << indent << "SeedPoint3: " << Vec(this->SeedPoint3) << "\n";
  os << indent << "SeedResolution2: " << this->SeedResolution2 << "\n";
  os << indent << "IntegrationDirection: " << this->IntegrationDirection << "\n";
  os << indent << "MaximumLength: " << this->MaximumLength << "\n";
  os << indent << "StepLength: " << this->StepLength << "\n";
  os << indent << "TerminalSpeed: " << this->TerminalSpeed << "\n";
  os << indent << "RibbonWidth: " << this->RibbonWidth << "\n";
  os << indent << "IterativeSeeding: " << this->IterativeSeeding << "\n";
  os << indent << "InsideOut: " << this->InsideOut << "\n";
  os << indent << "Values: " << this->Values.size() << "\n";
}
