// Baseline image: the four modes in four viewports (composite with an opaque
// sphere half inside the smoke, maximum intensity, isosurface, self-shadowed
// smoke), default sampling (jitter on, fixed seed).
#include "plumeVolumeTestUtil.h"

#include "vtkActor.h"
#include "vtkLight.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkSphereSource.h"

int TestVolumeModes(int argc, char* argv[])
{
  using namespace plumevolumetest;
  auto field = SmokeField(64);
  auto window = plume::test::MakeOffscreenWindow(400, 400);
  const double viewports[4][4] = { { 0, 0.5, 0.5, 1 }, { 0.5, 0.5, 1, 1 }, { 0, 0, 0.5, 0.5 },
    { 0.5, 0, 1, 0.5 } };
  for (int v = 0; v < 4; ++v)
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(viewports[v]);
    renderer->SetBackground(0.12, 0.1, 0.18);
    vtkNew<vtkPlumeVolumeMapper> mapper;
    mapper->SetInputData(field);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    SetTransferFunctions(volume->GetProperty(), 0.0, 1.2, 0.8, 0.05);
    volume->RotateZ(15);
    renderer->AddVolume(volume);
    if (v == 0)
    {
      vtkNew<vtkSphereSource> sphere;
      sphere->SetCenter(0.35, 0.4, 0.75);
      sphere->SetRadius(0.15);
      sphere->SetThetaResolution(32);
      sphere->SetPhiResolution(32);
      vtkNew<vtkPolyDataMapper> pm;
      pm->SetInputConnection(sphere->GetOutputPort());
      vtkNew<vtkActor> actor;
      actor->SetMapper(pm);
      actor->GetProperty()->SetColor(0.3, 0.8, 0.4);
      renderer->AddActor(actor);
    }
    else if (v == 1)
    {
      mapper->SetBlendModeToMaximumIntensity();
    }
    else if (v == 2)
    {
      mapper->SetBlendModeToIsoSurface();
      mapper->SetIsoValue(0.5);
      volume->GetProperty()->SetAmbient(0.15);
      volume->GetProperty()->SetDiffuse(0.75);
      volume->GetProperty()->SetSpecular(0.4);
      volume->GetProperty()->SetSpecularPower(30);
    }
    else
    {
      mapper->SmokeOn();
      volume->GetProperty()->SetAmbient(0.2);
      volume->GetProperty()->SetDiffuse(1.0);
      vtkNew<vtkLight> light;
      light->SetLightTypeToSceneLight();
      light->SetPosition(2.0, 1.5, 0.8);
      light->SetFocalPoint(0.5, 0.5, 0.5);
      renderer->AddLight(light);
      renderer->AutomaticLightCreationOff();
    }
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(0.3, -0.4, 1.0);
    camera->SetFocalPoint(0, 0, 0);
    camera->SetViewUp(0, 1, 0);
    renderer->ResetCamera();
    camera->Zoom(1.3);
    window->AddRenderer(renderer);
  }
  window->Render();
  const std::string gl = plume::test::GLErrors(window);
  if (!gl.empty())
  {
    std::printf("GL errors: %s\n", gl.c_str());
    return EXIT_FAILURE;
  }
  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
