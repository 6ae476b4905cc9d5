// Shader variants: //PLUME::IF blocks nest, "A+B" is AND and spaces are OR;
// a feature set's defines and key follow its content (not the order of the
// calls); the program cache builds a variant once per window, returns to a
// variant without building, and rebuilds for a new window.
#include "vtkPlumeShaderFeatures.h"
#include "vtkPlumeShaderProgramCache.h"
#include "vtkPlumeShaderVariants.h"

#include "plumeRenderingCoreTestUtil.h"

#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"

#include <cstdlib>
#include <stdexcept>

namespace
{
const char* Template = "a\n"
                       "//PLUME::IF X\n"
                       "x\n"
                       "//PLUME::IF Y+Z W\n"
                       "xyz_or_w\n"
                       "//PLUME::ENDIF\n"
                       "x2\n"
                       "//PLUME::ENDIF\n"
                       "//PLUME::Defines\n"
                       "b\n";

const char* VS = "//VTK::System::Dec\n"
                 "in vec4 vertexMC;\n"
                 "void main() { gl_Position = vertexMC; }\n";
const char* FS = "//VTK::System::Dec\n"
                 "//VTK::Output::Dec\n"
                 "//PLUME::Defines\n"
                 "void main() {\n"
                 "//PLUME::IF RED\n"
                 "  gl_FragData[0] = vec4(1.0, 0.0, 0.0, 1.0);\n"
                 "//PLUME::ENDIF\n"
                 "//PLUME::IF BLUE\n"
                 "  gl_FragData[0] = vec4(0.0, 0.0, float(PLUME_LEVEL) / 4.0, 1.0);\n"
                 "//PLUME::ENDIF\n"
                 "}\n";
}

int TestShaderFeatures(int, char*[])
{
  int failures = 0;
  using V = vtkPlumeShaderVariants;
  CHECK(V::Select(Template, {}, "") == "a\nb\n");
  CHECK(V::Select(Template, { "X" }, "") == "a\nx\nx2\nb\n");
  CHECK(V::Select(Template, { "X", "Y" }, "") == "a\nx\nx2\nb\n");            // Y alone: AND fails
  CHECK(V::Select(Template, { "X", "Y", "Z" }, "") == "a\nx\nxyz_or_w\nx2\nb\n"); // Y+Z
  CHECK(V::Select(Template, { "X", "W" }, "") == "a\nx\nxyz_or_w\nx2\nb\n");   // OR
  CHECK(V::Select(Template, { "W" }, "") == "a\nb\n");                         // inner needs the outer
  CHECK(V::Select(Template, {}, "#define K 1\n") == "a\n#define K 1\nb\n");

  vtkPlumeShaderFeatures f1, f2;
  f1.Enable("B").Enable("A").Define("N", 3).Define("M", "0.5");
  f2.Define("M", "0.5").Enable("A").Define("N", 3).Enable("B").Enable("C").Enable("C", false);
  CHECK(f1.GetKey() == f2.GetKey());
  CHECK(f1.GetDefines() == "#define M 0.5\n#define N 3\n#define PLUME_FEATURE_A 1\n#define PLUME_FEATURE_B 1\n");
  f2.Define("N", 4);
  CHECK(f1.GetKey() != f2.GetKey());
  bool threw = false;
  try
  {
    f1.Enable("not a name");
  }
  catch (const std::invalid_argument&)
  {
    threw = true;
  }
  CHECK(threw);

  // the cache: one build per variant and window
  vtkNew<vtkPlumeShaderProgramCache> cache;
  auto window = plumetest::MakeTestWindow();
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  vtkPlumeShaderFeatures red, blue1, blue2;
  red.Enable("RED");
  blue1.Enable("BLUE").Define("PLUME_LEVEL", 1);
  blue2.Enable("BLUE").Define("PLUME_LEVEL", 2);
  vtkShaderProgram* r = cache->Ready(gl, VS, nullptr, FS, red);
  CHECK(r != nullptr && cache->GetBuildCount() == 1);
  vtkShaderProgram* b1 = cache->Ready(gl, VS, nullptr, FS, blue1);
  vtkShaderProgram* b2 = cache->Ready(gl, VS, nullptr, FS, blue2);
  CHECK(b1 && b2 && b1 != b2 && b1 != r && cache->GetBuildCount() == 3);
  CHECK(cache->Ready(gl, VS, nullptr, FS, red) == r && cache->GetBuildCount() == 3);
  CHECK(cache->Ready(gl, VS, nullptr, FS, blue1) == b1 && cache->GetBuildCount() == 3);
  auto other = plumetest::MakeTestWindow();
  CHECK(cache->Ready(vtkOpenGLRenderWindow::SafeDownCast(other), VS, nullptr, FS, red) != nullptr);
  CHECK(cache->GetBuildCount() == 4);
  cache->ReleaseGraphicsResources(other);
  std::printf("programs built: %d\n", cache->GetBuildCount());
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
