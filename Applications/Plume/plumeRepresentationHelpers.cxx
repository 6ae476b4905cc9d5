#include "plumeRepresentationHelpers.h"

#include "vtkPlumeInputValidation.h"
#include "vtksys/SystemTools.hxx"

#include "plumeColorMaps.h"
#include "plumeParameters.h"
#include "plumeScene.h"
#include "plumeSceneError.h"

#include "vtkCellData.h"
#include "vtkCellDataToPointData.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkNew.h"
#include "vtkActor2DCollection.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkScalarBarActor.h"
#include "vtkScalarsToColors.h"
#include "vtkTextProperty.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <vector>

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
        std::to_string(a->GetNumberOfComponents()) + (a->GetNumberOfComponents() == 1 ? " component)" : " components)");
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
      // the commonest slip: the right name in the wrong case (u for U, T for t)
      std::string suggestion;
      vtkPointData* pd = data->GetPointData();
      for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
      {
        const char* candidate = pd->GetArrayName(i);
        if (candidate && vtksys::SystemTools::LowerCase(candidate) == vtksys::SystemTools::LowerCase(name))
        {
          suggestion = std::string("; did you mean '") + candidate + "'?";
        }
      }
      throw SceneError(where + ": dataset '" + dataset + "' has no point array '" + name +
        "' (point arrays: " + DescribeArrays(data) + ")" + suggestion);
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
  this->Where = p.Where();
  this->HasRange = p.Has("range");
  this->Range = p.Vector<2>("range", { 0, 1 });
  if (this->HasRange && !(this->Range[1] >= this->Range[0]))
  {
    throw SceneError(p.Where() + ": 'range' must be [min, max] with min <= max");
  }
}

