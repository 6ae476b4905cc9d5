#include "plumeScene.h"

#include "plumeParameters.h"
#include "plumeProgress.h"
#include "plumeRepresentationHelpers.h"
#include "plumeSceneError.h"

#include "vtkPlumeAirlightPass.h"
#include "vtkPlumeCellCenteredImage.h"
#include "vtkPlumeDatasetReader.h"
#include "vtkPlumeParameterTable.h"
#include "vtkPlumeInputValidation.h"
#include "vtkPlumeResampleToImage.h"
#include "vtkPlumeVortexSource.h"

#include "vtkCamera.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkPointData.h"
#include "vtkPropCollection.h"
#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkImageReader2Factory.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkOutputWindow.h"
#include "vtkPlumeCompositingPass.h"
#include "vtkRenderer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtksys/SystemTools.hxx"

#include <ImfArray.h>
#include <ImfRgbaFile.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <unistd.h>
#include <fstream>
#include <iostream>
#include <sstream>
#include <utility>
#include <vector>

namespace plume
{

void Note(const std::string& line)
{
  vtkOutputWindow::GetInstance()->DisplayText(("plume: " + line + "\n").c_str());
}

double MemoryBudgetBytes()
{
  // Default: half of the physical memory, so one scene cannot exhaust the machine.
  return vtkPlumeInputValidation::MemoryBudgetBytes();
}

nlohmann::json Scene::ReadFile(const std::string& path)
{
  if (vtksys::SystemTools::FileIsDirectory(path))
  {
    throw SceneError("scene file '" + path + "' is a directory");
  }
  // a FIFO or a device would block the open forever or never end
  const std::string notRegular = vtkPlumeInputValidation::CheckRegularFile(path);
  if (!notRegular.empty())
  {
    throw SceneError("scene file: " + notRegular);
  }
  std::ifstream in(path);
  if (!in)
  {
    throw SceneError("cannot open scene file '" + path + "'");
  }
  return Parse(in, "scene file '" + path + "'");
}

nlohmann::json Scene::Parse(std::istream& in, const std::string& what)
{
  // Everything after parsing (dump() in messages, the destructor) recurses per level:
  // thousands of nested levels overflow the stack, and no scene needs more than a few.
  const auto depthCheck = [&what](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
    if (depth > MaximumJsonDepth)
    {
      throw SceneError(what + " nests JSON deeper than " + std::to_string(MaximumJsonDepth) + " levels");
    }
    return true;
  };
  try
  {
    return nlohmann::json::parse(in, depthCheck);
  }
  catch (const nlohmann::json::exception& e)
  {
    // e.what() carries the position, or the offending number (e.g. 1e999 overflows).
    throw SceneError(what + " is not valid JSON: " + e.what());
  }
}

namespace
{
constexpr double BytesPerPixel = 110.0;

/**
 * True when every solution array holds one value: the cell arrays of a
 * finite-volume result (its point arrays are interpolated and carry the
 * boundary values even at an initial condition), else the point arrays.
 */
bool SolutionIsUniform(vtkDataObject* data)
{
  auto* ds = vtkDataSet::SafeDownCast(data);
  if (!ds)
  {
    return false;
  }
  vtkDataSetAttributes* attributes = ds->GetCellData()->GetNumberOfArrays() > 0
    ? static_cast<vtkDataSetAttributes*>(ds->GetCellData())
    : static_cast<vtkDataSetAttributes*>(ds->GetPointData());
  int checked = 0;
  for (int i = 0; i < attributes->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* a = attributes->GetArray(i);
    if (!a || !a->GetName() || std::string(a->GetName()) == "vtkGhostType" ||
      std::string(a->GetName()) == "vtkValidPointMask" || a->GetNumberOfTuples() < 2)
    {
      continue;
    }
    ++checked;
    for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    {
      double r[2];
      a->GetRange(r, c);
      if (r[0] != r[1])
      {
        return false;
      }
    }
  }
  return checked > 0;
}
}

SceneDatasets::SceneDatasets(const nlohmann::json* datasets, std::string sceneDirectory, bool progress, int timeStep)
  : SceneDirectory(std::move(sceneDirectory))
  , Progress(progress)
  , TimeStepOverride(timeStep)
{
  if (!datasets)
  {
    return;
  }
  if (!datasets->is_object())
  {
    throw SceneError("scene: 'datasets' must be an object mapping names to datasets, got " + datasets->dump());
  }
  for (auto it = datasets->begin(); it != datasets->end(); ++it)
  {
    this->Entries[it.key()].Spec = it.value();
  }
}

std::string DataFolder()
{
  const char* env = std::getenv("PLUME_DATA_DIR");
  return (env && *env) ? std::string(env) : std::string(PLUME_DATA_DIR);
}

std::string SceneDatasets::Resolve(const std::string& path) const
{
  if (vtksys::SystemTools::FileIsFullPath(path))
  {
    return path;
  }
  const std::string local = this->SceneDirectory + "/" + path;
  if (vtksys::SystemTools::FileExists(local))
  {
    return local;
  }
  const std::string shared = DataFolder() + "/" + path;
  if (vtksys::SystemTools::FileExists(shared))
  {
    return shared;
  }
  return local; // the reader reports it missing, naming the path
}

namespace
{
/** Whether `attributes` hold an array besides VTK's masks and ghost markers. */
bool HasSolutionArrays(vtkDataSetAttributes* attributes)
{
  for (int i = 0; i < attributes->GetNumberOfArrays(); ++i)
  {
    const char* n = attributes->GetArray(i) ? attributes->GetArray(i)->GetName() : nullptr;
    if (n && std::string(n) != "vtkValidPointMask" && std::string(n) != "vtkGhostType")
    {
      return true;
    }
  }
  return false;
}

/**
 * Whether every point array has a cell array of the same name: the points
 * hold a reader's interpolation of the cells (OpenFOAM's cell-to-point, which
 * gives boundary points their patch's value: a 600 K floor patch under a room
 * at 300 K becomes a 600 K layer of points).
 */
bool PointsInterpolateCells(vtkDataSet* ds)
{
  vtkPointData* points = ds->GetPointData();
  if (!HasSolutionArrays(points) || !HasSolutionArrays(ds->GetCellData()))
  {
    return false;
  }
  for (int i = 0; i < points->GetNumberOfArrays(); ++i)
  {
    const char* n = points->GetArrayName(i);
    if (n && std::string(n) != "vtkValidPointMask" && std::string(n) != "vtkGhostType" &&
      !ds->GetCellData()->GetArray(n))
    {
      return false;
    }
  }
  return true;
}

/**
 * A dataset's "association": "cell" (or "auto" on an image with cell arrays
 * and no point arrays, or on a mesh whose point arrays interpolate its cell
 * arrays when its cells are a 3D lattice of equal boxes, as a blockMesh
 * case): its cell values on the lattice of cell centres
 * (vtkPlumeCellCenteredImage), what every representation then samples as
 * point data, so volumes, glyphs and contours show the cells' own values.
 */
vtkSmartPointer<vtkDataObject> CellCentered(
  vtkDataObject* data, const std::string& association, int maximumDimension, const std::string& name)
{
  auto* ds = vtkDataSet::SafeDownCast(data);
  const bool cellOnlyImage = vtkImageData::SafeDownCast(data) && !HasSolutionArrays(ds->GetPointData()) &&
    HasSolutionArrays(ds->GetCellData());
  const bool interpolatedPoints = ds && !vtkImageData::SafeDownCast(data) && PointsInterpolateCells(ds);
  if (association == "point" || (association == "auto" && !cellOnlyImage && !interpolatedPoints))
  {
    return data;
  }
  if (!ds || !HasSolutionArrays(ds->GetCellData()))
  {
    throw SceneError("datasets." + name + ": 'association' \"cell\" needs a dataset with cell arrays (" +
      (ds ? "it has none" : std::string("a ") + data->GetClassName() + " is not one dataset; merge its blocks") +
      ")");
  }
  vtkNew<vtkPlumeCellCenteredImage> centres;
  centres->SetInputData(ds);
  // auto on interpolated points keeps only an exact lattice (below): a probe would be thrown away
  const bool autoCells = association == "auto" && interpolatedPoints;
  centres->SetMaximumDimension(autoCells ? 2 : maximumDimension);
  centres->GlobalWarningDisplayOff(); // its error is reported here, once
  centres->Update();
  vtkImageData* image = centres->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  if (autoCells &&
    !(centres->GetLastError().empty() && centres->GetExact() && dims[0] > 1 && dims[1] > 1 && dims[2] > 1))
  {
    // Only an exact 3D lattice: elsewhere cells would be sampled, not kept, and a
    // one-cell-thick (2D) case gives a plane of centres no volume can show.
    return data;
  }
  if (!centres->GetLastError().empty())
  {
    throw SceneError("datasets." + name + ": " + centres->GetLastError());
  }
  std::ostringstream note;
  note << "datasets." << name << ": cell values at the " << dims[0] << "x" << dims[1] << "x" << dims[2]
       << " cell centres"
       << (association != "auto" ? ""
             : cellOnlyImage ? " (an image with cell arrays only)"
                             : " (its point arrays interpolate its cell arrays, with boundary values at "
                               "boundary points; \"association\": \"point\" keeps them)")
       << (centres->GetExact() ? ", every cell exactly"
                               : ", each sample the value of the cell containing it (cells are not one box lattice)");
  Note(note.str());
  return image;
}
}

vtkDataObject* SceneDatasets::Get(const std::string& name, const std::string& where)
{
  auto it = this->Entries.find(name);
  if (it == this->Entries.end())
  {
    std::string known;
    for (const auto& e : this->Entries)
    {
      known += (known.empty() ? "" : ", ") + e.first;
    }
    throw SceneError(where + ": unknown dataset '" + name + "' (datasets: " + (known.empty() ? "none" : known) + ")");
  }
  Entry& entry = it->second;
  if (entry.Data)
  {
    return entry.Data;
  }
  // a splat's 'trace'/'reference'/'lines' naming a dataset that (indirectly) names it back
  if (std::find(this->Building.begin(), this->Building.end(), name) != this->Building.end())
  {
    std::string cycle;
    for (auto b = std::find(this->Building.begin(), this->Building.end(), name); b != this->Building.end(); ++b)
    {
      cycle += *b + " -> ";
    }
    throw SceneError(where + ": datasets depend on each other in a cycle: " + cycle + name);
  }
  this->Building.push_back(name);
  struct Pop
  {
    std::vector<std::string>& Stack;
    ~Pop() { this->Stack.pop_back(); }
  } pop{ this->Building };
  Parameters p(entry.Spec, "datasets." + name);
  const nlohmann::json* sourceKey = p.Raw("source");
  if (sourceKey && sourceKey->is_string() && IsDerivedSource(sourceKey->get<std::string>()))
  {
    entry.Data = BuildDerivedDataset(p, *this, name);
    return entry.Data;
  }
  const std::string source = p.Choice("source", "file",
    { "file", "vortex", "splat", "smoke", "contour", "slice", "streamlines", "stream_surface", "ribbon", "threshold",
      "clip" });
  if (source == "splat")
  {
    entry.Data = BuildSplatDataset(p, *this, name);
    return entry.Data;
  }
  if (source == "smoke")
  {
    entry.Data = BuildSmokeDataset(p, *this, name);
    return entry.Data;
  }
  if (source == "vortex")
  {
    vtkNew<vtkPlumeVortexSource> vortex;
    const auto dims = p.Vector<3>("dimensions", { 32, 32, 32 });
    for (double d : dims)
    {
      if (d < 1 || d > 1024 || d != std::floor(d))
      {
        throw SceneError("datasets." + name + ": 'dimensions' must be integers in [1, 1024], got " +
          std::to_string(d));
      }
    }
    vortex->SetDimensions(int(dims[0]), int(dims[1]), int(dims[2]));
    const auto bounds = p.Vector<6>("bounds", { -1, 1, -1, 1, -1, 1 });
    vortex->SetBounds(bounds.data());
    vortex->SetCirculation(p.Number("circulation", 2.0));
    vortex->SetCoreRadius(p.Number("core_radius", 0.4, 1e-12));
    vortex->SetAxialVelocity(p.Number("axial_velocity", 0.3));
    const auto drift = p.Vector<3>("drift", { 0.1, 0, 0 });
    vortex->SetDrift(drift.data());
    const auto center = p.Vector<3>("center", { 0, 0, 0 });
    vortex->SetCenter(center.data());
    p.RejectUnknown();
    vortex->Update();
    entry.Data = vortex->GetOutputDataObject(0);
    return entry.Data;
  }

  vtkNew<vtkPlumeDatasetReader> reader;
  const std::string path = p.String("path", "");
  if (path.empty())
  {
    throw SceneError("datasets." + name + ": 'path' is required (a file relative to the scene or to the data folder)");
  }
  for (const std::string key : { "path", "q_path" })
  {
    const std::string value = p.String(key, "");
    if (value.find('\0') != std::string::npos)
    {
      // C APIs would read the file named by the part before it
      throw SceneError("datasets." + name + ": '" + key + "' holds a NUL character: '" +
        std::string(value.c_str()) + "\\u0000" + value.substr(value.find('\0') + 1) + "'");
    }
  }
  const std::string resolved = this->Resolve(path);
  if (!vtksys::SystemTools::FileIsFullPath(path) && !vtksys::SystemTools::FileExists(resolved))
  {
    // both places a relative path is looked up in, so a wrong PLUME_DATA_DIR shows
    const char* env = std::getenv("PLUME_DATA_DIR");
    throw SceneError("datasets." + name + ": file not found: '" + path + "' is neither in the scene's folder (" +
      this->SceneDirectory + ") nor in the data folder (" + DataFolder() +
      (env && *env ? ", from PLUME_DATA_DIR" : ", the default; set PLUME_DATA_DIR to change it") + ")");
  }
  reader->SetFileName(resolved.c_str());
  if (p.Has("q_path"))
  {
    reader->SetQFileName(this->Resolve(p.String("q_path", "")).c_str());
  }
  reader->SetReaderName(p.String("reader", "").c_str());
  // Time: "time_step" (an index or "last") or "time" (nearest step). A series
  // opens at its last step by default: a transient run's step 0 is usually its
  // initial condition (uniform fields), which renders as an empty picture.
  const nlohmann::json* timeStep = p.Raw("time_step");
  const bool hasTime = p.Has("time");
  const double time = p.Number("time", 0.0);
  if (timeStep && hasTime)
  {
    throw SceneError("datasets." + name + ": give 'time_step' or 'time', not both");
  }
  bool lastStep = !timeStep && !hasTime;
  if (timeStep)
  {
    if (timeStep->is_string() && timeStep->get<std::string>() == "last")
    {
      lastStep = true;
    }
    else if (timeStep->is_number_integer() && timeStep->get<long long>() >= 0 &&
      timeStep->get<long long>() < (1 << 30))
    {
      reader->SetTimeStep(static_cast<int>(timeStep->get<long long>()));
    }
    else
    {
      throw SceneError("datasets." + name + ": 'time_step' must be a step index (0, 1, ...) or \"last\", got " +
        timeStep->dump());
    }
  }
  if (hasTime && this->TimeStepOverride < 0)
  {
    reader->SetTimeValue(time);
  }
  reader->SetMergeBlocks(p.Boolean("merge_blocks", true));
  for (const auto& block : p.Strings("blocks"))
  {
    reader->AddBlockName(block.c_str());
  }
  // Checked now so typos fail before any slow reading.
  const int imageDimension = static_cast<int>(p.Integer("image_dimension", 64, 2, 1024));
  const std::string association = p.Choice("association", "auto", { "auto", "point", "cell" });
  p.RejectUnknown();
  if (this->Progress)
  {
    AttachProgress(reader, "reading " + name);
  }
  if (this->TimeStepOverride >= 0)
  {
    // --time-steps: the frame's step of every series (datasets without steps stay as they are)
    reader->UpdateInformation();
    const int count = reader->GetNumberOfTimeValues();
    if (count > 1)
    {
      if (this->TimeStepOverride >= count)
      {
        throw SceneError("--time-steps: step " + std::to_string(this->TimeStepOverride) + " is past the last step " +
          std::to_string(count - 1) + " of datasets." + name);
      }
      reader->SetTimeStep(this->TimeStepOverride);
    }
  }
  else if (lastStep)
  {
    reader->UpdateInformation();
    if (reader->GetNumberOfTimeValues() > 1)
    {
      reader->SetTimeStep(reader->GetNumberOfTimeValues() - 1);
    }
  }
  reader->Update();
  if (!reader->GetLastError().empty())
  {
    throw SceneError("datasets." + name + ": " + reader->GetLastError());
  }
  entry.Data = reader->GetOutputDataObject(0);
  if (!entry.Data)
  {
    throw SceneError("datasets." + name + ": the reader produced no data from '" + path + "'");
  }
  entry.Data = CellCentered(entry.Data, association, imageDimension, name);
  const int steps = reader->GetNumberOfTimeValues();
  if (steps > 1)
  {
    const int step = reader->GetTimeStepRead();
    std::ostringstream line;
    line << "datasets." << name << ": time step " << step << " of 0.." << steps - 1
         << " (t = " << reader->GetTimeValueAt(step) << "; times " << reader->GetTimeValueAt(0) << " to "
         << reader->GetTimeValueAt(steps - 1) << ")";
    Note(line.str());
    this->TimeSteps = std::max(this->TimeSteps, steps);
    if (this->TimeLabel.empty())
    {
      std::ostringstream label;
      label << "t = " << reader->GetTimeValueAt(step);
      this->TimeLabel = label.str();
      this->TimeStepShown = step;
    }
    if (SolutionIsUniform(entry.Data))
    {
      std::ostringstream warning;
      warning << "warning: datasets." << name << ": every array of time step " << step
              << " (t = " << reader->GetTimeValueAt(step)
              << ") is uniform, as in an initial condition; choose another step with 'time_step' "
                 "(an index or \"last\") or 'time'";
      Note(warning.str());
    }
  }
  return entry.Data;
}

bool SceneDatasets::GravityUp(double up[3], std::string& from) const
{
  for (const auto& item : this->Entries)
  {
    const Entry& entry = item.second;
    if (!entry.Data)
    {
      continue; // only datasets the scene uses
    }
    double g[3] = { 0, 0, 0 };
    bool found = false;
    if (vtkFieldData* field = entry.Data->GetFieldData())
    {
      for (const char* name : { "gravity", "g" })
      {
        vtkDataArray* a = field->GetArray(name);
        if (a && a->GetNumberOfComponents() == 3 && a->GetNumberOfTuples() > 0)
        {
          a->GetTuple(0, g);
          from = "field array '" + std::string(name) + "' of dataset '" + item.first + "'";
          found = true;
          break;
        }
      }
    }
    const std::string path = entry.Spec.contains("path") && entry.Spec["path"].is_string()
      ? entry.Spec["path"].get<std::string>()
      : std::string();
    if (!found && vtksys::SystemTools::GetFilenameLastExtension(path) == ".foam")
    {
      // OpenFOAM: constant/g holds "value (gx gy gz);"
      const std::string file =
        vtksys::SystemTools::GetFilenamePath(this->Resolve(path)) + "/constant/g";
      std::ifstream in(file);
      std::stringstream text;
      text << in.rdbuf();
      const std::string content = text.str();
      const size_t at = content.find("value");
      const size_t open = content.find('(', at == std::string::npos ? 0 : at);
      if (at != std::string::npos && open != std::string::npos)
      {
        std::istringstream numbers(content.substr(open + 1));
        found = static_cast<bool>(numbers >> g[0] >> g[1] >> g[2]);
        from = file;
      }
    }
    const double n = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    if (found && n > 0 && std::isfinite(n))
    {
      for (int a = 0; a < 3; ++a)
      {
        up[a] = 0.0 - g[a] / n; // +0, not -0, in the stated direction
      }
      return true;
    }
  }
  return false;
}

vtkImageData* SceneDatasets::GetImage(const std::string& name, const std::string& where)
{
  vtkDataObject* data = this->Get(name, where);
  Entry& entry = this->Entries[name];
  if (entry.Image)
  {
    return entry.Image;
  }
  if (auto* image = vtkImageData::SafeDownCast(data))
  {
    entry.Image = image;
    return image;
  }
  int dimension = 64;
  if (entry.Spec.contains("image_dimension"))
  {
    dimension = entry.Spec["image_dimension"].get<int>();
  }
  // Refuse a grid that cannot fit before allocating it: the resampled image
  // holds every point and cell array of the dataset (as point data, up to 8
  // bytes a component), the mask, and the probe's temporary copies (x2).
  double bounds[6];
  if (auto* ds = vtkDataSet::SafeDownCast(data))
  {
    ds->GetBounds(bounds);
  }
  else if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    composite->GetBounds(bounds);
  }
  else
  {
    throw SceneError(where + ": dataset '" + name + "' (" + data->GetClassName() + ") cannot be resampled");
  }
  int dims[3];
  vtkPlumeResampleToImage::ComputeAutomaticDimensions(bounds, dimension, dims);
  const double points = double(dims[0]) * dims[1] * dims[2];
  int components = 0;
  if (auto* ds = vtkDataSet::SafeDownCast(data))
  {
    for (vtkDataSetAttributes* a : { static_cast<vtkDataSetAttributes*>(ds->GetPointData()),
           static_cast<vtkDataSetAttributes*>(ds->GetCellData()) })
    {
      for (int i = 0; i < a->GetNumberOfArrays(); ++i)
      {
        components += a->GetArray(i) ? a->GetArray(i)->GetNumberOfComponents() : 0;
      }
    }
  }
  const double bytes = points * (8.0 * std::max(components, 4) + 1.0) * 2.0;
  const double budget = MemoryBudgetBytes();
  if (bytes > budget)
  {
    std::ostringstream message;
    message << "datasets." << name << ": 'image_dimension' " << dimension << " resamples onto " << dims[0] << "x"
            << dims[1] << "x" << dims[2] << " points, about " << std::llround(bytes / (1 << 20))
            << " MB, over the memory budget of " << std::llround(budget / (1 << 20))
            << " MB (PLUME_MEMORY_BUDGET_MB); choose a smaller image_dimension";
    throw SceneError(message.str());
  }
  vtkNew<vtkPlumeResampleToImage> resample;
  resample->SetInputData(data);
  resample->SetMaximumDimension(dimension);
  if (this->Progress)
  {
    AttachProgress(resample, "resampling " + name);
  }
  resample->Update();
  if (!resample->GetLastError().empty())
  {
    throw SceneError(where + ": resampling dataset '" + name + "': " + resample->GetLastError());
  }
  entry.Image = resample->GetOutput();
  return entry.Image;
}

