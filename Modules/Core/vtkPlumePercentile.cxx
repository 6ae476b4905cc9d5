#include "vtkPlumePercentile.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace
{
std::uint32_t Bits(float value)
{
  value += 0.0f; // -0 -> +0: the sign bit would sort it last
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}
}

vtkPlumePercentile::vtkPlumePercentile(double q)
  : Quantile(std::isfinite(q) ? std::min(1.0, std::max(0.0, q)) : 0.0)
{
}

std::vector<vtkIdType> vtkPlumePercentile::Count(const std::vector<float>& values) const
{
  std::vector<vtkIdType> counts(256, 0);
  const int shift = 24 - 8 * this->Round;
  for (float v : values)
  {
    const std::uint32_t bits = Bits(v);
    // the bits above this round's byte must match the ones fixed so far
    if (this->Round == 0 || (bits >> (shift + 8)) == this->Prefix)
    {
      ++counts[(bits >> shift) & 0xffu];
    }
  }
  return counts;
}

bool vtkPlumePercentile::Advance(const std::vector<vtkIdType>& total)
{
  if (this->Round == 0)
  {
    vtkIdType n = 0;
    for (vtkIdType c : total)
    {
      n += c;
    }
    if (n == 0)
    {
      this->Empty = true;
      this->Round = 4;
      return true;
    }
    this->Rank = static_cast<vtkIdType>(std::floor(this->Quantile * double(n - 1)));
  }
  int bin = 0;
  while (bin < 255 && this->Rank >= total[bin])
  {
    this->Rank -= total[bin];
    ++bin;
  }
  this->Prefix = (this->Prefix << 8) | static_cast<std::uint32_t>(bin);
  ++this->Round;
  return this->Round == 4;
}

double vtkPlumePercentile::GetResult() const
{
  if (this->Empty || this->Round < 4)
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  float value;
  std::memcpy(&value, &this->Prefix, sizeof value);
  return value;
}

double vtkPlumePercentile::Select(const std::vector<float>& values, double q, const Sum& sum)
{
  vtkPlumePercentile selection(q);
  bool done = false;
  while (!done)
  {
    std::vector<vtkIdType> counts = selection.Count(values);
    if (sum)
    {
      sum(counts);
    }
    done = selection.Advance(counts);
  }
  return selection.GetResult();
}
