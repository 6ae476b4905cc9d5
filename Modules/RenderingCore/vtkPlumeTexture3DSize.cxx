#include "vtkPlumeTexture3DSize.h"

#include "vtkOpenGLRenderWindow.h"

#include "vtk_glew.h"

#include <sstream>

std::string plume::Check3DTextureSize(vtkOpenGLRenderWindow* window, const int dims[3], int& cachedMax)
{
  if (cachedMax == 0)
  {
    window->MakeCurrent();
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSize);
    cachedMax = maxSize;
  }
  if (dims[0] <= cachedMax && dims[1] <= cachedMax && dims[2] <= cachedMax)
  {
    return std::string();
  }
  std::ostringstream msg;
  msg << "grid " << dims[0] << "x" << dims[1] << "x" << dims[2] << " exceeds GL_MAX_3D_TEXTURE_SIZE = " << cachedMax
      << " along at least one axis; resample the data to a coarser image";
  return msg.str();
}
