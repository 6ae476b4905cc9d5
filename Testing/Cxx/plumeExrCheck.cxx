// plumeExrCheck FILE.exr W H [FILE.png]: the EXR written by `plume render` has
// float channels R, G, B, A and Z of the given size, finite non-negative
// colour everywhere (linear, may exceed 1), A = 1, a finite positive Z on
// drawn pixels and +inf Z on some background pixels. With the PNG of the same
// scene: the EXR matches it to within the 8-bit rounding away from edges
// (the window multisamples, the float framebuffer does not), and is not itself
// 8-bit (most colour values between 0 and 1 lie off the k/255 lattice: it
// comes from a float framebuffer, not the window's 8-bit one).
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

int main(int argc, char* argv[])
{
  if (argc != 4 && argc != 5)
  {
    std::cerr << "usage: plumeExrCheck FILE.exr W H [FILE.png]\n";
    return 2;
  }
  try
  {
    Imf::InputFile file(argv[1]);
    const Imath::Box2i window = file.header().dataWindow();
    const int w = window.max.x - window.min.x + 1, h = window.max.y - window.min.y + 1;
    if (w != std::atoi(argv[2]) || h != std::atoi(argv[3]))
    {
      std::cerr << "size " << w << "x" << h << " differs from the expected one\n";
      return 1;
    }
    const char* names[5] = { "R", "G", "B", "A", "Z" };
    std::vector<float> channels[5];
    Imf::FrameBuffer frame;
    for (int c = 0; c < 5; ++c)
    {
      const Imf::Channel* channel = file.header().channels().findChannel(names[c]);
      if (!channel || channel->type != Imf::FLOAT)
      {
        std::cerr << "channel " << names[c] << " missing or not FLOAT\n";
        return 1;
      }
      channels[c].resize(static_cast<size_t>(w) * h);
      frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(channels[c].data()), sizeof(float),
                               sizeof(float) * w));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    size_t drawn = 0, background = 0;
    for (size_t p = 0; p < channels[0].size(); ++p)
    {
      for (int c = 0; c < 3; ++c)
      {
        if (!std::isfinite(channels[c][p]) || channels[c][p] < 0)
        {
          std::cerr << "colour channel " << names[c] << " negative or not finite at pixel " << p << "\n";
          return 1;
        }
      }
      if (channels[3][p] != 1.0f)
      {
        std::cerr << "alpha " << channels[3][p] << " is not 1 at pixel " << p << "\n";
        return 1;
      }
      const float z = channels[4][p];
      if (std::isinf(z) && z > 0)
      {
        ++background;
      }
      else if (std::isfinite(z) && z > 0)
      {
        ++drawn;
      }
      else
      {
        std::cerr << "bad depth " << z << " at pixel " << p << "\n";
        return 1;
      }
    }
    std::cout << drawn << " drawn pixels, " << background << " background pixels\n";
    if (drawn == 0 || background == 0)
    {
      return 1;
    }
    if (argc == 5)
    {
      vtkNew<vtkPNGReader> reader;
      reader->SetFileName(argv[4]);
      reader->Update();
      vtkImageData* png = reader->GetOutput();
      int dims[3];
      png->GetDimensions(dims);
      if (dims[0] != w || dims[1] != h || png->GetNumberOfScalarComponents() < 3)
      {
        std::cerr << "the PNG is not a " << w << "x" << h << " RGB image\n";
        return 1;
      }
      // The window multisamples (the PNG's edges are antialiased), the float
      // framebuffer does not: edges differ, everything else must agree to
      // within the 8-bit rounding.
      std::vector<double> differences;
      size_t between = 0, offLattice = 0;
      for (int y = 0; y < h; ++y)
      {
        for (int x = 0; x < w; ++x)
        {
          const size_t p = static_cast<size_t>(h - 1 - y) * w + x; // EXR rows top to bottom
          for (int c = 0; c < 3; ++c)
          {
            const double e = channels[c][p];
            const double q = png->GetScalarComponentAsDouble(x, y, 0, c) / 255.0;
            differences.push_back(std::fabs(std::min(e, 1.0) - q) * 255.0);
            if (e > 0.01 && e < 0.99)
            {
              ++between;
              offLattice += std::fabs(e * 255.0 - std::round(e * 255.0)) > 0.01;
            }
          }
        }
      }
      std::sort(differences.begin(), differences.end());
      const double median = differences[differences.size() / 2];
      const double p95 = differences[differences.size() * 95 / 100];
      const double fraction = between ? double(offLattice) / between : 0.0;
      std::cout << "vs PNG: median " << median << ", 95th percentile " << p95 << " 8-bit steps; " << offLattice
                << " of " << between << " values in (0,1) off the 8-bit lattice\n";
      if (median > 0.5 || p95 > 2.0 || between < 100 || fraction < 0.5)
      {
        std::cerr << "the EXR does not look like an unquantised float render of the PNG's scene\n";
        return 1;
      }
    }
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "cannot read EXR: " << e.what() << "\n";
    return 1;
  }
}
