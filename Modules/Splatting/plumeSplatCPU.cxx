#include "plumeSplatCPU.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>

namespace plume
{
namespace splat
{
namespace
{
// A splat clipped to the grid: its voxel box and (Sum) its 1D weights.
struct Footprint
{
  int Lo[3];
  int Hi[3];
  size_t WeightOffset; // into the weight arena: x weights, then y, then z
};

constexpr int SlabThickness = 2; // z slices per task; fixed, so results never depend on threads
}

size_t SplatCPU(const Grid& grid, const Settings& settings, const std::vector<Splat>& splats, float* out)
{
  const bool sum = settings.Mode == Kind::Sum;
  // 1. footprints (sequential: cheap, and gives the weight offsets in order)
  std::vector<Footprint> prints;
  std::vector<size_t> owner; // splat index of each footprint
  prints.reserve(splats.size());
  owner.reserve(splats.size());
  size_t weights = 0;
  for (size_t s = 0; s < splats.size(); ++s)
  {
    const Splat& sp = splats[s];
    const double reach = sum ? settings.Cutoff * sp.Radius : sp.Radius;
    Footprint f;
    bool touches = true;
    for (int a = 0; a < 3 && touches; ++a)
    {
      touches = AxisSpan(grid, a, sp.Center[a], reach, sum && settings.Integrate, f.Lo[a], f.Hi[a]);
    }
    if (!touches)
    {
      continue;
    }
    f.WeightOffset = weights;
    if (sum)
    {
      weights += size_t(f.Hi[0] - f.Lo[0] + 1) + (f.Hi[1] - f.Lo[1] + 1) + (f.Hi[2] - f.Lo[2] + 1);
    }
    prints.push_back(f);
    owner.push_back(s);
  }
  // 2. 1D weights, in parallel over splats (each writes its own range)
  std::vector<float> arena(weights);
  if (sum)
  {
    vtkSMPTools::For(0, static_cast<vtkIdType>(prints.size()), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType p = begin; p < end; ++p)
      {
        const Footprint& f = prints[p];
        const Splat& sp = splats[owner[p]];
        float* w = arena.data() + f.WeightOffset;
        for (int a = 0; a < 3; ++a)
        {
          AxisWeights(grid, a, sp.Center[a], sp.Radius, settings.Integrate, f.Lo[a], f.Hi[a], w);
          w += f.Hi[a] - f.Lo[a] + 1;
        }
      }
    });
  }
  // 3. slab lists (CSR, input order kept)
  const int nz = grid.Dims[2];
  const int slabs = (nz + SlabThickness - 1) / SlabThickness;
  std::vector<size_t> start(slabs + 1, 0);
  for (const Footprint& f : prints)
  {
    for (int b = f.Lo[2] / SlabThickness; b <= f.Hi[2] / SlabThickness; ++b)
    {
      ++start[b + 1];
    }
  }
  for (int b = 0; b < slabs; ++b)
  {
    start[b + 1] += start[b];
  }
  std::vector<size_t> members(start[slabs]);
  {
    std::vector<size_t> fill(start.begin(), start.end() - 1);
    for (size_t p = 0; p < prints.size(); ++p)
    {
      for (int b = prints[p].Lo[2] / SlabThickness; b <= prints[p].Hi[2] / SlabThickness; ++b)
      {
        members[fill[b]++] = p;
      }
    }
  }
  // 4. each slab owned by one task
  const int comps = settings.Components;
  const size_t nx = grid.Dims[0];
  const size_t nxy = nx * grid.Dims[1];
  vtkSMPTools::For(0, slabs, 1, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType b = begin; b < end; ++b)
    {
      const int z0 = static_cast<int>(b) * SlabThickness;
      const int z1 = std::min(nz - 1, z0 + SlabThickness - 1);
      std::fill(out + comps * (z0 * nxy), out + comps * ((z1 + 1) * nxy), 0.0f);
      for (size_t m = start[b]; m < start[b + 1]; ++m)
      {
        const Footprint& f = prints[members[m]];
        const Splat& sp = splats[owner[members[m]]];
        const int k0 = std::max(z0, f.Lo[2]);
        const int k1 = std::min(z1, f.Hi[2]);
        if (sum)
        {
          const int wx = f.Hi[0] - f.Lo[0] + 1;
          const int wy = f.Hi[1] - f.Lo[1] + 1;
          const float* Wx = arena.data() + f.WeightOffset;
          const float* Wy = Wx + wx;
          const float* Wz = Wy + wy;
          const float v[3] = { float(sp.Value[0]), float(sp.Value[1]), float(sp.Value[2]) };
          for (int k = k0; k <= k1; ++k)
          {
            const float az = Wz[k - f.Lo[2]];
            for (int j = 0; j < wy; ++j)
            {
              const float ayz = az * Wy[j];
              float* row = out + comps * (k * nxy + (f.Lo[1] + j) * nx + f.Lo[0]);
              if (comps == 3)
              {
                for (int i = 0; i < wx; ++i)
                {
                  const float w = ayz * Wx[i];
                  row[3 * i] += v[0] * w;
                  row[3 * i + 1] += v[1] * w;
                  row[3 * i + 2] += v[2] * w;
                }
              }
              else
              {
                for (int i = 0; i < wx; ++i)
                {
                  row[i] += v[0] * (ayz * Wx[i]);
                }
              }
            }
          }
        }
        else
        {
          const double R = sp.Radius;
          for (int k = k0; k <= k1; ++k)
          {
            const double dz = grid.Origin[2] + k * grid.Spacing[2] - sp.Center[2];
            for (int j = f.Lo[1]; j <= f.Hi[1]; ++j)
            {
              const double dy = grid.Origin[1] + j * grid.Spacing[1] - sp.Center[1];
              float* row = out + comps * (k * nxy + j * nx);
              for (int i = f.Lo[0]; i <= f.Hi[0]; ++i)
              {
                const double dx = grid.Origin[0] + i * grid.Spacing[0] - sp.Center[0];
                const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
                if (r < R)
                {
                  const float val = static_cast<float>(sp.Value[0] * (1.0 - r / R));
                  row[comps * i] = std::max(row[comps * i], val);
                }
              }
            }
          }
        }
      }
    }
  });
  return prints.size();
}
}
}
