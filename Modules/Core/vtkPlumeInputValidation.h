/**
 * @class   vtkPlumeInputValidation
 * @brief   checks every Plume reader, filter, mapper and the command line apply to untrusted input
 *
 * VTK's readers hand out what a file says, true or not: cells whose point ids
 * do not exist, arrays shorter than their dataset, extents of 10^15 points,
 * NaN and Inf values. Plume's renderers and filters read those without bounds
 * checks (they index GPU buffers and textures), so every untrusted dataset
 * goes through these checks first, and every parameter whose arithmetic can
 * overflow is checked here. Each check returns an empty string when the
 * input is fine, else one sentence naming the problem and the offending value;
 * the caller adds where the input came from (file, dataset, parameter).
 *
 * All functions are static and thread-safe; none allocates in proportion to
 * the input (the checks stream over the arrays once).
 */
#ifndef vtkPlumeInputValidation_h
#define vtkPlumeInputValidation_h

#include "PlumeCoreModule.h"  // For export macro
#include "vtkType.h"          // For vtkIdType
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <string> // For std::string

class vtkCellArray;
class vtkDataArray;
class vtkDataObject;
class vtkDataSet;

class PLUMECORE_EXPORT VTK_WRAPEXCLUDE vtkPlumeInputValidation
{
public:
  // --- files -------------------------------------------------------------
  /**
   * "" if `path` names an existing regular file that can be opened for
   * reading without blocking. Refuses (with the reason) a path holding a NUL
   * character (the C APIs would read a truncated name), a missing path, a
   * directory, a FIFO (opening it blocks until a writer comes), a character or
   * block device and a socket.
   */
  static std::string CheckRegularFile(const std::string& path);

  // --- datasets ----------------------------------------------------------
  /**
   * "" if every cell of the cell array references point ids in
   * [0, numberOfPoints) and its offsets are non-decreasing and within its
   * connectivity. `what` names the cell array in the message (e.g. "polys").
   */
  static std::string CheckCellArray(vtkCellArray* cells, vtkIdType numberOfPoints, const char* what);

  /**
   * "" if the cells of a dataset (vtkPolyData, vtkUnstructuredGrid) are
   * consistent with its points (CheckCellArray on each cell array; the cell
   * types array of an unstructured grid as long as its cells) and each cell
   * has the points its type needs: polydata cells at least 1 (with
   * `polyDataSizes`, what a reader's output must meet: lines 2, polygons and
   * strips 3); a grid cell of a fixed-size type exactly its
   * count (a hexahedron 8), of a variable one at least its minimum, a
   * polyhedron its faces, and every type a VTK cell type. VTK's cell classes
   * read as many points as the type has (a 4-point hexahedron or a 1-point
   * polygon was a SEGV in the surface, glyph and volume paths). Structured
   * datasets have no explicit connectivity: "" unless their point count
   * disagrees with their extent.
   */
  static std::string CheckCells(vtkDataSet* data, bool polyDataSizes = false);

  /**
   * "" if every point array has one tuple per point and every cell array one
   * per cell.
   */
  static std::string CheckArrays(vtkDataSet* data);

  /**
   * "" if every point coordinate of a point set is finite (not part of
   * CheckDataObject: Plume's mappers and splatter skip NaN/Inf points with a
   * warning, for callers that must refuse them instead).
   */
  static std::string CheckFinitePoints(vtkDataSet* data);

  /**
   * CheckCells and CheckArrays on a dataset or on every leaf of a composite
   * (the message names the block by its flat index). `polyDataSizes`: see
   * CheckCells (vtkPlumeDatasetReader sets it: a 1-point line or polygon in a
   * file was a SEGV in the glyph and volume resampling).
   */
  static std::string CheckDataObject(vtkDataObject* data, bool polyDataSizes = false);

  // --- values ------------------------------------------------------------
  /**
   * Range of one component of an array (component -1: the Euclidean norm of
   * the tuple) over its finite values only; NaN and +-Inf tuples are left out
   * and counted in `nonFinite` (may be null). Returns false (range [0, 0])
   * when no value is finite. Masked tuples (mask != null and mask[i] == 0)
   * are left out and not counted.
   */
  static bool FiniteRange(vtkDataArray* array, int component, double range[2], vtkIdType* nonFinite,
    const unsigned char* mask = nullptr);

  /**
   * Parses a whole string as a decimal integer in [min, max], with overflow
   * checks (no silent wrap-around as with sscanf("%d")). Leading/trailing
   * spaces, signs other than a leading '-', and trailing characters fail.
   */
  static bool ParseInteger(const std::string& text, long long min, long long max, long long& value);

  /** Parses a whole string as a finite double; "inf", "nan", overflow and trailing characters fail. */
  static bool ParseFinite(const std::string& text, double& value);

  /**
   * Parses "WxH" (or "WXH") with each side an integer in [1, maxSide]; false
   * on anything else, including values that overflow an int.
   */
  static bool ParseSize(const std::string& text, int maxSide, int& width, int& height);

  /** "" if `value` is finite, else "<what> is <value> (not a finite number)". */
  static std::string CheckFinite(double value, const std::string& what);

  // --- budgets -----------------------------------------------------------
  /**
   * Bytes one allocation driven by user input may take:
   * $PLUME_MEMORY_BUDGET_MB when set to a positive number, else half of the
   * physical memory (4 GiB when that is unknown).
   */
  static double MemoryBudgetBytes();

  /**
   * "" if `bytes` fits MemoryBudgetBytes(), else "<what> needs about N MB,
   * over the memory budget of M MB (PLUME_MEMORY_BUDGET_MB)".
   */
  static std::string CheckMemory(double bytes, const std::string& what);

  /**
   * Operations (e.g. voxel updates) one user request may cost:
   * $PLUME_WORK_BUDGET when set to a positive number, else 1e10 (seconds to
   * tens of seconds on this kind of machine, never the unbounded hours of a
   * mistyped parameter).
   */
  static double WorkBudget();

  /** "" if `operations` fits WorkBudget(), else "<what> needs about N operations, over the work budget ...". */
  static std::string CheckWork(double operations, const std::string& what);
};

#endif
// VTK-HeaderTest-Exclude: vtkPlumeInputValidation.h
