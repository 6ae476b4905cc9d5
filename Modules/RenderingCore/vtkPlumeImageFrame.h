// The one index -> physical frame of an image, for every renderer that
// samples image data as a texture (volume, glyphs, splats): texture index i
// (0-based over the extent) lands at origin + D (spacing * (extent start + i)),
// D the image's direction matrix, composed in double. Renderers that each
// wrote their own disagreed (the glyph mapper ignored D and the extent start).
#ifndef vtkPlumeImageFrame_h
#define vtkPlumeImageFrame_h

#include "vtkImageData.h"
#include "vtkMatrix3x3.h"

namespace plume
{
/** Row-major 4x4 matrix from 0-based texture index to the image's physical (model) coordinates. */
inline void IndexToPhysical(vtkImageData* image, double m[16])
{
  int extent[6];
  double spacing[3], origin[3];
  image->GetExtent(extent);
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  const double* dir = image->GetDirectionMatrix()->GetData();
  for (int r = 0; r < 3; ++r)
  {
    m[4 * r + 3] = origin[r];
    for (int c = 0; c < 3; ++c)
    {
      m[4 * r + c] = dir[3 * r + c] * spacing[c];
      m[4 * r + 3] += dir[3 * r + c] * spacing[c] * extent[2 * c];
    }
  }
  m[12] = m[13] = m[14] = 0.0;
  m[15] = 1.0;
}
}

#endif
