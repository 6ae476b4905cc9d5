#include "plumeTestSupport.h"

#include "vtkPlumeDatasetReader.h"
#include "vtkPlumeResampleToImage.h"

#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkRenderWindow.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace plume
{
namespace test
{

std::string DataDirectory()
{
  const char* env = std::getenv("PLUME_DATA_DIR");
  return (env && *env) ? std::string(env) : std::string(PLUME_DATA_DIR);
}

std::string DataPath(const std::string& relative)
{
  return DataDirectory() + "/" + relative;
}

vtkSmartPointer<vtkDataObject> LoadDataset(const std::string& relative)
{
  vtkNew<vtkPlumeDatasetReader> reader;
  reader->SetFileName(DataPath(relative).c_str());
  reader->Update();
  vtkDataObject* output = reader->GetOutputDataObject(0);
  if (!output || !reader->GetLastError().empty())
  {
    std::cerr << "LoadDataset(" << relative << "): " << reader->GetLastError() << "\n";
    return nullptr;
  }
  return output;
}

vtkSmartPointer<vtkImageData> LoadImage(const std::string& relative, int maxDimension)
{
  vtkNew<vtkPlumeDatasetReader> reader;
  reader->SetFileName(DataPath(relative).c_str());
  vtkNew<vtkPlumeResampleToImage> resample;
  resample->SetInputConnection(reader->GetOutputPort());
  resample->SetMaximumDimension(maxDimension);
  resample->Update();
  if (!reader->GetLastError().empty())
  {
    std::cerr << "LoadImage(" << relative << "): " << reader->GetLastError() << "\n";
    return nullptr;
  }
  return resample->GetOutput();
}

vtkSmartPointer<vtkRenderWindow> MakeOffscreenWindow(int width, int height)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0); // identical pixels run to run; baselines assume no MSAA
  window->SetSize(width, height);
  return window;
}


ImageError Compare(const FloatImage& a, const FloatImage& b, int channels)
{
  ImageError error;
  if (a.Width != b.Width || a.Height != b.Height)
  {
    error.RMS = error.Max = HUGE_VAL;
    return error;
  }
  double sum = 0;
  size_t count = 0;
  const size_t n = static_cast<size_t>(a.Width) * a.Height;
  for (size_t p = 0; p < n; ++p)
  {
    for (int c = 0; c < channels; ++c)
    {
      const double d = std::fabs(double(a.RGBA[4 * p + c]) - double(b.RGBA[4 * p + c]));
      sum += d * d;
      error.Max = std::max(error.Max, std::isnan(d) ? HUGE_VAL : d);
      ++count;
    }
  }
  error.RMS = count ? std::sqrt(sum / count) : 0;
  return error;
}


size_t CountForeground(const FloatImage& image, const double background[3], double tolerance)
{
  size_t count = 0;
  const size_t n = static_cast<size_t>(image.Width) * image.Height;
  for (size_t p = 0; p < n; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (std::fabs(image.RGBA[4 * p + c] - background[c]) > tolerance)
      {
        ++count;
        break;
      }
    }
  }
  return count;
}


}
}
