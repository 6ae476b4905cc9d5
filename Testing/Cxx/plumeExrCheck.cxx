// plumeExrCheck FILE.exr W H: the EXR written by `plume render` has float
// channels R, G, B, A and Z of the given size, finite colour everywhere, a
// finite positive Z on drawn pixels and +inf Z on some background pixels.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

int main(int argc, char* argv[])
{
  if (argc != 4)
  {
    std::cerr << "usage: plumeExrCheck FILE.exr W H\n";
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
      for (int c = 0; c < 4; ++c)
      {
        if (!std::isfinite(channels[c][p]) || channels[c][p] < 0 || channels[c][p] > 1)
        {
          std::cerr << "colour channel " << names[c] << " out of [0,1] at pixel " << p << "\n";
          return 1;
        }
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
    return (drawn > 0 && background > 0) ? 0 : 1;
  }
  catch (const std::exception& e)
  {
    std::cerr << "cannot read EXR: " << e.what() << "\n";
    return 1;
  }
}
