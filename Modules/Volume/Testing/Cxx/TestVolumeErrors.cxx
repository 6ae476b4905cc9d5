// Bad input gives one clear error naming the problem, draws nothing and does
// not crash: no scalars, only cell scalars, an array name that does not exist,
// a component beyond the array's, and a grid larger than GL_MAX_3D_TEXTURE_SIZE
// (no silent crop).
#include "plumeVolumeTestUtil.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtk_glew.h"

namespace
{
struct Errors
{
  std::string Last;
  int Count = 0;
};

void OnError(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* errors = static_cast<Errors*>(clientData);
  errors->Last = callData ? static_cast<const char*>(callData) : "";
  ++errors->Count;
}

int Expect(const char* name, plumevolumetest::Scene& s, const std::string& needle)
{
  Errors errors;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(OnError);
  callback->SetClientData(&errors);
  s.Mapper->AddObserver(vtkCommand::ErrorEvent, callback);
  const double background[3] = { 0.12, 0.1, 0.18 };
  const plume::test::FloatImage image = plume::test::ReadBack(s.Window);
  const size_t drawn = plume::test::CountForeground(image, background, 2.0 / 255);
  const std::string gl = plume::test::GLErrors(s.Window);
  const bool ok = errors.Count >= 1 && errors.Last.find(needle) != std::string::npos && drawn == 0 && gl.empty();
  std::printf("%-34s %d error(s), drew %zu px: %s%s\n", name, errors.Count, drawn,
    errors.Last.substr(errors.Last.find(':') == std::string::npos ? 0 : errors.Last.rfind("): ") + 3).c_str(),
    ok ? "" : "  FAIL");
  s.Mapper->RemoveObserver(callback);
  return ok ? 0 : 1;
}
}

int TestVolumeErrors(int, char*[])
{
  using namespace plumevolumetest;
  int failures = 0;
  {
    auto field = SmokeField(8);
    Scene s = MakeScene(field, 64, 64);
    auto bare = vtkSmartPointer<vtkImageData>::New();
    bare->SetDimensions(8, 8, 8);
    s.Mapper->SetInputData(bare);
    failures += Expect("no scalars", s, "no scalars");
  }
  {
    auto field = SmokeField(8);
    Scene s = MakeScene(field, 64, 64);
    auto cells = vtkSmartPointer<vtkImageData>::New();
    cells->SetDimensions(8, 8, 8);
    vtkNew<vtkFloatArray> c;
    c->SetName("c");
    c->SetNumberOfTuples(cells->GetNumberOfCells());
    c->FillValue(1.0f);
    cells->GetCellData()->SetScalars(c);
    s.Mapper->SetInputData(cells);
    failures += Expect("cell scalars only", s, "cell scalars are not supported");
  }
  {
    Scene s = MakeScene(SmokeField(8), 64, 64);
    s.Mapper->SetScalarModeToUsePointFieldData();
    s.Mapper->SelectScalarArray("nope");
    failures += Expect("missing array name", s, "'nope'");
  }
  {
    Scene s = MakeScene(SmokeField(8), 64, 64);
    s.Mapper->SetScalarComponent(2);
    failures += Expect("component out of range", s, "component 2");
  }
  {
    Scene s = MakeScene(SmokeField(8), 64, 64);
    s.Window->Render();
    static_cast<vtkOpenGLRenderWindow*>(s.Window.GetPointer())->MakeCurrent();
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSize);
    auto big = vtkSmartPointer<vtkImageData>::New();
    big->SetDimensions(maxSize + 1, 2, 2);
    vtkNew<vtkFloatArray> v;
    v->SetName("v");
    v->SetNumberOfTuples(big->GetNumberOfPoints());
    v->FillValue(0.5f);
    big->GetPointData()->SetScalars(v);
    s.Mapper->SetInputData(big);
    s.Renderer->ResetCamera();
    failures += Expect("larger than GL_MAX_3D_TEXTURE_SIZE", s, "GL_MAX_3D_TEXTURE_SIZE");
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