namespace
{
void BuildCamera(
  const nlohmann::json* spec, vtkRenderer* renderer, int width, int height, const SceneDatasets& datasets)
{
  // The window does not exist yet: without the image's aspect ratio,
  // ResetCamera fits the data to a square and a tall or wide --size crops it.
  renderer->SetAspect(double(width) / double(height), 1.0);
  renderer->ResetCamera();
  if (!spec)
  {
    return;
  }
  Parameters p(*spec, "camera");
  vtkCamera* camera = renderer->GetActiveCamera();
  const bool hasPosition = p.Has("position");
  if (hasPosition || p.Has("focal_point"))
  {
    double fp[3], pos[3];
    camera->GetFocalPoint(fp);
    camera->GetPosition(pos);
    const auto focal = p.Vector<3>("focal_point", { fp[0], fp[1], fp[2] });
    const auto position = p.Vector<3>("position", { pos[0], pos[1], pos[2] });
    const double d[3] = { position[0] - focal[0], position[1] - focal[1], position[2] - focal[2] };
    if (!(vtkMath::Norm(d) > 0))
    {
      throw SceneError("camera: 'position' equals 'focal_point' (" + std::to_string(focal[0]) + ", " +
        std::to_string(focal[1]) + ", " + std::to_string(focal[2]) + "): no view direction");
    }
    camera->SetFocalPoint(focal.data());
    camera->SetPosition(position.data());
  }
  // "auto": up against the datasets' gravity when one gives it, else +y
  const nlohmann::json* upSpec = p.Raw("view_up");
  std::array<double, 3> up = { 0, 1, 0 };
  if (upSpec && upSpec->is_string())
  {
    if (upSpec->get<std::string>() != "auto")
    {
      throw SceneError("camera: 'view_up' must be 3 numbers or \"auto\", got " + upSpec->dump());
    }
    std::string from;
    if (datasets.GravityUp(up.data(), from))
    {
      std::ostringstream line;
      line << "camera: view_up auto: [" << up[0] << ", " << up[1] << ", " << up[2] << "] against gravity from "
           << from;
      Note(line.str());
    }
    else
    {
      Note("camera: view_up auto: no dataset gives gravity (field array 'gravity' or OpenFOAM constant/g); "
           "[0, 1, 0]");
    }
  }
  else
  {
    up = p.Vector<3>("view_up", { 0, 1, 0 });
  }
  if (!hasPosition)
  {
    // Without a position, look along -z (VTK's default) unless the requested
    // up is (nearly) z; then look along +y, so "view_up": [0, 0, 1] just works.
    const double n = vtkMath::Norm(up.data());
    if (n > 0 && std::fabs(up[2]) > 0.9 * n)
    {
      double fp[3], pos[3];
      camera->GetFocalPoint(fp);
      camera->GetPosition(pos);
      const double distance = std::sqrt(vtkMath::Distance2BetweenPoints(fp, pos));
      camera->SetPosition(fp[0], fp[1] - distance, fp[2]);
    }
  }
  {
    double dop[3];
    camera->GetDirectionOfProjection(dop);
    double cross[3];
    vtkMath::Cross(dop, up.data(), cross);
    if (!(vtkMath::Norm(cross) > 1e-9 * vtkMath::Norm(up.data())))
    {
      throw SceneError("camera: 'view_up' [" + std::to_string(up[0]) + ", " + std::to_string(up[1]) + ", " +
        std::to_string(up[2]) + "] is zero or parallel to the view direction");
    }
    camera->SetViewUp(up.data());
  }
  camera->SetViewAngle(p.Number("view_angle", 30.0, 1e-3, 179.0));
  camera->SetParallelProjection(p.Boolean("parallel_projection", false));
  if (p.Has("parallel_scale"))
  {
    camera->SetParallelScale(p.Number("parallel_scale", 1.0, 1e-300));
  }
  if (!hasPosition)
  {
    renderer->ResetCamera();
  }
  camera->Azimuth(p.Number("azimuth", 0.0));
  camera->Elevation(p.Number("elevation", 0.0));
  camera->Roll(p.Number("roll", 0.0));
  camera->OrthogonalizeViewUp();
  camera->Zoom(p.Number("zoom", 1.0, 1e-6, 1e6));
  p.RejectUnknown();
  renderer->ResetCameraClippingRange();
}

// A light's image: OpenEXR (linear float RGB, through OpenEXR: VTK 9.1 has no
// EXR reader) or any format VTK's image readers know (PNG, JPEG, TIFF, ...),
// row 0 at the bottom as VTK's readers give it.
vtkSmartPointer<vtkImageData> ReadLightImage(const std::string& path, const std::string& where)
{
  // a FIFO or a device would block the readers forever
  const std::string notRegular = vtkPlumeInputValidation::CheckRegularFile(path);
  if (!notRegular.empty())
  {
    throw SceneError(where + ": texture: " + notRegular);
  }
  auto image = vtkSmartPointer<vtkImageData>::New();
  if (vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path)) == ".exr")
  {
    try
    {
      Imf::RgbaInputFile file(path.c_str());
      const Imath::Box2i dw = file.dataWindow();
      const int w = dw.max.x - dw.min.x + 1;
      const int h = dw.max.y - dw.min.y + 1;
      Imf::Array2D<Imf::Rgba> pixels(h, w);
      file.setFrameBuffer(&pixels[0][0] - dw.min.x - dw.min.y * w, 1, w);
      file.readPixels(dw.min.y, dw.max.y);
      image->SetDimensions(w, h, 1);
      image->AllocateScalars(VTK_FLOAT, 3);
      auto* out = static_cast<float*>(image->GetScalarPointer());
      for (int j = 0; j < h; ++j)
      {
        const Imf::Rgba* row = pixels[h - 1 - j]; // EXR rows run top to bottom
        for (int i = 0; i < w; ++i)
        {
          out[3 * (size_t(j) * w + i) + 0] = row[i].r;
          out[3 * (size_t(j) * w + i) + 1] = row[i].g;
          out[3 * (size_t(j) * w + i) + 2] = row[i].b;
        }
      }
    }
    catch (const std::exception& e)
    {
      throw SceneError(where + ": cannot read texture '" + path + "': " + e.what());
    }
    return image;
  }
  vtkNew<vtkImageReader2Factory> factory;
  vtkSmartPointer<vtkImageReader2> reader;
  reader.TakeReference(factory->CreateImageReader2(path.c_str()));
  if (!reader)
  {
    throw SceneError(where + ": texture '" + path + "' is not an image VTK can read (PNG, JPEG, TIFF, ...) nor EXR");
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  if (dims[0] < 1 || dims[1] < 1 || dims[2] != 1 || !reader->GetOutput()->GetPointData()->GetScalars())
  {
    throw SceneError(where + ": texture '" + path + "' is not a 2D image");
  }
  image->ShallowCopy(reader->GetOutput());
  return image;
}

