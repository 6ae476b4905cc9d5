// Scene datasets derived from another dataset with VTK's own filters:
// `"source": "contour" | "slice" | "streamlines" | "stream_surface" | "ribbon"
// | "threshold" | "clip"` with `"input": NAME` (vtkPlumeDerivedGeometry). Every
// filter parameter comes from the class's vtkPlumeParameterTable; `input`,
// `seeds` (a dataset name) and `values` (a list) are read here. The value
// and array chosen by default are stated on stderr. Documented in
// Documentation/SceneFormat.md.
#include "plumeParameters.h"
#include "plumeProgress.h"
#include "plumeScene.h"
#include "plumeSceneError.h"

#include "vtkPlumeDerivedGeometry.h"
#include "vtkPlumeParameterTable.h"

#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkPolyData.h"

#include <cmath>
#include <sstream>

namespace plume
{
namespace
{
vtkDataSet* AsDataSet(vtkDataObject* data, const std::string& where, const std::string& name)
{
  auto* ds = vtkDataSet::SafeDownCast(data);
  if (!ds)
  {
    throw SceneError(where + ": dataset '" + name + "' is a " + data->GetClassName() +
      ", not a single dataset (set 'merge_blocks' to true, or pick one with 'blocks')");
  }
  return ds;
}
}

bool IsDerivedSource(const std::string& source)
{
  const auto* operation = vtkPlumeDerivedGeometry::GetParameterTable().Find("source");
  return operation->FindOption(source) != nullptr;
}

vtkSmartPointer<vtkDataObject> BuildDerivedDataset(Parameters& p, SceneDatasets& datasets, const std::string& name)
{
  const std::string where = "datasets." + name;
  auto filter = vtkSmartPointer<vtkPlumeDerivedGeometry>::New();
  p.Apply(vtkPlumeDerivedGeometry::GetParameterTable(), filter);
  const std::string input = p.String("input", "");
  const std::string seeds = p.String("seeds", "");
  std::vector<double> values;
  if (const nlohmann::json* v = p.Raw("values"))
  {
    const bool list = v->is_array() && !v->empty() && v->size() <= 1000;
    if (v->is_number())
    {
      values.push_back(v->get<double>());
    }
    else if (list)
    {
      for (const auto& x : *v)
      {
        if (!x.is_number())
        {
          throw SceneError(where + ": parameter 'values' must be a number or a list of numbers, got " + v->dump());
        }
        values.push_back(x.get<double>());
      }
    }
    else
    {
      throw SceneError(where + ": parameter 'values' must be a number or a list of 1 to 1000 numbers, got " +
        v->dump().substr(0, 80));
    }
    for (double x : values)
    {
      if (!std::isfinite(x))
      {
        throw SceneError(where + ": parameter 'values' must hold finite numbers, got " + v->dump());
      }
    }
  }
  p.RejectUnknown();
  const int operation = filter->GetOperation();
  const std::string source = vtkPlumeDerivedGeometry::GetParameterTable().Find("source")->FindOption(operation)->Key;
  if (input.empty())
  {
    throw SceneError(where + ": 'input' is required: the name of the dataset the " + source + " is derived from");
  }
  if (!values.empty() && operation != vtkPlumeDerivedGeometry::CONTOUR &&
    operation != vtkPlumeDerivedGeometry::THRESHOLD)
  {
    throw SceneError(where + ": parameter 'values' is used by contour and threshold only, not " + source);
  }
  const bool flow = operation == vtkPlumeDerivedGeometry::STREAMLINES ||
    operation == vtkPlumeDerivedGeometry::STREAM_SURFACE || operation == vtkPlumeDerivedGeometry::RIBBON;
  if (!seeds.empty() && !flow)
  {
    throw SceneError(where + ": parameter 'seeds' is used by streamlines, stream_surface and ribbon only, not " +
      source);
  }
  filter->SetValues(values);
  filter->SetInputData(0, AsDataSet(datasets.Get(input, where + ".input"), where + ".input", input));
  if (!seeds.empty())
  {
    filter->SetInputData(1, AsDataSet(datasets.Get(seeds, where + ".seeds"), where + ".seeds", seeds));
  }
  if (datasets.ProgressEnabled())
  {
    AttachProgress(filter, "deriving " + name);
  }
  filter->Update();
  if (!filter->GetLastError().empty())
  {
    throw SceneError(where + ": " + filter->GetLastError());
  }
  if (values.empty() &&
    (operation == vtkPlumeDerivedGeometry::CONTOUR || operation == vtkPlumeDerivedGeometry::THRESHOLD))
  {
    std::ostringstream line;
    line << where << ": " << source << " of '" << filter->GetUsedArrayName() << "' at "
         << (operation == vtkPlumeDerivedGeometry::THRESHOLD ? "or above " : "") << filter->GetUsedValues()[0]
         << ", the median of its values; set 'values' to choose";
    Note(line.str());
  }
  if (operation == vtkPlumeDerivedGeometry::THRESHOLD)
  {
    // what was kept, and from which association (cell values are not interpolated)
    auto* in = vtkDataSet::SafeDownCast(filter->GetInputDataObject(0, 0));
    auto* result = vtkDataSet::SafeDownCast(filter->GetOutputDataObject(0));
    std::ostringstream line;
    line << where << ": threshold of " << (filter->GetUsedCellData() ? "cell" : "point") << " array '"
         << filter->GetUsedArrayName() << "' in [" << filter->GetUsedValues()[0] << ", "
         << (filter->GetUsedValues().size() > 1 ? std::to_string(filter->GetUsedValues()[1]) : std::string("inf"))
         << "]: " << result->GetNumberOfCells() << " of " << in->GetNumberOfCells() << " cells";
    Note(line.str());
  }
  vtkSmartPointer<vtkDataObject> out;
  out.TakeReference(filter->GetOutputDataObject(0)->NewInstance());
  out->ShallowCopy(filter->GetOutputDataObject(0));
  return out;
}
}
