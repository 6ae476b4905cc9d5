// vtkPlumeScalarTexture3D: the texture holds the raw values (v - the finite
// minimum) with non-finite nodes sanitised (read back and compared with the
// array in double); GetScaleBias maps any range to [0, 1] (checked against
// (v - lo) / (hi - lo) computed here); it uploads once per data change and
// never for a range change or a re-Update, once more after a window change; a
// producer's R32F hand-over of the right size is bound instead of an upload,
// and ignored when stale, of the wrong size, with a mask or with non-finite
// data; bad input is refused with one message naming the counts.
#include "vtkPlumeScalarTexture3D.h"
#include "vtkPlumeTextureHandOver.h"

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

int TestScalarTexture3D(int, char*[])
{
  int failures = 0;
  auto window = plumetest::MakeTestWindow();
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);

  // 6x5x4 grid, far from zero (300 +- 0.06: a normalised-in-float copy would
  // keep only ~1e-5 of the span; v - lo keeps float's precision of the span)
  vtkNew<vtkImageData> image;
  image->SetDimensions(6, 5, 4);
  const vtkIdType n = image->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> v;
  v->SetName("v");
  v->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    v->SetValue(i, 300.0 + 0.001 * ((i * 37) % 120) - 0.06);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  v->SetValue(7, nan);
  v->SetValue(8, inf);
  v->SetValue(9, -inf);
  double lo = 1e300, hi = -1e300;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (std::isfinite(v->GetValue(i)))
    {
      lo = std::min(lo, v->GetValue(i));
      hi = std::max(hi, v->GetValue(i));
    }
  }

  vtkNew<vtkPlumeScalarTexture3D> texture;
  CHECK(texture->Update(gl, image, v));
  CHECK(texture->GetUploadCount() == 1 && !texture->GetHandedOver());
  CHECK(texture->GetScalarRange()[0] == lo && texture->GetScalarRange()[1] == hi);
  CHECK(texture->GetNonFiniteCount() == 3);
  vtkTextureObject* t = texture->GetTextureObject();
  CHECK(t->GetWidth() == 6 && t->GetHeight() == 5 && t->GetDepth() == 4 && t->GetComponents() == 1);
  {
    std::vector<float> texels = plumetest::ReadBack3D(t);
    const double range[2] = { lo, hi };
    double sb[2];
    texture->GetScaleBias(range, sb);
    double worst = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      double value = v->GetValue(i);
      value = std::isnan(value) ? lo : (std::isinf(value) ? (value > 0 ? hi : lo) : value);
      // raw: the texel is v - shift in data units
      worst = std::max(worst, std::abs(double(texels[4 * i]) - (value - texture->GetValueShift())));
      // and maps to (v - lo) / (hi - lo)
      const double u = texels[4 * i] * sb[0] + sb[1];
      worst = std::max(worst, std::abs(u - (value - lo) / (hi - lo)) * (hi - lo));
    }
    std::printf("largest error %.3g data units (span %.3g)\n", worst, hi - lo);
    CHECK(worst <= 1e-7 * (hi - lo)); // float precision of the span, not of 300
    // another range maps the same texels: u = (v - 299) / 2
    const double other[2] = { 299.0, 301.0 };
    texture->GetScaleBias(other, sb);
    CHECK(std::abs(texels[0] * sb[0] + sb[1] - (v->GetValue(0) - 299.0) / 2.0) < 1e-7);
    const double flat[2] = { 5.0, 5.0 };
    texture->GetScaleBias(flat, sb);
    CHECK(sb[0] == 0.0 && sb[1] == 0.0);
  }
  // block summary in texel units: one 8^3 block covers this grid
  CHECK(texture->GetBlockRanges().size() == 2);
  CHECK(texture->GetBlockRanges()[0] == 0.0f &&
    texture->GetBlockRanges()[1] == static_cast<float>(hi - texture->GetValueShift()));

  // no change and range changes (GetScaleBias is all they need): no upload;
  // a modified array, a component choice, gradients, a window change: one each
  CHECK(texture->Update(gl, image, v) && texture->GetUploadCount() == 1);
  v->Modified();
  CHECK(texture->Update(gl, image, v) && texture->GetUploadCount() == 2);
  CHECK(texture->Update(gl, image, v, 0) && texture->GetUploadCount() == 3);
  texture->SetGradients(true);
  CHECK(texture->Update(gl, image, v, 0) && texture->GetUploadCount() == 4 && texture->GetHasGradients());
  texture->SetGradients(false);
  CHECK(texture->Update(gl, image, v, 0) && texture->GetUploadCount() == 5);
  auto second = plumetest::MakeTestWindow();
  CHECK(texture->Update(vtkOpenGLRenderWindow::SafeDownCast(second), image, v, 0));
  CHECK(texture->GetUploadCount() == 6);
  texture->ReleaseGraphicsResources(second);
  CHECK(texture->Update(gl, image, v, 0) && texture->GetUploadCount() == 7);

  // a mask: (t w, w), the range of the valid nodes only
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetNumberOfTuples(n);
  mask->Fill(1);
  mask->SetValue(11, 0);
  v->SetValue(11, 1e6); // outside the data: not in the range
  v->Modified();
  CHECK(texture->Update(gl, image, v, -1, mask) && texture->GetMasked() && texture->GetUploadCount() == 8);
  CHECK(texture->GetScalarRange()[1] == hi);
  {
    std::vector<float> texels = plumetest::ReadBack3D(texture->GetTextureObject());
    CHECK(texels[4 * 11] == 0.0f && texels[4 * 11 + 1] == 0.0f);
    CHECK(texels[4 * 12 + 1] == 1.0f &&
      texels[4 * 12] == static_cast<float>(v->GetValue(12) - texture->GetValueShift()));
  }

  // a producer's R32F copy of the right size is bound instead of uploading
  vtkNew<vtkFloatArray> w;
  w->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    w->SetValue(i, static_cast<float>(i % 7));
  }
  vtkNew<vtkTextureObject> produced;
  produced->SetContext(gl);
  CHECK(produced->Create3DFromRaw(6, 5, 4, 1, VTK_FLOAT, w->GetPointer(0)));
  vtkPlumeTextureHandOver::Attach(w, produced, gl);
  CHECK(texture->Update(gl, image, w));
  CHECK(texture->GetHandedOver() && texture->GetTextureObject() == produced.Get());
  CHECK(texture->GetHandOverCount() == 1 && texture->GetUploadCount() == 8);
  // the range and blocks still come from the array; the shift is 0 (raw texels)
  CHECK(texture->GetScalarRange()[0] == 0 && texture->GetScalarRange()[1] == 6 &&
    texture->GetValueShift() == 0.0);
  CHECK(texture->GetBlockRanges()[0] == 0.0f && texture->GetBlockRanges()[1] == 6.0f);
  CHECK(texture->Update(gl, image, w) && texture->GetHandOverCount() == 1 && texture->GetUploadCount() == 8);
  // with a mask or gradients the producer's copy cannot be used as it is
  CHECK(texture->Update(gl, image, w, -1, mask) && !texture->GetHandedOver() && texture->GetUploadCount() == 9);
  texture->SetGradients(true);
  CHECK(texture->Update(gl, image, w) && !texture->GetHandedOver() && texture->GetUploadCount() == 10);
  texture->SetGradients(false);
  CHECK(texture->Update(gl, image, w) && texture->GetHandedOver() && texture->GetHandOverCount() == 2);
  // a changed array makes the hand-over stale: our own upload of its values
  w->SetValue(0, 9.0f);
  w->Modified();
  CHECK(texture->Update(gl, image, w) && !texture->GetHandedOver());
  CHECK(texture->GetUploadCount() == 11 && texture->GetScalarRange()[1] == 9.0);
  CHECK(plumetest::ReadBack3D(texture->GetTextureObject())[0] == 9.0f - float(texture->GetValueShift()));
  // a wrong-size producer texture is ignored too
  vtkNew<vtkFloatArray> u;
  u->DeepCopy(w);
  vtkNew<vtkTextureObject> small;
  small->SetContext(gl);
  CHECK(small->Create3DFromRaw(5, 5, 4, 1, VTK_FLOAT, nullptr));
  vtkPlumeTextureHandOver::Attach(u, small, gl);
  CHECK(texture->Update(gl, image, u) && !texture->GetHandedOver() && texture->GetUploadCount() == 12);
  // ... and so is one of an array with NaN (it would reach the shader unsanitised)
  vtkNew<vtkFloatArray> withNaN;
  withNaN->DeepCopy(w);
  withNaN->SetValue(3, std::numeric_limits<float>::quiet_NaN());
  vtkPlumeTextureHandOver::Attach(withNaN, produced, gl);
  CHECK(texture->Update(gl, image, withNaN) && !texture->GetHandedOver() && texture->GetUploadCount() == 13);
  CHECK(plumetest::ReadBack3D(texture->GetTextureObject())[4 * 3] == 0.0f); // NaN -> the minimum

  // bad input: one message naming the counts
  vtkNew<vtkDoubleArray> shortArray;
  shortArray->SetNumberOfTuples(n - 1);
  CHECK(!texture->Update(gl, image, shortArray));
  CHECK(texture->GetLastError().find(std::to_string(n - 1) + " tuples but the image has " + std::to_string(n)) !=
    std::string::npos);
  std::printf("last error: %s\n", texture->GetLastError().c_str());
  CHECK(!texture->Update(gl, image, v, 2));
  CHECK(texture->GetLastError().find("component 2") != std::string::npos);
  produced->ReleaseGraphicsResources(gl);
  small->ReleaseGraphicsResources(gl);
  texture->ReleaseGraphicsResources(gl);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
