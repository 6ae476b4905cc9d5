// Reading a rendered frame back as floats (colour and window depth) and the
// GL error queue: what `plume render` writes to PNG/EXR and what tests and
// benchmarks compare. Product code: the tests use it, not the other way round.
#ifndef vtkPlumeFrameReadBack_h
#define vtkPlumeFrameReadBack_h

#include "PlumeRenderingCoreModule.h" // For export macro

#include <string> // For std::string
#include <vector> // For std::vector

class vtkRenderWindow;

namespace plume
{
/** Colour (RGBA, 0..1) and depth (0..1 window depth) of a rendered window, bottom row first. */
struct FloatImage
{
  int Width = 0;
  int Height = 0;
  std::vector<float> RGBA;  // Width*Height*4
  std::vector<float> Depth; // Width*Height
  const float* Pixel(int x, int y) const { return &this->RGBA[4 * (static_cast<size_t>(y) * this->Width + x)]; }
};

/** Read back the last rendered frame of `window` (renders first if `render` is true). */
PLUMERENDERINGCORE_EXPORT FloatImage ReadBack(vtkRenderWindow* window, bool render = true);

/** True if any colour or depth value is NaN or infinite. */
PLUMERENDERINGCORE_EXPORT bool HasNonFinite(const FloatImage& image);

/** Drain the GL error queue of the window's context; returns a description or "" when clean. */
PLUMERENDERINGCORE_EXPORT std::string GLErrors(vtkRenderWindow* window);
}

#endif
// VTK-HeaderTest-Exclude: vtkPlumeFrameReadBack.h
