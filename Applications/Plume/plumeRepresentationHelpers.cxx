#include "plumeRepresentationHelpers.h"

#include "vtkPlumeInputValidation.h"

#include "plumeColorMaps.h"
#include "plumeParameters.h"
#include "plumeSceneError.h"

#include "vtkCellData.h"
#include "vtkCellDataToPointData.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkScalarsToColors.h"

#include <algorithm>
#include <cmath>
#include <vector>
#include <iostream>

namespace plume
{

std::string DescribeArrays(vtkDataSet* data)
{
  std::string list;
  vtkPointData* pd = data->GetPointData();
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* a = pd->GetArray(i);
    if (a && a->GetName() && std::string(a->GetName()) != "vtkGhostType")
    {
      list += (list.empty() ? "" : ", ") + std::string(a->GetName()) + " (" +
        std::to_string(a->GetNumberOfComponents()) + " components)";
    }
  }
  return list.empty() ? "none" : list;
}

/** A named point array (or the active one of the given kind), checked for its component count. */
vtkDataArray* RequirePointArray(
  vtkDataSet* data, const std::string& name, int components, const std::string& where, const std::string& dataset)
{
  vtkDataArray* array = nullptr;
  if (name.empty())
  {
    array = components == 3 ? data->GetPointData()->GetVectors() : data->GetPointData()->GetScalars();
    if (!array)
    {
      throw SceneError(where + ": dataset '" + dataset + "' has no active " +
        (components == 3 ? "vectors" : "scalars") + "; name one (point arrays: " + DescribeArrays(data) + ")");
    }
  }
  else
  {
    array = data->GetPointData()->GetArray(name.c_str());
    if (!array)
    {
      throw SceneError(where + ": dataset '" + dataset + "' has no point array '" + name +
        "' (point arrays: " + DescribeArrays(data) + ")");
    }
  }
  if (components > 0 && array->GetNumberOfComponents() != components)
  {
    throw SceneError(where + ": point array '" + std::string(array->GetName() ? array->GetName() : name) +
      "' of dataset '" + dataset + "' has " + std::to_string(array->GetNumberOfComponents()) +
      (array->GetNumberOfComponents() == 1 ? " component" : " components") + ", expected " +
      std::to_string(components));
  }
  return array;
}

vtkSmartPointer<vtkDataSet> WithPointArrays(vtkDataSet* data, std::initializer_list<std::string> names)
{
  for (const auto& name : names)
  {
    if (!name.empty() && !data->GetPointData()->GetArray(name.c_str()) &&
      data->GetCellData()->GetArray(name.c_str()))
    {
      vtkNew<vtkCellDataToPointData> convert;
      convert->SetInputData(data);
      convert->PassCellDataOn();
      convert->Update();
      return vtkDataSet::SafeDownCast(convert->GetOutputDataObject(0));
    }
  }
  return data;
}

vtkDataSet* RequireDataSet(vtkDataObject* data, const std::string& where, const std::string& name)
{
  auto* ds = vtkDataSet::SafeDownCast(data);
  if (!ds)
  {
    throw SceneError(where + ": dataset '" + name + "' is a " + data->GetClassName() +
      "; set \"merge_blocks\": true (the default) to render it");
  }
  return ds;
}

void Coloring::Read(Parameters& p, const std::array<double, 3>& defaultColor)
{
  this->Where = p.Where();
  this->Color = p.Color("color", defaultColor);
  this->Map = p.Choice("colormap", "viridis", ColorMapNames());
  this->HasRange = p.Has("range");
  this->Range = p.Vector<2>("range", { 0, 1 });
  if (this->HasRange && !(this->Range[1] >= this->Range[0]))
  {
    throw SceneError(p.Where() + ": 'range' must be [min, max] with min <= max");
  }
}

vtkSmartPointer<vtkScalarsToColors> Coloring::Table(vtkDataArray* array, int component, vtkDataArray* mask) const
{
  double r[2] = { this->Range[0], this->Range[1] };
  if (!this->HasRange)
  {
    // nodes outside the data (resampled: stored as 0) must not widen the range
    std::vector<unsigned char> valid;
    if (mask && mask->GetNumberOfTuples() == array->GetNumberOfTuples())
    {
      valid.resize(static_cast<size_t>(mask->GetNumberOfTuples()));
      for (vtkIdType i = 0; i < mask->GetNumberOfTuples(); ++i)
      {
        valid[static_cast<size_t>(i)] = mask->GetComponent(i, 0) != 0.0;
      }
    }
    // a few Inf values would make the range infinite: every colour the same
    vtkIdType nonFinite = 0;
    vtkPlumeInputValidation::FiniteRange(array, component, r, &nonFinite, valid.empty() ? nullptr : valid.data());
    if (nonFinite > 0)
    {
      std::cerr << "plume: warning: " << this->Where << ": " << nonFinite << " NaN or infinite value(s) of array '"
                << (array->GetName() ? array->GetName() : "(unnamed)")
                << "' left out of the colour range [" << r[0] << ", " << r[1] << "]\n";
    }
  }
  return MakeColorMap(this->Map, r[0], r[1]);
}

}
