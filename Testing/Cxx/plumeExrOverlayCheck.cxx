// plumeExrOverlayCheck ON.exr OFF.exr ON.png OFF.png: the overlay (colour
// bars, title, time label) is in the EXR as in the PNG. The overlay pixels
// are where the two PNGs (the same scene with and without the overlay)
// differ by more than 32 levels; there the two EXRs must differ by more than
// 16 (the overlay was drawn into the float framebuffer too), and where the
// PNGs agree (within 2 levels: not the overlay's antialiased fringe) the two
// EXRs must agree too (only the overlay changed).
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
struct Rgb
{
  int Width = 0, Height = 0;
  std::vector<double> Values; // rows bottom to top, 3 per pixel, 0..255
  double At(int x, int y, int c) const { return this->Values[(static_cast<size_t>(y) * this->Width + x) * 3 + c]; }
};

Rgb ReadExr(const char* path)
{
  Imf::InputFile file(path);
  const Imath::Box2i window = file.header().dataWindow();
  Rgb image;
  image.Width = window.max.x - window.min.x + 1;
  image.Height = window.max.y - window.min.y + 1;
  std::vector<float> channels[3];
  Imf::FrameBuffer frame;
  const char* names[3] = { "R", "G", "B" };
  for (int c = 0; c < 3; ++c)
  {
    channels[c].resize(static_cast<size_t>(image.Width) * image.Height);
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(channels[c].data()), sizeof(float),
                             sizeof(float) * image.Width));
  }
  file.setFrameBuffer(frame);
  file.readPixels(window.min.y, window.max.y);
  image.Values.resize(static_cast<size_t>(image.Width) * image.Height * 3);
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      const size_t p = static_cast<size_t>(image.Height - 1 - y) * image.Width + x; // EXR rows top to bottom
      for (int c = 0; c < 3; ++c)
      {
        image.Values[(static_cast<size_t>(y) * image.Width + x) * 3 + c] =
          255.0 * std::min(1.0, std::max(0.0, double(channels[c][p])));
      }
    }
  }
  return image;
}

Rgb ReadPng(const char* path)
{
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path);
  reader->Update();
  vtkImageData* png = reader->GetOutput();
  int dims[3];
  png->GetDimensions(dims);
  if (png->GetNumberOfScalarComponents() < 3)
  {
    throw std::runtime_error(std::string("cannot read an RGB PNG from ") + path);
  }
  Rgb image;
  image.Width = dims[0];
  image.Height = dims[1];
  image.Values.resize(static_cast<size_t>(dims[0]) * dims[1] * 3);
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        image.Values[(static_cast<size_t>(y) * dims[0] + x) * 3 + c] = png->GetScalarComponentAsDouble(x, y, 0, c);
      }
    }
  }
  return image;
}

double MaxDifference(const Rgb& a, const Rgb& b, int x, int y)
{
  double d = 0;
  for (int c = 0; c < 3; ++c)
  {
    d = std::max(d, std::fabs(a.At(x, y, c) - b.At(x, y, c)));
  }
  return d;
}
}

int main(int argc, char* argv[])
{
  if (argc != 5)
  {
    std::cerr << "usage: plumeExrOverlayCheck ON.exr OFF.exr ON.png OFF.png\n";
    return 2;
  }
  try
  {
    const Rgb exrOn = ReadExr(argv[1]), exrOff = ReadExr(argv[2]), pngOn = ReadPng(argv[3]), pngOff = ReadPng(argv[4]);
    for (const Rgb* image : { &exrOff, &pngOn, &pngOff })
    {
      if (image->Width != exrOn.Width || image->Height != exrOn.Height)
      {
        std::cerr << "the four images must have one size\n";
        return 1;
      }
    }
    size_t overlay = 0, overlayInExr = 0, rest = 0, restChanged = 0;
    for (int y = 0; y < exrOn.Height; ++y)
    {
      for (int x = 0; x < exrOn.Width; ++x)
      {
        const double exr = MaxDifference(exrOn, exrOff, x, y);
        const double png = MaxDifference(pngOn, pngOff, x, y);
        if (png > 32)
        {
          ++overlay;
          overlayInExr += exr > 16;
        }
        else if (png <= 2) // not the overlay's antialiased fringe either
        {
          ++rest;
          restChanged += exr > 16;
        }
      }
    }
    std::cout << overlay << " overlay pixels in the PNG, " << overlayInExr << " of them in the EXR; " << restChanged
              << " of the other " << rest << " pixels changed in the EXR\n";
    // edges of text are antialiased in the PNG only (the float framebuffer does
    // not multisample): most, not all, overlay pixels differ as much in the EXR
    if (overlay < 100 || overlayInExr < 0.8 * overlay || restChanged > 0.02 * overlay)
    {
      std::cerr << "the EXR does not hold the PNG's overlay\n";
      return 1;
    }
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "cannot read: " << e.what() << "\n";
    return 1;
  }
}