void BuildLights(const nlohmann::json* spec, vtkRenderer* renderer, const SceneDatasets& datasets)
{
  if (!spec)
  {
    return; // VTK's automatic headlight
  }
  if (!spec->is_array())
  {
    throw SceneError("scene: 'lights' must be a list of lights, got " + spec->dump());
  }
  renderer->AutomaticLightCreationOff();
  renderer->RemoveAllLights();
  int index = 0;
  for (const auto& item : *spec)
  {
    const std::string where = "lights[" + std::to_string(index++) + "]";
    Parameters p(item, where);
    vtkNew<vtkLight> light;
    const std::string type = p.Choice("type", "scene", { "headlight", "camera", "scene" });
    if (type == "headlight")
    {
      light->SetLightTypeToHeadlight();
    }
    else if (type == "camera")
    {
      light->SetLightTypeToCameraLight();
    }
    else
    {
      light->SetLightTypeToSceneLight();
    }
    const auto position = p.Vector<3>("position", { 0, 0, 1 });
    const auto focal = p.Vector<3>("focal_point", { 0, 0, 0 });
    light->SetPosition(position.data());
    light->SetFocalPoint(focal.data());
    const auto color = p.Color("color", { 1, 1, 1 });
    light->SetColor(color.data());
    // intensities multiply colours in float shaders: far beyond 1 is only saturation
    light->SetIntensity(p.Number("intensity", 1.0, 0.0, 1e4));
    light->SetPositional(p.Boolean("positional", false));
    light->SetConeAngle(p.Number("cone_angle", 30.0, 0.0, 180.0));
    light->SetExponent(p.Number("exponent", 1.0, 0.0, 128.0));
    light->SetAttenuationValues(p.Vector<3>("attenuation", { 1, 0, 0 }).data());
    // a spot light's projected image (the airlight's textured spot lights)
    const std::string texture = p.String("texture", "");
    if (!texture.empty())
    {
      vtkPlumeAirlightPass::SetLightTexture(light, ReadLightImage(datasets.Resolve(texture), where));
    }
    if (p.Has("texture_up"))
    {
      const auto up = p.Vector<3>("texture_up", { 0, 1, 0 });
      vtkPlumeAirlightPass::SetLightTextureUp(light, up[0], up[1], up[2]);
    }
    p.RejectUnknown();
    renderer->AddLight(light);
  }
}
}