std::array<double, 3> TextColorOn(const double background[3])
{
  // relative luminance of the sRGB colour (IEC 61966-2-1 transfer, Rec. 709 weights)
  const double weights[3] = { 0.2126, 0.7152, 0.0722 };
  double luminance = 0;
  for (int c = 0; c < 3; ++c)
  {
    const double v = std::min(1.0, std::max(0.0, background[c]));
    luminance += weights[c] * (v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
  }
  const double againstWhite = 1.05 / (luminance + 0.05);
  const double againstBlack = (luminance + 0.05) / 0.05;
  if (againstBlack > againstWhite)
  {
    return { 0.05, 0.05, 0.05 };
  }
  return { 0.95, 0.95, 0.95 };
}

std::array<double, 3> BackgroundAt(vtkRenderer* renderer, double y)
{
  const double* bottom = renderer->GetBackground();
  std::array<double, 3> color = { bottom[0], bottom[1], bottom[2] };
  if (renderer->GetGradientBackground())
  {
    const double* top = renderer->GetBackground2();
    for (int c = 0; c < 3; ++c)
    {
      color[c] = (1 - y) * bottom[c] + y * top[c];
    }
  }
  return color;
}

void Coloring::ReadLegend(Parameters& p)
{
  this->Legend = p.Boolean("legend", true);
}

void Coloring::AddLegend(vtkRenderer* renderer, vtkScalarsToColors* table, const std::string& title) const
{
  if (!this->Legend || !table)
  {
    return;
  }
  // bars stand side by side from the right edge, one per coloured representation
  int earlier = 0;
  vtkActor2DCollection* actors = renderer->GetActors2D();
  actors->InitTraversal();
  while (vtkActor2D* a = actors->GetNextActor2D())
  {
    earlier += vtkScalarBarActor::SafeDownCast(a) ? 1 : 0;
  }
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(table);
  bar->SetTitle(title.c_str());
  bar->SetNumberOfLabels(5);
  // enough significant digits that the labels (a quarter of the range apart) differ:
  // T 300-301 K is "%.5g" (300.25, ...), not "%.3g" (300, 300, 301, ...)
  int digits = 3;
  if (const double* range = table->GetRange())
  {
    const double span = range[1] - range[0];
    const double magnitude = std::max(std::abs(range[0]), std::abs(range[1]));
    if (span > 0 && std::isfinite(span) && magnitude > 0)
    {
      digits = std::max(3, std::min(8, static_cast<int>(std::ceil(std::log10(magnitude / (span / 4)))) + 1));
    }
  }
  bar->SetLabelFormat(("%." + std::to_string(digits) + "g").c_str());
  // fixed, legible text at any picture size (VTK otherwise fits it to the bar)
  bar->UnconstrainedFontSizeOn();
  bar->GetTitleTextProperty()->SetFontSize(14);
  bar->GetLabelTextProperty()->SetFontSize(12);
  bar->SetMaximumWidthInPixels(90);
  bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  bar->GetPositionCoordinate()->SetValue(0.84 - 0.15 * earlier, 0.08);
  bar->SetWidth(0.1);
  bar->SetHeight(0.78);
  // readable on the background behind the bar (its middle, on a gradient)
  const std::array<double, 3> background = BackgroundAt(renderer, 0.5);
  const std::array<double, 3> ink = TextColorOn(background.data());
  for (vtkTextProperty* text : { bar->GetTitleTextProperty(), bar->GetLabelTextProperty() })
  {
    text->SetColor(ink.data());
    text->ShadowOff();
    text->ItalicOff();
    text->BoldOff();
  }
  renderer->AddActor2D(bar);
}

std::array<double, 2> Coloring::RobustRange(
  vtkDataArray* array, int component, vtkDataArray* mask, std::array<double, 2>* extremes, size_t* count)
{
  // the valid values: finite, and not where the mask (resampled data: nodes
  // outside the data, stored as 0) is 0
  const bool useMask = mask && mask->GetNumberOfTuples() == array->GetNumberOfTuples();
  const int comps = array->GetNumberOfComponents();
  std::vector<double> values;
  values.reserve(static_cast<size_t>(array->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    if (useMask && mask->GetComponent(i, 0) == 0.0)
    {
      continue;
    }
    double v = 0.0;
    if (component >= 0)
    {
      v = array->GetComponent(i, component);
    }
    else
    {
      for (int c = 0; c < comps; ++c)
      {
        v += array->GetComponent(i, c) * array->GetComponent(i, c);
      }
      v = std::sqrt(v);
    }
    if (std::isfinite(v))
    {
      values.push_back(v);
    }
  }
  if (count)
  {
    *count = values.size();
  }
  if (values.empty())
  {
    if (extremes)
    {
      *extremes = { 0.0, 0.0 };
    }
    return { 0.0, 0.0 };
  }
  // percentile q: linear interpolation between the order statistics around rank q (n - 1)
  auto percentile = [&values](double q) {
    const double rank = q * double(values.size() - 1);
    const size_t below = static_cast<size_t>(std::floor(rank));
    std::nth_element(values.begin(), values.begin() + below, values.end());
    const double low = values[below];
    if (below + 1 >= values.size())
    {
      return low;
    }
    // the next order statistic is the smallest of the values above `below`
    const double high = *std::min_element(values.begin() + below + 1, values.end());
    return low + (rank - double(below)) * (high - low);
  };
  const double p1 = percentile(0.01);
  const double p99 = percentile(0.99);
  const auto minmax = std::minmax_element(values.begin(), values.end());
  if (extremes)
  {
    *extremes = { *minmax.first, *minmax.second };
  }
  if (!(p99 > p1))
  {
    // (nearly) constant bulk with a few other values: those should still show
    return { *minmax.first, *minmax.second };
  }
  // A percentile a rounding residue away from zero (resampled or interpolated
  // zero velocities at walls: 9.15e-19 on the kitchen) is zero: the colour bar
  // then reads 0, not 9.15e-19.
  const double residue = 1e-9 * (p99 - p1);
  return { std::fabs(p1) < residue ? 0.0 : p1, std::fabs(p99) < residue ? 0.0 : p99 };
}

vtkSmartPointer<vtkScalarsToColors> Coloring::Table(vtkDataArray* array, int component, vtkDataArray* mask) const
{
  std::array<double, 2> r = this->Range;
  if (!this->HasRange)
  {
    std::array<double, 2> extremes;
    size_t count = 0;
    r = RobustRange(array, component, mask, &extremes, &count);
    if (this->Verbose)
    {
      // stated, so a user knows the picture does not span the whole data
      const std::string name = array->GetName() ? array->GetName() : "";
      std::ostringstream line;
      line << this->Where << ": range of " << (component < 0 ? "|" + name + "|" : "'" + name + "'") << " ["
           << r[0] << ", " << r[1] << "]: 1-99 % percentiles of " << count << " valid values (all: ["
           << extremes[0] << ", " << extremes[1] << "]); set 'range' to choose";
      Note(line.str());
    }
    // a few Inf values would have made the range infinite: say how many were left out
    double finite[2];
    vtkIdType nonFinite = 0;
    vtkPlumeInputValidation::FiniteRange(array, component, finite, &nonFinite, nullptr);
    if (nonFinite > 0)
    {
      std::cerr << "plume: warning: " << this->Where << ": " << nonFinite << " NaN or infinite value(s) of array '"
                << (array->GetName() ? array->GetName() : "(unnamed)") << "' left out of the colour range [" << r[0]
                << ", " << r[1] << "]\n";
    }
  }
  return MakeColorMap(this->Map, r[0], r[1]);
}

}
