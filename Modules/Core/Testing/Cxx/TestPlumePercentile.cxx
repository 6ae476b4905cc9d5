// vtkPlumePercentile against std::nth_element (the reference: the element of
// rank floor(q (n - 1)) of all the values), on one piece and on the values
// split over three pieces that are driven round by round as MPI ranks would
// be (one of them empty), for data with ties, zeros (also -0), denormals and
// values over 40 orders of magnitude.
#include "vtkPlumePercentile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace
{
double Reference(std::vector<float> values, double q)
{
  const size_t k = static_cast<size_t>(std::floor(q * double(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

// three pieces, each with its own selection, their counts summed each round
double ThreePieces(const std::vector<float>& all, double q)
{
  std::vector<std::vector<float>> pieces(3);
  for (size_t i = 0; i < all.size(); ++i)
  {
    pieces[i % 5 == 0 ? 0 : 2].push_back(all[i]); // pieces[1] stays empty
  }
  std::vector<vtkPlumePercentile> selections(3, vtkPlumePercentile(q));
  bool done = false;
  while (!done)
  {
    std::vector<vtkIdType> total(256, 0);
    for (int p = 0; p < 3; ++p)
    {
      const std::vector<vtkIdType> counts = selections[p].Count(pieces[p]);
      for (int b = 0; b < 256; ++b)
      {
        total[b] += counts[b];
      }
    }
    for (int p = 0; p < 3; ++p)
    {
      done = selections[p].Advance(total);
    }
  }
  const double r = selections[0].GetResult();
  for (int p = 1; p < 3; ++p)
  {
    const double other = selections[p].GetResult();
    if (!(other == r) && !(std::isnan(other) && std::isnan(r)))
    {
      std::printf("pieces disagree: %.9g vs %.9g\n", other, r);
      return -1.0;
    }
  }
  return r;
}
}

int TestPlumePercentile(int, char*[])
{
  int failures = 0;
  std::mt19937 rng(7);
  std::vector<std::vector<float>> cases;
  {
    std::vector<float> v; // speeds: mostly still air, a few fast nodes
    std::exponential_distribution<float> air(50.f);
    std::uniform_real_distribution<float> blood(0.3f, 9.f);
    for (int i = 0; i < 20000; ++i)
    {
      v.push_back(i % 30 == 0 ? blood(rng) : air(rng));
    }
    cases.push_back(v);
  }
  {
    std::vector<float> v; // ties, zeros, -0, denormals, huge values
    std::uniform_int_distribution<int> pick(0, 5);
    std::uniform_real_distribution<float> exponent(-40.f, 30.f);
    for (int i = 0; i < 5000; ++i)
    {
      switch (pick(rng))
      {
        case 0: v.push_back(0.f); break;
        case 1: v.push_back(-0.f); break;
        case 2: v.push_back(1e-42f); break;
        case 3: v.push_back(2.5f); break;
        default: v.push_back(std::pow(10.f, exponent(rng))); break;
      }
    }
    cases.push_back(v);
  }
  cases.push_back({ 3.f });
  cases.push_back({ 1.f, 2.f });
  for (const auto& values : cases)
  {
    for (double q : { 0.0, 0.01, 0.5, 0.99, 1.0 })
    {
      const double expected = Reference(values, q);
      const double one = vtkPlumePercentile::Select(values, q);
      const double three = ThreePieces(values, q);
      if (!(one == expected) || !(three == expected))
      {
        std::printf("n %zu q %g: one piece %.9g, three pieces %.9g, nth_element %.9g\n", values.size(), q,
          one, three, expected);
        ++failures;
      }
    }
  }
  // the documented quantile of the first case, for the log
  std::printf("99th percentile of %zu speeds: %.9g\n", cases[0].size(), vtkPlumePercentile::Select(cases[0], 0.99));
  if (!std::isnan(vtkPlumePercentile::Select({}, 0.99)) || !std::isnan(ThreePieces({}, 0.5)))
  {
    std::printf("no values: expected NaN\n");
    ++failures;
  }
  return failures == 0 ? 0 : 1;
}