// The scene's "medium": a vtkPlumeAirlightPass around the compositing pass,
// its keys checked and set through the pass's parameter table. Without a
// medium the pass is still there when a light projects an image (it draws
// the image on the surfaces).
void BuildMedium(const nlohmann::json* spec, vtkRenderer* renderer)
{
  if (!spec)
  {
    vtkLightCollection* lights = renderer->GetLights();
    lights->InitTraversal();
    bool textured = false;
    while (vtkLight* light = lights->GetNextItem())
    {
      textured = textured || vtkPlumeAirlightPass::GetLightTexture(light);
    }
    if (textured)
    {
      vtkNew<vtkPlumeAirlightPass> pass;
      pass->SetDelegatePass(vtkPlumeCompositingPass::Install(renderer));
      renderer->SetPass(pass);
    }
    return;
  }
  if (!spec->is_object())
  {
    throw SceneError("scene: 'medium' must be an object, got " + spec->dump());
  }
  Parameters p(*spec, "medium");
  vtkNew<vtkPlumeAirlightPass> pass;
  p.Apply(vtkPlumeAirlightPass::GetParameterTable(), pass);
  p.RejectUnknown();
  // the medium is seen through after the whole compositing frame: it wraps it
  pass->SetDelegatePass(vtkPlumeCompositingPass::Install(renderer));
  renderer->SetPass(pass);
}

