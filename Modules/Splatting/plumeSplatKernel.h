// What the two backends of vtkPlumeGaussianSplatter share: the grid, the
// sanitised splats, and the separable 1D weights of one splat along one axis.
// (vtkPlumeSplatReference shares none of this: it is the independent yardstick.)
#ifndef plumeSplatKernel_h
#define plumeSplatKernel_h

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace plume
{
namespace splat
{
/** Output lattice: point (i,j,k) at Origin + (i,j,k)·Spacing; its voxel is the cell of size Spacing centred there. */
struct Grid
{
  double Origin[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
  int Dims[3] = { 1, 1, 1 };
  size_t Voxels() const { return size_t(this->Dims[0]) * this->Dims[1] * this->Dims[2]; }
};

/** One finite splat: centre, value (1 or 3 components used), radius (σ, or the falloff radius in MAX mode). */
struct Splat
{
  double Center[3];
  double Value[3];
  double Radius;
};

enum class Kind
{
  Sum,     // normalised Gaussians, added
  Distance // s·max(0, 1 - r/R), MAX-blended
};

/** Settings the backends need besides grid and splats. */
struct Settings
{
  Kind Mode = Kind::Sum;
  int Components = 3; // 3 (vector) or 1 (scalar)
  double Cutoff = 4;  // k: only voxels within kσ (per axis) are touched
  bool Integrate = true;
};

/** Index range [lo, hi] of the voxels a splat touches along one axis; false if none. */
inline bool AxisSpan(const Grid& g, int axis, double c, double reach, bool cellOverlap, int& lo, int& hi)
{
  const double o = g.Origin[axis];
  const double h = g.Spacing[axis];
  const int n = g.Dims[axis];
  if (n == 1)
  {
    // a one-point axis has no extent: the point is touched if within reach
    const bool inside = std::fabs(c - o) <= reach;
    lo = hi = 0;
    return inside;
  }
  // cellOverlap: voxels whose cell [x - h/2, x + h/2] meets [c - reach, c + reach];
  // else voxels whose centre lies in it.
  const double pad = cellOverlap ? 0.5 : 0.0;
  const double a = std::ceil((c - reach - o) / h - pad);
  const double b = std::floor((c + reach - o) / h + pad);
  if (!(a <= b) || b < 0 || a > n - 1)
  {
    return false;
  }
  lo = static_cast<int>(std::max(0.0, a));
  hi = static_cast<int>(std::min(double(n - 1), b));
  return lo <= hi;
}

/** ∫ from a to b of the unit normal pdf (in units of σ), without cancellation in the tails. */
inline double NormalMass(double a, double b)
{
  constexpr double s = 0.70710678118654752440; // 1/√2
  if (a >= 0)
  {
    return 0.5 * (std::erfc(a * s) - std::erfc(b * s));
  }
  if (b <= 0)
  {
    return 0.5 * (std::erfc(-b * s) - std::erfc(-a * s));
  }
  return 0.5 * (std::erf(b * s) - std::erf(a * s));
}

/**
 * The 1D factor of a normalised Gaussian splat at voxels lo..hi of one axis:
 * the average of the 1D normal pdf over each voxel's cell (Integrate), or
 * its value at the voxel centre. The 3D voxel value is value·wx·wy·wz, so the
 * sum over all voxels times the voxel volume is the splat's value (Integrate).
 * On a one-point axis the pdf is sampled at the point.
 */
inline void AxisWeights(const Grid& g, int axis, double c, double sigma, bool integrate, int lo, int hi, float* out)
{
  constexpr double invSqrt2Pi = 0.39894228040143267794;
  const double o = g.Origin[axis];
  const double h = g.Spacing[axis];
  const bool sample = !integrate || g.Dims[axis] == 1;
  if (sample && hi > lo)
  {
    // Samples at a uniform spacing d = h/σ follow a recurrence: w(u + d) =
    // w(u)·r with r itself multiplied by q = e^(−d²) each step, so a row
    // costs three exp() instead of one per voxel. Used where no factor can
    // under- or overflow a double (|u|, d² bounded); the rounding it adds is
    // ~1e-15 relative over a box, far below the float the weight is stored in.
    const double d = h / sigma;
    const double u0 = (o + lo * h - c) / sigma;
    const double u1 = (o + hi * h - c) / sigma;
    if (d <= 8.0 && std::fabs(u0) <= 25.0 && std::fabs(u1) <= 25.0)
    {
      double w = invSqrt2Pi / sigma * std::exp(-0.5 * u0 * u0);
      double r = std::exp(-(u0 * d + 0.5 * d * d));
      const double q = std::exp(-d * d);
      for (int i = lo; i <= hi; ++i)
      {
        out[i - lo] = static_cast<float>(w);
        w *= r;
        r *= q;
      }
      return;
    }
  }
  for (int i = lo; i <= hi; ++i)
  {
    const double x = o + i * h - c;
    double w;
    if (sample)
    {
      const double u = x / sigma;
      w = invSqrt2Pi / sigma * std::exp(-0.5 * u * u);
    }
    else
    {
      w = NormalMass((x - 0.5 * h) / sigma, (x + 0.5 * h) / sigma) / h;
    }
    out[i - lo] = static_cast<float>(w);
  }
}
}
}

#endif
