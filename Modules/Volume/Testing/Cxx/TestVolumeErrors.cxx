// Bad input gives one clear error naming the problem, draws nothing and does
// not crash: no scalars, only cell scalars, an array name that does not exist,
// a component beyond the array's, a grid larger than GL_MAX_3D_TEXTURE_SIZE
// and one larger than the texture-memory budget (no silent crop; the same grid
// within the budget is drawn).
#include "plumeVolumeTestUtil.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtk_glew.h"

#include <unistd.h>

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
  {
    // texture-memory budget: a 40x24x16 grid needs 61 440 B of R32F texture (+ block
    // summary); 0.05 MB refuses it with its size and the budget, 0.07 MB draws it
    auto field = SmokeField(8);
    Scene s = MakeScene(field, 64, 64);
    auto grid = vtkSmartPointer<vtkImageData>::New();
    grid->SetDimensions(40, 24, 16);
    grid->SetSpacing(1.0 / 39, 1.0 / 39, 1.0 / 39);
    vtkNew<vtkFloatArray> v;
    v->SetName("v");
    v->SetNumberOfTuples(grid->GetNumberOfPoints());
    for (vtkIdType i = 0; i < v->GetNumberOfTuples(); ++i)
    {
      v->SetValue(i, static_cast<float>(i % 40) / 39.0f); // a ramp: visible everywhere
    }
    grid->GetPointData()->SetScalars(v);
    s.Mapper->SetInputData(grid);
    SetTransferFunctions(s.Volume->GetProperty(), 0.0, 1.0, 0.8, 0.05);
    s.Renderer->ResetCamera();
    const int dims[3] = { 40, 24, 16 };
    const double mb = vtkPlumeVolumeMapper::GetTextureBytes(dims) / (1024.0 * 1024.0);
    if (!(mb > 0.0586 && mb < 0.06))
    {
      std::printf("texture bytes of 40x24x16: %.4f MB, expected 0.0586..0.06  FAIL\n", mb);
      ++failures;
    }
    s.Mapper->SetTextureMemoryBudgetMB(0.05);
    failures += Expect("over the texture memory budget", s, "volume 40x24x16 needs 0.0589 MB of 3D texture (4 bytes per point), over the texture memory budget of 0.05 MB");
    s.Mapper->SetTextureMemoryBudgetMB(0.07);
    const double background[3] = { 0.12, 0.1, 0.18 };
    const size_t drawn = plume::test::CountForeground(plume::test::ReadBack(s.Window), background, 2.0 / 255);
    const bool drawnOk = drawn > 500 && s.Mapper->GetEffectiveTextureMemoryBudgetMB() == 0.07;
    std::printf("%-34s drew %zu px%s\n", "within the texture memory budget", drawn, drawnOk ? "" : "  FAIL");
    failures += drawnOk ? 0 : 1;
    // the automatic budget: half the physical memory (llvmpipe reports no video memory)
    s.Mapper->SetTextureMemoryBudgetMB(0);
    s.Window->Render();
    const double automatic = s.Mapper->GetEffectiveTextureMemoryBudgetMB();
    const double half = 0.5 * double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE)) / (1024.0 * 1024.0);
    const bool autoOk = automatic > 0 && automatic <= half * 1.0001;
    std::printf("%-34s %.0f MB (half the RAM: %.0f MB)%s\n", "automatic budget", automatic, half, autoOk ? "" : "  FAIL");
    failures += autoOk ? 0 : 1;
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
