// The representation types `plume render` knows. Each renderer's builders
// live in their own file and register here with one line.
#include "plumeScene.h"

namespace plume
{

const std::map<std::string, RepresentationBuilder>& Representations()
{
  static const std::map<std::string, RepresentationBuilder> builders = [] {
    std::map<std::string, RepresentationBuilder> b;
    RegisterCoreRepresentations(b); // glyphs, surface, contour, outline, sphere
    RegisterVolumeRepresentations(b); // volume
    RegisterSheetRepresentations(b); // sheet
    return b;
  }();
  return builders;
}

}
