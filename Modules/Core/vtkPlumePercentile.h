/**
 * @class   vtkPlumePercentile
 * @brief   exact percentile of non-negative floats, also over data split into pieces (MPI ranks)
 *
 * Select(values, q) returns the value of 0-based rank floor(q (N - 1)) among
 * the N values: what std::nth_element picks, bit for bit. When the values are
 * split over several pieces (each MPI rank holding its own), every piece
 * calls Select with its values and a `sum` that adds an array of counts over
 * all pieces in place (e.g. vtkMultiProcessController::AllReduce with
 * SUM_OP); every piece gets the same result, the one Select gives on all the
 * values together. Select is then collective: every piece must call it, with
 * or without values.
 *
 * How: non-negative floats order as their bit patterns do, so the value is
 * found 8 bits at a time, most significant first (a radix select): 4 rounds,
 * each one count over 256 bins of the values that match the bits fixed so far,
 * summed over the pieces. No value is sent between pieces; 4 reductions of
 * 256 counts whatever the data size.
 *
 * Values must be finite and non-negative (speeds, magnitudes); -0 counts as 0.
 * The rounds can also be driven by hand (Count, Advance), as the tests do to
 * simulate several pieces in one process.
 */
#ifndef vtkPlumePercentile_h
#define vtkPlumePercentile_h

#include "PlumeCoreModule.h"  // For export macro
#include "vtkType.h"          // For vtkIdType
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <cstdint>    // For std::uint32_t
#include <functional> // For std::function
#include <vector>     // For std::vector

class PLUMECORE_EXPORT VTK_WRAPEXCLUDE vtkPlumePercentile
{
public:
  /** Adds counts over all pieces, in place (the same length on every piece). */
  using Sum = std::function<void(std::vector<vtkIdType>& counts)>;

  /**
   * The value of rank floor(q (N - 1)) among the N values of all pieces, q in
   * [0, 1] (clamped); NaN if there are none. No `sum`: this piece alone.
   */
  static double Select(const std::vector<float>& values, double q, const Sum& sum = nullptr);

  /** Starts a selection of the value at quantile q (clamped to [0, 1]). */
  explicit vtkPlumePercentile(double q);

  /** This piece's 256 counts for the current round. */
  std::vector<vtkIdType> Count(const std::vector<float>& values) const;

  /**
   * Takes the current round's counts summed over all pieces; true when the
   * value is known (after 4 rounds, or at once when there are no values).
   */
  bool Advance(const std::vector<vtkIdType>& total);

  /** The selected value once Advance returned true; NaN without values. */
  double GetResult() const;

private:
  double Quantile;
  int Round = 0;          // 0..4: bits fixed so far = 8 x Round
  std::uint32_t Prefix = 0; // the bits fixed so far
  vtkIdType Rank = 0;     // the rank still to find among the values matching Prefix
  bool Empty = false;
};

#endif
