// CPU backend of vtkPlumeGaussianSplatter (vtkSMPTools).
#ifndef plumeSplatCPU_h
#define plumeSplatCPU_h

#include "plumeSplatKernel.h"

namespace plume
{
namespace splat
{
/**
 * Adds (Sum) or MAX-blends (Distance) all splats into `out` (Grid::Voxels() ×
 * Components floats, x fastest; zeroed here, each slab by the task that owns
 * it, so the first touch of a freshly allocated grid, whose page faults cost
 * more than the splats when they are few, is spread over the threads). Race-free and deterministic
 * whatever the thread count: the grid is cut into z-slabs whose size does not
 * depend on the threads, each slab is owned by one task, and each task visits
 * the splats touching its slab in input order, so every voxel sees the same
 * sequence of float additions. Returns the number of splats that touched the grid.
 */
size_t SplatCPU(const Grid& grid, const Settings& settings, const std::vector<Splat>& splats, float* out);
}
}

#endif
