#include "vtkPlumeFrameReadBack.h"

#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderWindow.h"
#include "vtk_glew.h"

#include <cmath>
#include <sstream>

namespace plume
{
FloatImage ReadBack(vtkRenderWindow* window, bool render)
{
  if (render)
  {
    window->Render();
  }
  FloatImage image;
  const int* size = window->GetSize();
  image.Width = size[0];
  image.Height = size[1];
  vtkNew<vtkFloatArray> rgba;
  window->GetRGBAPixelData(0, 0, image.Width - 1, image.Height - 1, 0, rgba, 0);
  image.RGBA.assign(rgba->GetPointer(0), rgba->GetPointer(0) + 4 * static_cast<size_t>(image.Width) * image.Height);
  image.Depth.resize(static_cast<size_t>(image.Width) * image.Height);
  window->GetZbufferData(0, 0, image.Width - 1, image.Height - 1, image.Depth.data());
  return image;
}

bool HasNonFinite(const FloatImage& image)
{
  for (float v : image.RGBA)
  {
    if (!std::isfinite(v))
    {
      return true;
    }
  }
  for (float v : image.Depth)
  {
    if (!std::isfinite(v))
    {
      return true;
    }
  }
  return false;
}

std::string GLErrors(vtkRenderWindow* window)
{
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!gl)
  {
    return "not an OpenGL render window";
  }
  gl->MakeCurrent();
  std::ostringstream out;
  for (int i = 0; i < 16; ++i)
  {
    const GLenum e = glGetError();
    if (e == GL_NO_ERROR)
    {
      break;
    }
    out << "GL error 0x" << std::hex << e << std::dec << " ";
  }
  return out.str();
}
}
