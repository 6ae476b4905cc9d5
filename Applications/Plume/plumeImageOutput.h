// Writing a rendered frame: 8-bit PNG, or OpenEXR with linear float RGBA and a
// depth channel Z (distance along the view direction, +inf on the background).
#ifndef plumeImageOutput_h
#define plumeImageOutput_h

#include "plumeTestSupport.h"

#include <string>

class vtkCamera;

namespace plume
{
/** Writes `image` to `path`; the format comes from the extension (.png or .exr). Throws SceneError. */
void WriteImage(const std::string& path, const test::FloatImage& image, vtkCamera* camera);
/** Window depth (0..1) to distance along the view direction, for the camera's clipping range. */
double LinearDepth(double windowDepth, vtkCamera* camera);
}

#endif
