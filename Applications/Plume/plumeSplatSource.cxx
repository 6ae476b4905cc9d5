// The scene dataset `"source": "splat"`: a field splatted from flow lines
// given in the scene (a list of points, a circle) or taken from another
// dataset's polylines (e.g. a .vtp of streamlines), or from streamlines
// traced here through another dataset (`trace`), by
// vtkPlumeGaussianSplatter (seed 002's flowline extrusion). The result is an
// image with the splatted array ("velocity", "density" or "distance") and,
// for velocity, "speed" = |v|, ready for the glyphs, contour or volume
// representations. Documented in Documentation/SceneFormat.md.
#include "plumeParameters.h"
#include "plumeScene.h"
#include "plumeSceneError.h"

#include "vtkPlumeGaussianSplatter.h"
#include "vtkPlumeParameterTable.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkStreamTracer.h"
#include "vtkXMLImageDataWriter.h"

#include <cmath>
#include <sstream>

namespace plume
{
namespace
{
std::string Num(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

// A list of [x, y, z] points, each finite.
vtkSmartPointer<vtkPolyData> PolylineFromJson(const nlohmann::json& list, bool closed, const std::string& where)
{
  if (!list.is_array() || list.empty())
  {
    throw SceneError(where + ": 'points' must be a non-empty list of [x, y, z], got " + list.dump());
  }
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const auto& p : list)
  {
    if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number() ||
      !std::isfinite(p[0].get<double>()) || !std::isfinite(p[1].get<double>()) || !std::isfinite(p[2].get<double>()))
    {
      throw SceneError(where + ": 'points' entries must be lists of 3 finite numbers, got " + p.dump());
    }
    pts->InsertNextPoint(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
  }
  vtkNew<vtkCellArray> cells;
  const vtkIdType n = pts->GetNumberOfPoints();
  cells->InsertNextCell(closed && n > 1 ? n + 1 : n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    cells->InsertCellPoint(i);
  }
  if (closed && n > 1)
  {
    cells->InsertCellPoint(0);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(pts);
  poly->SetLines(cells);
  return poly;
}
}

vtkSmartPointer<vtkDataObject> BuildSplatDataset(Parameters& p, SceneDatasets& datasets, const std::string& name)
{
  const std::string where = "datasets." + name;
  const nlohmann::json* points = p.Raw("points");
  const nlohmann::json* circle = p.Object("circle");
  const std::string linesDataset = p.String("lines", "");
  const nlohmann::json* trace = p.Object("trace");
  const std::string reference = p.String("reference", "");
  const std::string save = p.String("save", "");
  const bool closed = p.Boolean("closed", false);
  // the splatter's own parameters (mode, sigma, scale, cutoff, integrate,
  // backend, ...) come from its table: one declaration of their defaults and
  // ranges for scenes, ParaView and the documentation
  vtkNew<vtkPlumeGaussianSplatter> splatter;
  p.Apply(vtkPlumeGaussianSplatter::GetParameterTable(), splatter);
  const auto dims = p.Vector<3>("dimensions", { 32, 32, 32 });
  const bool hasBounds = p.Has("bounds");
  const auto bounds = p.Vector<6>("bounds", { 1, -1, 1, -1, 1, -1 });
  p.RejectUnknown();
  for (double d : dims)
  {
    if (d < 1 || d > 1024 || d != std::floor(d))
    {
      throw SceneError(where + ": 'dimensions' must be integers in [1, 1024], got " + Num(d));
    }
  }
  if (hasBounds && !(bounds[0] < bounds[1] && bounds[2] < bounds[3] && bounds[4] < bounds[5]))
  {
    throw SceneError(where + ": 'bounds' must be [xmin, xmax, ymin, ymax, zmin, zmax] with min < max");
  }
  if (int(points != nullptr) + int(circle != nullptr) + int(!linesDataset.empty()) + int(trace != nullptr) != 1)
  {
    throw SceneError(where + ": a splat source needs exactly one of 'points', 'circle', 'lines' or 'trace'");
  }
  if (linesDataset == name || reference == name)
  {
    throw SceneError(where + ": 'lines' and 'reference' cannot name the splat dataset itself");
  }

  vtkSmartPointer<vtkPolyData> lines;
  if (points)
  {
    lines = PolylineFromJson(*points, closed, where);
  }
  else if (circle)
  {
    Parameters c(*circle, where + ".circle");
    const auto center = c.Vector<3>("center", { 0, 0, 0 });
    const double radius = c.Number("radius", 1.0, 1e-12);
    const int resolution = c.Integer("resolution", 64, 3, 1 << 20);
    c.RejectUnknown();
    nlohmann::json list = nlohmann::json::array();
    for (int i = 0; i < resolution; ++i)
    {
      const double t = 2 * vtkMath::Pi() * i / resolution;
      list.push_back({ center[0] + radius * std::cos(t), center[1] + radius * std::sin(t), center[2] });
    }
    lines = PolylineFromJson(list, true, where);
  }
  else if (trace)
  {
    // streamlines (RK4, both directions) from a rake of seeds on a plane
    Parameters t(*trace, where + ".trace");
    const std::string flow = t.String("dataset", "");
    const std::string vectors = t.String("vectors", "");
    const auto origin = t.Vector<3>("origin", { 0, 0, 0 });
    auto point1 = t.Vector<3>("point1", { 1, 0, 0 });
    auto point2 = t.Vector<3>("point2", { 0, 1, 0 });
    const auto resolution = t.Vector<2>("resolution", { 8, 8 });
    const double maxLength = t.Number("max_length", 100.0, 1e-12);
    const double step = t.Number("step", 0.5, 1e-3, 10.0);
    const double terminalSpeed = t.Number("terminal_speed", 1e-12, 0.0);
    t.RejectUnknown();
    if (flow.empty() || flow == name)
    {
      throw SceneError(where + ".trace: 'dataset' must name another dataset (the flow to trace)");
    }
    for (double r : resolution)
    {
      if (r < 1 || r > 1024 || r != std::floor(r))
      {
        throw SceneError(where + ".trace: 'resolution' must be integers in [1, 1024], got " + Num(r));
      }
    }
    vtkImageData* field = datasets.GetImage(flow, where + ".trace");
    vtkNew<vtkPlaneSource> rake;
    rake->SetOrigin(origin.data());
    rake->SetPoint1(point1.data());
    rake->SetPoint2(point2.data());
    rake->SetResolution(int(resolution[0]), int(resolution[1]));
    vtkNew<vtkStreamTracer> tracer;
    tracer->SetInputData(field);
    tracer->SetSourceConnection(rake->GetOutputPort());
    if (!vectors.empty())
    {
      if (!field->GetPointData()->GetArray(vectors.c_str()))
      {
        throw SceneError(where + ".trace: dataset '" + flow + "' has no point array '" + vectors + "'");
      }
      tracer->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vectors.c_str());
    }
    tracer->SetIntegratorTypeToRungeKutta4();
    tracer->SetIntegrationDirectionToBoth();
    tracer->SetIntegrationStepUnit(vtkStreamTracer::CELL_LENGTH_UNIT);
    tracer->SetInitialIntegrationStep(step); // fixed steps: vertex differences ∝ direction only
    tracer->SetMaximumPropagation(maxLength);
    tracer->SetMaximumNumberOfSteps(100000);
    tracer->SetTerminalSpeed(terminalSpeed); // stagnant regions would pile up vertices
    tracer->Update();
    lines = tracer->GetOutput();
    if (lines->GetNumberOfLines() == 0)
    {
      throw SceneError(where + ".trace: no streamline left the seeds (check the rake lies in the flow)");
    }
  }
  else
  {
    lines = vtkPolyData::SafeDownCast(datasets.Get(linesDataset, where));
    if (!lines || lines->GetNumberOfLines() == 0)
    {
      throw SceneError(where + ": dataset '" + linesDataset + "' has no polylines to splat");
    }
  }

