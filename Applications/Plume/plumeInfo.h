// `plume info`: what a dataset holds (type, blocks, sizes, geometry, arrays, time steps).
#ifndef plumeInfo_h
#define plumeInfo_h

#include <ostream>

class vtkPlumeDatasetReader;

namespace plume
{
/**
 * Update `configuredReader` (file, reader name, time step, blocks already set) and print what
 * the dataset holds on `out`: the data type; for composites each block's name, type and size;
 * points and cells; dimensions (structured grids and images), bounds, origin and spacing
 * (images); point, cell and field arrays with component count, value type and range (per
 * component, and the magnitude for vectors); the time steps (count and values) and the step
 * read. Human-readable text, or JSON (one object) when `json` is true.
 *
 * Returns 0 on success. On failure prints one line "plume info: <message>" on `err` (the
 * reader's GetLastError()) and returns 1 (2 for a null reader).
 */
int RunInfo(vtkPlumeDatasetReader* configuredReader, bool json, std::ostream& out,
  std::ostream& err);
}

#endif
