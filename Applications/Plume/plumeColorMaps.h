// Named colour maps for the command line (a few perceptual and classic ones).
#ifndef plumeColorMaps_h
#define plumeColorMaps_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkScalarsToColors;

namespace plume
{
/** Names accepted by MakeColorMap. */
const std::vector<std::string>& ColorMapNames();
/** A lookup table for `name` over [min, max]; nullptr for an unknown name. */
vtkSmartPointer<vtkScalarsToColors> MakeColorMap(const std::string& name, double min, double max);
}

#endif
