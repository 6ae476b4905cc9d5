// plumeImageCompare A.png B.png [--exact | --rms R --max-fraction F]
// Compares two 8-bit images: --exact requires identical RGB; otherwise the RMS
// difference (0..255 units) must be <= R and the fraction of pixels differing
// by more than 16 in any channel <= F. Both images must be non-trivial (not a
// single colour), so an empty render never passes against an empty baseline.
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkSmartPointer.h"

#include <cmath>
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

bool SingleColour(vtkImageData* image)
{
  const int* d = image->GetDimensions();
  const int c = image->GetNumberOfScalarComponents();
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer());
  for (long i = 1; i < static_cast<long>(d[0]) * d[1]; ++i)
  {
    for (int k = 0; k < std::min(c, 3); ++k)
    {
      if (p[i * c + k] != p[k])
      {
        return false;
      }
    }
  }
  return true;
}
}

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: plumeImageCompare A.png B.png [--exact | --rms R --max-fraction F]\n";
    return 2;
  }
  bool exact = false;
  double rmsLimit = 2.0, fractionLimit = 0.002;
  for (int i = 3; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--exact")
    {
      exact = true;
    }
    else if (a == "--rms" && i + 1 < argc)
    {
      rmsLimit = std::atof(argv[++i]);
    }
    else if (a == "--max-fraction" && i + 1 < argc)
    {
      fractionLimit = std::atof(argv[++i]);
    }
    else
    {
      std::cerr << "unknown argument '" << a << "'\n";
      return 2;
    }
  }
  auto a = Load(argv[1]);
  auto b = Load(argv[2]);
  if (!a || !b)
  {
    return 1;
  }
  const int* da = a->GetDimensions();
  const int* db = b->GetDimensions();
  if (da[0] != db[0] || da[1] != db[1])
  {
    std::cerr << "size differs: " << da[0] << "x" << da[1] << " vs " << db[0] << "x" << db[1] << "\n";
    return 1;
  }
  if (SingleColour(a) || SingleColour(b))
  {
    std::cerr << "an image is a single colour (nothing rendered?)\n";
    return 1;
  }
  const int ca = a->GetNumberOfScalarComponents(), cb = b->GetNumberOfScalarComponents();
  auto* pa = static_cast<unsigned char*>(a->GetScalarPointer());
  auto* pb = static_cast<unsigned char*>(b->GetScalarPointer());
  const long n = static_cast<long>(da[0]) * da[1];
  double sum = 0;
  long differing = 0, big = 0;
  for (long i = 0; i < n; ++i)
  {
    int worst = 0;
    for (int k = 0; k < 3; ++k)
    {
      const int d = std::abs(int(pa[i * ca + k]) - int(pb[i * cb + k]));
      sum += double(d) * d;
      worst = std::max(worst, d);
    }
    differing += worst > 0;
    big += worst > 16;
  }
  const double rms = std::sqrt(sum / (3.0 * n));
  const double fraction = double(big) / n;
  std::cout << "rms " << rms << " differing pixels " << differing << " (>16: " << big << ", fraction " << fraction
            << ")\n";
  if (exact)
  {
    return differing == 0 ? 0 : 1;
  }
  return (rms <= rmsLimit && fraction <= fractionLimit) ? 0 : 1;
}
