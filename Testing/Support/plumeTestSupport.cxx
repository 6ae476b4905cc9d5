#include "plumeTestSupport.h"

#include "vtkPlumeDatasetReader.h"
#include "vtkPlumeResampleToImage.h"

#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderWindow.h"
#include "vtk_glew.h"

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

FloatImage ReadBack(vtkRenderWindow* window, bool render)
{
  if (render)
  {
    window->Render();
  }
  FloatImage image;
  const int* size = window->GetSize();
  image.Width = size[0];
  image.Height = size[1];
  vtkNew<vtkFloatArray> rgba;
  window->GetRGBAPixelData(0, 0, image.Width - 1, image.Height - 1, 0, rgba, 0);
  image.RGBA.assign(rgba->GetPointer(0), rgba->GetPointer(0) + 4 * static_cast<size_t>(image.Width) * image.Height);
  image.Depth.resize(static_cast<size_t>(image.Width) * image.Height);
  window->GetZbufferData(0, 0, image.Width - 1, image.Height - 1, image.Depth.data());
  return image;
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

bool HasNonFinite(const FloatImage& image)
{
  for (float v : image.RGBA)
  {
    if (!std::isfinite(v))
    {
      return true;
    }
  }
  for (float v : image.Depth)
  {
    if (!std::isfinite(v))
    {
      return true;
    }
  }
  return false;
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

std::string GLErrors(vtkRenderWindow* window)
{
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!gl)
  {
    return "not an OpenGL render window";
  }
  gl->MakeCurrent();
  std::ostringstream out;
  for (int i = 0; i < 16; ++i)
  {
    const GLenum e = glGetError();
    if (e == GL_NO_ERROR)
    {
      break;
    }
    out << "GL error 0x" << std::hex << e << std::dec << " ";
  }
  return out.str();
}

}
}
