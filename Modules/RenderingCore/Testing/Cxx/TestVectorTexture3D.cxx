// vtkPlumeVectorTexture3D: the texture holds the raw vectors (a = 1) with
// non-finite and masked nodes zeroed (read back and compared with the array);
// it uploads only when the data changes or the window does; a producer's
// hand-over of the right layout is bound instead of an upload and dropped
// once the array changes; wrong tuple counts are refused with a message.
#include "vtkPlumeTextureHandOver.h"
#include "vtkPlumeVectorTexture3D.h"

#include "plumeRenderingCoreTestUtil.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

int TestVectorTexture3D(int, char*[])
{
  int failures = 0;
  auto window = plumetest::MakeTestWindow();
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);

  // 5x4x3 grid, far-from-zero doubles (raw values, not a normalised range)
  vtkNew<vtkImageData> image;
  image->SetDimensions(5, 4, 3);
  const vtkIdType n = image->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> v;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    v->SetTuple3(i, 1e5 + 0.25 * i, -3.0 * i, 0.5);
  }
  v->SetTuple3(7, std::numeric_limits<double>::quiet_NaN(), 1, 1);
  v->SetTuple3(8, 1, std::numeric_limits<double>::infinity(), 1);
  image->GetPointData()->AddArray(v);
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetNumberOfTuples(n);
  mask->Fill(1);
  mask->SetValue(11, 0);

  vtkNew<vtkPlumeVectorTexture3D> texture;
  CHECK(texture->Update(gl, image, v, mask));
  CHECK(texture->GetUploadCount() == 1 && !texture->GetHandedOver());
  vtkTextureObject* t = texture->GetTextureObject();
  CHECK(t->GetWidth() == 5 && t->GetHeight() == 4 && t->GetDepth() == 3);
  std::vector<float> texels = plumetest::ReadBack3D(t);
  int wrong = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const bool invalid = i == 7 || i == 8 || i == 11;
    double expect[4] = { 0, 0, 0, 0 };
    if (!invalid)
    {
      v->GetTuple(i, expect);
      expect[3] = 1;
    }
    for (int c = 0; c < 4; ++c)
    {
      wrong += texels[4 * i + c] != static_cast<float>(expect[c]);
    }
  }
  CHECK(wrong == 0);

  // no change: no upload; a modified array, a new mask or a new window: one each
  CHECK(texture->Update(gl, image, v, mask) && texture->GetUploadCount() == 1);
  v->Modified();
  CHECK(texture->Update(gl, image, v, mask) && texture->GetUploadCount() == 2);
  CHECK(texture->Update(gl, image, v, nullptr) && texture->GetUploadCount() == 3);
  CHECK(plumetest::ReadBack3D(texture->GetTextureObject())[4 * 11 + 3] == 1.0f); // unmasked now
  auto second = plumetest::MakeTestWindow();
  CHECK(texture->Update(vtkOpenGLRenderWindow::SafeDownCast(second), image, v, nullptr));
  CHECK(texture->GetUploadCount() == 4);
  texture->ReleaseGraphicsResources(second);
  CHECK(texture->Update(gl, image, v, nullptr) && texture->GetUploadCount() == 5);

  // a producer's RGBA32F copy of the right size is bound instead of uploading
  vtkNew<vtkFloatArray> w;
  w->SetNumberOfComponents(3);
  w->SetNumberOfTuples(n);
  w->Fill(2.0f);
  vtkNew<vtkTextureObject> produced;
  produced->SetContext(gl);
  produced->SetInternalFormat(GL_RGBA32F);
  CHECK(produced->Create3DFromRaw(5, 4, 3, 4, VTK_FLOAT, nullptr));
  vtkPlumeTextureHandOver::Attach(w, produced, gl);
  CHECK(texture->Update(gl, image, w, nullptr));
  CHECK(texture->GetHandedOver() && texture->GetTextureObject() == produced.Get());
  CHECK(texture->GetHandOverCount() == 1 && texture->GetUploadCount() == 5);
  CHECK(texture->Update(gl, image, w, nullptr) && texture->GetHandOverCount() == 1);
  // with a mask the producer's copy cannot be used
  CHECK(texture->Update(gl, image, w, mask) && !texture->GetHandedOver() && texture->GetUploadCount() == 6);
  // a changed array makes the hand-over stale: our own upload of its values
  w->SetTuple3(0, 9, 9, 9);
  w->Modified();
  CHECK(texture->Update(gl, image, w, nullptr) && !texture->GetHandedOver());
  CHECK(texture->GetUploadCount() == 7 && plumetest::ReadBack3D(texture->GetTextureObject())[0] == 9.0f);
  // a wrong-size producer texture is ignored too
  vtkNew<vtkFloatArray> u;
  u->DeepCopy(w);
  vtkNew<vtkTextureObject> small;
  small->SetContext(gl);
  small->SetInternalFormat(GL_RGBA32F);
  CHECK(small->Create3DFromRaw(4, 4, 3, 4, VTK_FLOAT, nullptr));
  vtkPlumeTextureHandOver::Attach(u, small, gl);
  CHECK(texture->Update(gl, image, u, nullptr) && !texture->GetHandedOver());

  // bad input: one message naming the counts
  vtkNew<vtkDoubleArray> shortArray;
  shortArray->SetNumberOfComponents(3);
  shortArray->SetNumberOfTuples(n - 1);
  CHECK(!texture->Update(gl, image, shortArray, nullptr));
  CHECK(texture->GetLastError().find(std::to_string(n - 1) + " tuples for " + std::to_string(n)) !=
    std::string::npos);
  std::printf("last error: %s\n", texture->GetLastError().c_str());
  produced->ReleaseGraphicsResources(gl);
  small->ReleaseGraphicsResources(gl);
  texture->ReleaseGraphicsResources(gl);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
