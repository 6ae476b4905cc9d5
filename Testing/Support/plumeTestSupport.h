// Shared helpers for Plume's tests and benchmarks: datasets by name, offscreen
// windows, float read-back of colour and depth, image error metrics, and
// PLUME_CHECK (counts a failed condition in the caller's `int failures`).
#ifndef plumeTestSupport_h
#define plumeTestSupport_h

#include "vtkSmartPointer.h"

#include <iostream>
#include <string>
#include <vector>

class vtkDataObject;
class vtkImageData;
class vtkRenderWindow;

namespace plume
{
namespace test
{
/** Folder of the shared CFD datasets: $PLUME_DATA_DIR if set, else the configured default. */
std::string DataDirectory();

/** Absolute path of a dataset given relative to the data folder, e.g. "classic/carotid.vtk". */
std::string DataPath(const std::string& relative);

/**
 * Load a dataset by its path relative to the data folder with vtkPlumeDatasetReader
 * (format from the extension). Returns nullptr and prints the reader's message on failure.
 */
vtkSmartPointer<vtkDataObject> LoadDataset(const std::string& relative);

/** Load and, if needed, resample onto an image of about `maxDimension` points along the longest axis. */
vtkSmartPointer<vtkImageData> LoadImage(const std::string& relative, int maxDimension = 64);

/** An offscreen render window of the given size (needs a display; tests run under Xvfb). */
vtkSmartPointer<vtkRenderWindow> MakeOffscreenWindow(int width, int height);

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
FloatImage ReadBack(vtkRenderWindow* window, bool render = true);

/** Root-mean-square and maximum absolute difference over the first `channels` channels. */
struct ImageError
{
  double RMS = 0;
  double Max = 0;
};
ImageError Compare(const FloatImage& a, const FloatImage& b, int channels = 3);

/** True if any colour or depth value is NaN or infinite. */
bool HasNonFinite(const FloatImage& image);

/** Number of pixels whose RGB differs from `background` by more than `tolerance`. */
size_t CountForeground(const FloatImage& image, const double background[3], double tolerance = 1.0 / 255);

/** Drain the GL error queue of the window's context; returns a description or "" when clean. */
std::string GLErrors(vtkRenderWindow* window);
}
}

/** Report a failed condition (file:line and the condition) and count it in the caller's `failures`. */
#define PLUME_CHECK(cond)                                                                          \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #cond << std::endl;           \
      ++failures;                                                                                  \
    }                                                                                              \
  } while (false)

#endif
