// vtkPlumeLookupTexture: the table holds the entries at evenly spaced values
// of the range; it is rebuilt only when the source, its time, the range, the
// size or the window changes.
#include "vtkPlumeLookupTexture.h"

#include "plumeRenderingCoreTestUtil.h"

#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

#include <cmath>
#include <cstdlib>

int TestLookupTexture(int, char*[])
{
  int failures = 0;
  auto window = plumetest::MakeTestWindow();
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  int calls = 0;
  auto ramp = [&calls](double v, float rgba[4]) {
    ++calls;
    rgba[0] = static_cast<float>(v);
    rgba[1] = static_cast<float>(2 * v);
    rgba[2] = 0.0f;
    rgba[3] = 1.0f;
  };
  vtkNew<vtkPlumeLookupTexture> table;
  const int source = 0; // any object's address identifies the source
  const double range[2] = { -1.0, 3.0 };
  CHECK(table->Update(gl, &source, 5, range, 5, ramp));
  CHECK(table->GetUploadCount() == 1 && calls == 5);
  CHECK(table->GetTable().size() == 20 && table->GetTable()[4] == 0.0f && table->GetTable()[16] == 3.0f &&
    table->GetTable()[17] == 6.0f);
  CHECK(table->GetTextureObject()->GetHandle() != 0 && table->GetTextureObject()->GetWidth() == 5);
  CHECK(table->Update(gl, &source, 5, range, 5, ramp) && table->GetUploadCount() == 1 && calls == 5);
  const double other[2] = { -1.0, 4.0 };
  CHECK(table->Update(gl, &source, 5, other, 5, ramp) && table->GetUploadCount() == 2);
  CHECK(table->Update(gl, &source, 6, other, 5, ramp) && table->GetUploadCount() == 3);
  const int another = 0;
  CHECK(table->Update(gl, &another, 6, other, 5, ramp) && table->GetUploadCount() == 4);
  CHECK(table->Update(gl, &another, 6, other, 7, ramp) && table->GetUploadCount() == 5);
  auto second = plumetest::MakeTestWindow();
  CHECK(table->Update(vtkOpenGLRenderWindow::SafeDownCast(second), &another, 6, other, 7, ramp));
  CHECK(table->GetUploadCount() == 6);
  table->ReleaseGraphicsResources(second);
  std::printf("uploads %d, entries computed %d\n", table->GetUploadCount(), calls);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
