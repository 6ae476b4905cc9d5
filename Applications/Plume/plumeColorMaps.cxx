#include "plumeColorMaps.h"

#include "vtkColorTransferFunction.h"

#include <iterator>

namespace plume
{

const std::vector<std::string>& ColorMapNames()
{
  static const std::vector<std::string> names = { "viridis", "inferno", "coolwarm", "grayscale", "rainbow" };
  return names;
}

vtkSmartPointer<vtkScalarsToColors> MakeColorMap(const std::string& name, double min, double max)
{
  struct Stop
  {
    double t, r, g, b;
  };
  // Samples of matplotlib's viridis and inferno at t = 0, .25, .5, .75, 1.
  static const Stop viridis[] = { { 0, 0.267, 0.005, 0.329 }, { 0.25, 0.229, 0.322, 0.546 },
    { 0.5, 0.128, 0.567, 0.551 }, { 0.75, 0.369, 0.789, 0.383 }, { 1, 0.993, 0.906, 0.144 } };
  static const Stop inferno[] = { { 0, 0.001, 0.000, 0.014 }, { 0.25, 0.342, 0.062, 0.429 },
    { 0.5, 0.735, 0.216, 0.330 }, { 0.75, 0.978, 0.557, 0.035 }, { 1, 0.988, 0.998, 0.645 } };
  static const Stop coolwarm[] = { { 0, 0.230, 0.299, 0.754 }, { 1, 0.706, 0.016, 0.150 } };
  static const Stop grayscale[] = { { 0, 0, 0, 0 }, { 1, 1, 1, 1 } };
  static const Stop rainbow[] = { { 0, 0, 0, 1 }, { 0.5, 0, 1, 0 }, { 1, 1, 0, 0 } };

  auto ctf = vtkSmartPointer<vtkColorTransferFunction>::New();
  const Stop* begin = nullptr;
  const Stop* end = nullptr;
  if (name == "viridis")
  {
    begin = std::begin(viridis), end = std::end(viridis);
  }
  else if (name == "inferno")
  {
    begin = std::begin(inferno), end = std::end(inferno);
  }
  else if (name == "coolwarm")
  {
    ctf->SetColorSpaceToDiverging();
    begin = std::begin(coolwarm), end = std::end(coolwarm);
  }
  else if (name == "grayscale")
  {
    begin = std::begin(grayscale), end = std::end(grayscale);
  }
  else if (name == "rainbow")
  {
    ctf->SetColorSpaceToHSV();
    begin = std::begin(rainbow), end = std::end(rainbow);
  }
  else
  {
    return nullptr;
  }
  if (!(max > min))
  {
    max = min + 1; // a constant field still maps to the low end
  }
  for (const Stop* s = begin; s != end; ++s)
  {
    ctf->AddRGBPoint(min + s->t * (max - min), s->r, s->g, s->b);
  }
  return ctf;
}

}
