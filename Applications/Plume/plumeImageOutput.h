// Writing a rendered frame: 8-bit PNG, or OpenEXR with linear float RGB (from a
// float framebuffer, unclamped), A = 1 (opaque, as the PNG) and a depth
// channel Z (distance along the view direction, +inf on the background).
#ifndef plumeImageOutput_h
#define plumeImageOutput_h

#include "vtkPlumeFrameReadBack.h"

#include <string>

class vtkCamera;
class vtkRenderWindow;
class vtkRenderer;

namespace plume
{
/** Writes `image` to `path`; the format comes from the extension (.png or .exr). Throws SceneError. */
void WriteImage(const std::string& path, const FloatImage& image, vtkCamera* camera);
/**
 * Renders `window` with `renderer`'s passes inside a float framebuffer
 * (RGBA32F colour; depth in the window's format) and returns that frame unquantised:
 * what EXR output needs (the window's own framebuffer is 8 bits per channel).
 * The float framebuffer is not multisampled: edges are not antialiased as
 * in the window's (multisampled) PNG output.
 * The renderer's pass is restored afterwards. Throws SceneError on failure.
 */
FloatImage RenderFloat(vtkRenderWindow* window, vtkRenderer* renderer);
/** Window depth (0..1) to distance along the view direction, for the camera's clipping range. */
double LinearDepth(double windowDepth, vtkCamera* camera);
}

#endif
