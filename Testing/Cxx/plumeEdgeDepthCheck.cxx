// plumeEdgeDepthCheck BOTH.png LINES.png VOLUME.png MAX_MEAN MAX_FRACTION
// Opaque lines in front of a volume must look as they do alone: over the
// pixels where the lines-only image shows a line (any channel > 24 from its
// background, the corner pixel) and the volume-only image shows the volume,
// the lines+volume image must match the lines-only one: the mean of the
// largest channel difference <= MAX_MEAN and the fraction of those pixels
// differing by more than 48 <= MAX_FRACTION. (Anti-aliased edge pixels whose
// depth came from a background sample let the volume cover the line: dashed
// lines, issue 15.) Prints the numbers; exit 0 pass, 1 fail, 2 bad input.
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
vtkSmartPointer<vtkImageData> Load(const std::string& path)
{
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    std::cerr << "cannot read PNG '" << path << "'\n";
    return nullptr;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

int Channel(vtkImageData* image, int x, int y, int c)
{
  return static_cast<int>(image->GetScalarComponentAsDouble(x, y, 0, c));
}

int Difference(vtkImageData* a, int ax, int ay, vtkImageData* b, int bx, int by)
{
  int d = 0;
  for (int c = 0; c < 3; ++c)
  {
    d = std::max(d, std::abs(Channel(a, ax, ay, c) - Channel(b, bx, by, c)));
  }
  return d;
}
}

int main(int argc, char* argv[])
{
  if (argc != 6)
  {
    std::cerr << "usage: plumeEdgeDepthCheck BOTH.png LINES.png VOLUME.png MAX_MEAN MAX_FRACTION\n";
    return 2;
  }
  auto both = Load(argv[1]);
  auto lines = Load(argv[2]);
  auto volume = Load(argv[3]);
  if (!both || !lines || !volume)
  {
    return 2;
  }
  int dims[3], d2[3], d3[3];
  both->GetDimensions(dims);
  lines->GetDimensions(d2);
  volume->GetDimensions(d3);
  if (dims[0] != d2[0] || dims[1] != d2[1] || dims[0] != d3[0] || dims[1] != d3[1])
  {
    std::cerr << "images differ in size\n";
    return 2;
  }
  long count = 0, off = 0;
  double sum = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      const bool line = Difference(lines, x, y, lines, 0, 0) > 24;
      const bool behind = Difference(volume, x, y, volume, 0, 0) > 24;
      if (!line || !behind)
      {
        continue;
      }
      const int d = Difference(both, x, y, lines, x, y);
      ++count;
      sum += d;
      off += d > 48 ? 1 : 0;
    }
  }
  if (count < 20)
  {
    std::cerr << "only " << count << " line pixels over the volume: the scene does not test anything\n";
    return 2;
  }
  const double mean = sum / count;
  const double fraction = double(off) / count;
  std::cout << count << " line pixels over the volume: mean difference " << mean << ", fraction over 48: "
            << fraction << "\n";
  return mean <= std::atof(argv[4]) && fraction <= std::atof(argv[5]) ? 0 : 1;
}
