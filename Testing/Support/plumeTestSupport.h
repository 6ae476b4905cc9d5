// Shared helpers for Plume's tests and benchmarks: datasets by name, offscreen
// windows, float read-back of colour and depth, image error metrics, and
// PLUME_CHECK (counts a failed condition in the caller's `int failures`).
#ifndef plumeTestSupport_h
#define plumeTestSupport_h

#include "vtkPlumeFrameReadBack.h" // For FloatImage, ReadBack, GLErrors, HasNonFinite
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

// Frame read-back is product code (plume render writes it); the tests use it
// under their own names.
using plume::FloatImage;
using plume::ReadBack;

/** Root-mean-square and maximum absolute difference over the first `channels` channels. */
struct ImageError
{
  double RMS = 0;
  double Max = 0;
};
ImageError Compare(const FloatImage& a, const FloatImage& b, int channels = 3);

using plume::HasNonFinite;

/** Number of pixels whose RGB differs from `background` by more than `tolerance`. */
size_t CountForeground(const FloatImage& image, const double background[3], double tolerance = 1.0 / 255);

using plume::GLErrors;
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
