// Set-up shared by the Plume::RenderingCore tests: the CHECK macro that
// counts failures, a small off-screen window with a live context, and the
// read-back of a 3D texture (TestScalarTexture3D, TestVectorTexture3D).
// Tests only: no Plume library includes this header.
#ifndef plumeRenderingCoreTestUtil_h
#define plumeRenderingCoreTestUtil_h

#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include "vtk_glew.h"

#include <cstdio>
#include <vector>

// counts into a local `int failures` and goes on (every failed check is printed)
#define CHECK(c)                                                                                   \
  do                                                                                               \
  {                                                                                                \
    if (!(c))                                                                                      \
    {                                                                                              \
      std::printf("%s:%d: check failed: %s\n", __FILE__, __LINE__, #c);                            \
      ++failures;                                                                                  \
    }                                                                                              \
  } while (false)

namespace plumetest
{
/** An 8x8 off-screen window, rendered once so that its OpenGL context exists. */
inline vtkSmartPointer<vtkRenderWindow> MakeTestWindow()
{
  vtkNew<vtkRenderWindow> w;
  w->SetOffScreenRendering(1);
  w->SetSize(8, 8);
  w->Render();
  return vtkSmartPointer<vtkRenderWindow>(w.Get());
}

/** The texels of a 3D texture as RGBA floats (channels it does not store read as GL fills them: 0, 0, 1). */
inline std::vector<float> ReadBack3D(vtkTextureObject* texture)
{
  const size_t n = size_t(texture->GetWidth()) * texture->GetHeight() * texture->GetDepth();
  std::vector<float> texels(4 * n);
  texture->Activate();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_FLOAT, texels.data());
  texture->Deactivate();
  return texels;
}
}

#endif