  splatter->SetLinesData(lines);
  splatter->SetDimensions(int(dims[0]), int(dims[1]), int(dims[2]));
  if (hasBounds)
  {
    splatter->SetModelBounds(bounds.data());
  }
  if (!reference.empty())
  {
    splatter->SetReferenceImage(datasets.GetImage(reference, where)); // its grid, not its data
  }
  splatter->Update();
  if (!splatter->GetLastError().empty())
  {
    throw SceneError(where + ": " + splatter->GetLastError());
  }
  vtkSmartPointer<vtkImageData> image = splatter->GetOutput();
  if (splatter->GetMode() == vtkPlumeGaussianSplatter::VECTOR_SUM)
  {
    vtkDataArray* v = image->GetPointData()->GetVectors();
    vtkNew<vtkFloatArray> speed;
    speed->SetName("speed");
    speed->SetNumberOfTuples(v->GetNumberOfTuples());
    for (vtkIdType i = 0; i < v->GetNumberOfTuples(); ++i)
    {
      double t[3];
      v->GetTuple(i, t);
      speed->SetValue(i, static_cast<float>(vtkMath::Norm(t)));
    }
    image->GetPointData()->AddArray(speed);
    image->GetPointData()->SetActiveScalars("speed");
  }
  if (!save.empty())
  {
    // the splatted field as a file, for other tools (relative: to the working directory)
    if (save.find('\0') != std::string::npos)
    {
      throw SceneError(where + ": 'save' path holds a NUL character: '" + std::string(save.c_str()) + "\\u0000...'");
    }
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetFileName(save.c_str());
    writer->SetInputData(image);
    // VTK's writer reports an unwritable path as an error message but still returns 1
    if (writer->Write() != 1 || writer->GetErrorCode() != 0)
    {
      throw SceneError(where + ": could not write 'save' file '" + save + "'");
    }
  }
  return image;
}
}
