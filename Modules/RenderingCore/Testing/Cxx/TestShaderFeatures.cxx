// Shader variants: //PLUME::IF blocks nest, "A+B" is AND and spaces are OR;
// a feature set's defines and key follow its content (not the order of the
// calls); the program cache builds a variant once per window, returns to a
// variant without building, and rebuilds for a new window; full-screen quads
// (ReadyQuad) draw the variant asked for, share that bookkeeping, and are
// dropped with their window.
#include "vtkPlumeShaderFeatures.h"
#include "vtkPlumeShaderProgramCache.h"
#include "vtkPlumeShaderVariants.h"

#include "plumeRenderingCoreTestUtil.h"

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtk_glew.h"
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
// The variants' bodies, for a plain program and for a full-screen quad.
#define VARIANTS                                                                                   \
  "//PLUME::IF RED\n"                                                                              \
  "  gl_FragData[0] = vec4(1.0, 0.0, 0.0, 1.0);\n"                                                 \
  "//PLUME::ENDIF\n"                                                                               \
  "//PLUME::IF BLUE\n"                                                                             \
  "  gl_FragData[0] = vec4(0.0, 0.0, float(PLUME_LEVEL) / 4.0, 1.0);\n"                            \
  "//PLUME::ENDIF\n"
const char* FS = "//VTK::System::Dec\n"
                 "//VTK::Output::Dec\n"
                 "//PLUME::Defines\n"
                 "void main() {\n" VARIANTS "}\n";
// VTK's quad vertex shader passes texCoord, which must be used (else the quad cannot bind it)
const char* QuadFS = "//VTK::System::Dec\n"
                     "//VTK::Output::Dec\n"
                     "//PLUME::Defines\n"
                     "in vec2 texCoord;\n"
                     "void main() {\n"
                     "  if (texCoord.x < -1.0) discard;\n" VARIANTS "}\n";

// The centre pixel of an 8x8 float target after drawing the variant's quad over it.
void DrawQuad(vtkOpenGLRenderWindow* gl, vtkPlumeShaderProgramCache* cache, const vtkPlumeShaderFeatures& f,
  float rgba[4])
{
  gl->MakeCurrent();
  vtkOpenGLQuadHelper* quad = cache->ReadyQuad(gl, QuadFS, f);
  vtkNew<vtkOpenGLFramebufferObject> fbo;
  fbo->SetContext(gl);
  gl->GetState()->PushFramebufferBindings();
  fbo->PopulateFramebuffer(8, 8, true, 1, VTK_FLOAT, false, 0, 0, false);
  fbo->Bind();
  fbo->ActivateDrawBuffer(0);
  fbo->ActivateReadBuffer(0);
  gl->GetState()->vtkglViewport(0, 0, 8, 8);
  gl->GetState()->vtkglDisable(GL_DEPTH_TEST);
  gl->GetState()->vtkglDisable(GL_BLEND);
  gl->GetState()->vtkglDisable(GL_SCISSOR_TEST);
  quad->Render();
  glReadPixels(4, 4, 1, 1, GL_RGBA, GL_FLOAT, rgba);
  gl->GetState()->PopFramebufferBindings();
}
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

  // full-screen quads: same variants, same key rules, counted in BuildCount
  // (a quad's vertex array belongs to the context current when it is built)
  gl->MakeCurrent();
  vtkOpenGLQuadHelper* qr = cache->ReadyQuad(gl, QuadFS, red);
  CHECK(qr != nullptr && cache->GetBuildCount() == 5);
  vtkOpenGLQuadHelper* qb = cache->ReadyQuad(gl, QuadFS, blue2);
  CHECK(qb != nullptr && qb != qr && cache->GetBuildCount() == 6);
  CHECK(cache->ReadyQuad(gl, QuadFS, red) == qr && cache->GetBuildCount() == 6);
  float px[4] = { -1, -1, -1, -1 };
  DrawQuad(gl, cache, red, px);
  CHECK(px[0] == 1.0f && px[1] == 0.0f && px[2] == 0.0f && px[3] == 1.0f);
  DrawQuad(gl, cache, blue2, px);
  CHECK(px[0] == 0.0f && px[2] == 0.5f);
  auto* otherGL = vtkOpenGLRenderWindow::SafeDownCast(other);
  CHECK(cache->ReadyQuad(otherGL, QuadFS, red) != nullptr && cache->GetBuildCount() == 7);
  cache->ReleaseGraphicsResources(other);
  CHECK(cache->ReadyQuad(otherGL, QuadFS, red) != nullptr && cache->GetBuildCount() == 8);
  cache->ReleaseGraphicsResources(other);
  std::printf("programs built: %d\n", cache->GetBuildCount());
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
