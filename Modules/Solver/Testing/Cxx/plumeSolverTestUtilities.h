// Small helpers shared by the smoke solver tests: checks that count
// failures, grid indexing, norms. No solver code is shared: the references
// each test compares with are computed here or in the test itself.
#ifndef plumeSolverTestUtilities_h
#define plumeSolverTestUtilities_h

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <vector>

namespace plume_solver_test
{
inline int& Failures()
{
  static int failures = 0;
  return failures;
}

#define PLUME_CHECK(cond, what)                                                                     \
  do                                                                                                \
  {                                                                                                 \
    if (!(cond))                                                                                    \
    {                                                                                               \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #cond " -- " << what << "\n"; \
      ++plume_solver_test::Failures();                                                              \
    }                                                                                               \
  } while (false)

inline double MaxAbs(const std::vector<double>& v)
{
  double m = 0;
  for (double x : v)
  {
    m = std::max(m, std::abs(x));
  }
  return m;
}

inline double Norm2(const std::vector<double>& v)
{
  double s = 0;
  for (double x : v)
  {
    s += x * x;
  }
  return std::sqrt(s);
}

/** A repeatable pseudo-random number in [-1, 1) (64-bit LCG). */
struct Random
{
  unsigned long long State = 12345;
  double Next()
  {
    State = State * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(State >> 11) / double(1ULL << 53) * 2.0 - 1.0;
  }
};
}

#endif
