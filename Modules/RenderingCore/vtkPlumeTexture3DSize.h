// The one check of a 3D texture's size against the context's
// GL_MAX_3D_TEXTURE_SIZE, shared by vtkPlumeScalarTexture3D and
// vtkPlumeVectorTexture3D so both refuse an oversized grid with the same words.
#ifndef vtkPlumeTexture3DSize_h
#define vtkPlumeTexture3DSize_h

#include "PlumeRenderingCoreModule.h" // For export macro

#include <string> // For std::string

class vtkOpenGLRenderWindow;

namespace plume
{
/**
 * "" if a dims[0] x dims[1] x dims[2] texture fits `window`'s
 * GL_MAX_3D_TEXTURE_SIZE along every axis, else one message naming the grid
 * and the limit. `cachedMax` (0 = not yet known) keeps the queried limit, so
 * the driver is asked once per texture object.
 */
PLUMERENDERINGCORE_EXPORT std::string Check3DTextureSize(
  vtkOpenGLRenderWindow* window, const int dims[3], int& cachedMax);
}

#endif