void Scene::Build(
  const nlohmann::json& scene, const std::string& sceneDirectory, vtkRenderer* renderer, SceneOptions& options)
{
  Parameters top(scene, "scene");
  SceneDatasets datasets(top.Object("datasets"), sceneDirectory, options.Progress, options.TimeStep);

  const auto size = top.Vector<2>("size", { 800, 600 });
  for (double s : size)
  {
    if (s < 1 || s > 16384 || s != std::floor(s))
    {
      throw SceneError("scene: 'size' entries must be integers in [1, 16384], got " + std::to_string(s));
    }
  }
  if (options.Width <= 0 || options.Height <= 0)
  {
    options.Width = static_cast<int>(size[0]);
    options.Height = static_cast<int>(size[1]);
  }

  {
    // Refused before any loading: measured peak about 110 bytes a pixel (the
    // window's buffers, the float framebuffer, its read-back and the encoded
    // file; 4096x4096 peaked at 1.85 GB), and an oversized window otherwise
    // dies in std::bad_alloc after a long render.
    const double bytes = BytesPerPixel * double(options.Width) * double(options.Height);
    const double budget = MemoryBudgetBytes();
    if (bytes > budget)
    {
      std::ostringstream message;
      message << "image size " << options.Width << "x" << options.Height << " needs about "
              << std::llround(bytes / (1 << 20)) << " MB to render (about " << BytesPerPixel
              << " bytes a pixel), over the memory budget of " << std::llround(budget / (1 << 20))
              << " MB (PLUME_MEMORY_BUDGET_MB; default half the RAM); choose a smaller --size or 'size'";
      throw SceneError(message.str());
    }
  }

  const auto background = top.Color("background", { 0.1, 0.1, 0.12 });
  renderer->SetBackground(background.data());
  if (top.Has("background2"))
  {
    const auto background2 = top.Color("background2", { 0, 0, 0 });
    renderer->SetBackground2(background2.data());
    renderer->GradientBackgroundOn();
  }

  const std::string title = top.String("title", "");
  const bool timeLabel = top.Boolean("time_label", true);
  const nlohmann::json* camera = top.Object("camera");
  const nlohmann::json* lights = top.Raw("lights");
  const nlohmann::json* medium = top.Raw("medium");
  const nlohmann::json* reps = top.Raw("representations");
  top.RejectUnknown(); // before any slow loading
  if (!reps || !reps->is_array() || reps->empty())
  {
    throw SceneError("scene: 'representations' must be a non-empty list, got " + (reps ? reps->dump() : "nothing"));
  }
  const auto& builders = Representations();
  // The frame's order is the compositing pass's (opaque, glyphs, translucent,
  // media back to front), not the order of the list.
  vtkPlumeCompositingPass::Install(renderer);
  int index = 0;
  for (const auto& item : *reps)
  {
    const std::string where = "representations[" + std::to_string(index++) + "]";
    if (!item.is_object() || !item.contains("type") || !item["type"].is_string())
    {
      throw SceneError(where + ": needs a string 'type', got " + item.dump());
    }
    const std::string type = item["type"].get<std::string>();
    auto builder = builders.find(type);
    if (builder == builders.end())
    {
      std::string known;
      for (const auto& b : builders)
      {
        known += (known.empty() ? "" : ", ") + b.first;
      }
      throw SceneError(where + ": unknown representation type '" + type + "' (known: " + known + ")");
    }
    Parameters p(item, where + " (" + type + ")");
    p.String("type", type);
    // the props this representation adds are the ones after those already there
    const int before = renderer->GetViewProps()->GetNumberOfItems();
    builder->second(p, datasets, renderer);
    std::vector<vtkSmartPointer<vtkProp>> added;
    vtkPropCollection* props = renderer->GetViewProps();
    for (int i = before; i < props->GetNumberOfItems(); ++i)
    {
      added.emplace_back(vtkProp::SafeDownCast(props->GetItemAsObject(i)));
    }
    options.RepresentationProps.push_back(std::move(added));
  }
  if (!title.empty())
  {
    // centred above the data, in the overlay like the colour bars
    vtkNew<vtkTextActor> text;
    text->SetInput(title.c_str());
    text->GetTextProperty()->SetJustificationToCentered();
    text->GetTextProperty()->SetVerticalJustificationToTop();
    text->GetTextProperty()->SetFontSize(std::max(12, std::min(options.Width, options.Height) / 22));
    text->GetTextProperty()->SetColor(TextColorOn(BackgroundAt(renderer, 0.95).data()).data());
    text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    text->GetPositionCoordinate()->SetValue(0.5, 0.97);
    renderer->AddActor2D(text);
  }
  options.NumberOfTimeSteps = datasets.GetNumberOfTimeSteps();
  options.TimeStepShown = datasets.GetTimeStepShown();
  if (timeLabel && !datasets.GetTimeLabel().empty())
  {
    // the time of the step shown, bottom left, in the overlay like the title
    vtkNew<vtkTextActor> text;
    text->SetInput(datasets.GetTimeLabel().c_str());
    text->GetTextProperty()->SetJustificationToLeft();
    text->GetTextProperty()->SetVerticalJustificationToBottom();
    text->GetTextProperty()->SetFontSize(std::max(12, std::min(options.Width, options.Height) / 26));
    text->GetTextProperty()->SetColor(TextColorOn(BackgroundAt(renderer, 0.03).data()).data());
    text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    text->GetPositionCoordinate()->SetValue(0.02, 0.02);
    renderer->AddActor2D(text);
  }
  BuildCamera(camera, renderer, options.Width, options.Height, datasets);
  BuildLights(lights, renderer, datasets);
  BuildMedium(medium, renderer);
}

}
