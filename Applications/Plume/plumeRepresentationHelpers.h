// Pieces shared by the representation builders of the command line: array
// look-up with messages that name the dataset and the array, and colouring.
#ifndef plumeRepresentationHelpers_h
#define plumeRepresentationHelpers_h

#include "vtkSmartPointer.h"

#include <array>
#include <initializer_list>
#include <string>

class vtkDataArray;
class vtkDataObject;
class vtkDataSet;
class vtkRenderer;
class vtkScalarsToColors;

namespace plume
{
class Parameters;

/** "name (N components), ..." for the point arrays of a dataset. */
std::string DescribeArrays(vtkDataSet* data);

/**
 * The colour of overlay text (colour bars, title, time label) readable on
 * `background` (RGB 0..1, sRGB): near-white or near-black, whichever has the
 * higher contrast ratio (WCAG: (L1 + 0.05) / (L2 + 0.05) of relative luminances).
 */
std::array<double, 3> TextColorOn(const double background[3]);

/**
 * The background behind overlay text at height `y` (0 bottom .. 1 top) of the
 * renderer's viewport: its background, or the gradient towards background2.
 */
std::array<double, 3> BackgroundAt(vtkRenderer* renderer, double y);

/**
 * A point array by name (or the active vectors/scalars when `name` is empty),
 * checked for `components` (0: any). Throws SceneError naming what is wrong.
 */
vtkDataArray* RequirePointArray(
  vtkDataSet* data, const std::string& name, int components, const std::string& where, const std::string& dataset);

/**
 * `data` itself, or — when one of `names` exists only as cell data, as is
 * common for finite-volume results (CGNS, OpenFOAM) — a copy with the cell
 * arrays also interpolated to the points (vtkCellDataToPointData).
 */
vtkSmartPointer<vtkDataSet> WithPointArrays(vtkDataSet* data, std::initializer_list<std::string> names);

/** The dataset as a vtkDataSet; throws SceneError if it is still a composite. */
vtkDataSet* RequireDataSet(vtkDataObject* data, const std::string& where, const std::string& name);

/** Colouring parameters shared by representations: solid colour or a colour map over a range. */
struct Coloring
{
  std::array<double, 3> Color = { 1, 1, 1 };
  std::string Map;
  bool HasRange = false;
  std::array<double, 2> Range = { 0, 1 };
  bool Legend = true;
  std::string Where;    // the representation, in the range message
  bool Verbose = true;  // state a default range on stderr

  /**
   * The default range: the 1st and 99th percentiles (linear interpolation of
   * order statistics) of the valid values — finite and, if `mask` is given,
   * where it is not 0 — of `component` (-1: magnitude), so a few outliers or
   * interpolated boundary values do not wash out the picture; the min and max
   * when those percentiles are equal. `extremes` and `count` receive the
   * valid values' min/max and number.
   */
  static std::array<double, 2> RobustRange(vtkDataArray* array, int component, vtkDataArray* mask,
    std::array<double, 2>* extremes = nullptr, size_t* count = nullptr);

  /** Reads color, colormap and range. */
  void Read(Parameters& p, const std::array<double, 3>& defaultColor);
  /** Reads `legend` (default true), for representations coloured through a map. */
  void ReadLegend(Parameters& p);
  /**
   * Unless `legend` is false: a colour bar (vtkScalarBarActor) of `table`
   * titled `title`, on the right of the picture, left of any earlier bars.
   */
  void AddLegend(vtkRenderer* renderer, vtkScalarsToColors* table, const std::string& title) const;
  /**
   * The colour map over `range`, or else over RobustRange (stated on stderr
   * unless Verbose is false). NaN and +-Inf values are left out of the
   * default range, with a warning naming the array and how many were left out.
   */
  vtkSmartPointer<vtkScalarsToColors> Table(vtkDataArray* array, int component, vtkDataArray* mask = nullptr) const;
};
}

#endif
