// Geometry cases against vtkPlumeVolumeReference: a rotated, translated and
// anisotropically spaced volume (with a non-zero extent start and a direction
// matrix), the camera inside the volume, an opaque sphere inside the smoke
// (rays must stop at its depth; also in a multisampled window), a volume crossing the near plane, and data far
// from the origin (1e6).
#include "plumeVolumeTestUtil.h"

#include "vtkActor.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"

int TestVolumeGeometry(int, char*[])
{
  using namespace plumevolumetest;
  int failures = 0;

  {
    // anisotropic spacing, extent not starting at 0, direction matrix, rotated + translated volume
    auto field = SmokeField(48);
    field->SetSpacing(2.5 / 47, 1.0 / 47, 0.4 / 47);
    int e[6];
    field->GetExtent(e);
    field->SetExtent(e[0] + 5, e[1] + 5, e[2] - 3, e[3] - 3, e[4], e[5]);
    field->SetOrigin(-0.3, 0.2, 0.1);
    field->SetDirectionMatrix(0, -1, 0, 1, 0, 0, 0, 0, 1); // 90° about z
    Scene s = MakeScene(field, 200, 160);
    s.Volume->RotateX(30);
    s.Volume->RotateY(-20);
    s.Volume->SetPosition(0.2, -0.1, 0.05);
    s.Volume->SetScale(1.0, 1.3, 1.0);
    s.Renderer->ResetCamera();
    s.Mapper->JitterOff();
    failures += Check("rotated anisotropic, no jitter", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.005, 0.05);
    s.Mapper->JitterOn();
    failures += Check("rotated anisotropic, jitter", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.005, 0.05);
  }
  {
    // camera inside the volume, looking through the smoke
    Scene s = MakeScene(SmokeField(48), 160, 160);
    vtkCamera* camera = s.Renderer->GetActiveCamera();
    camera->SetPosition(0.5, 0.45, 0.55);
    camera->SetFocalPoint(0.2, 0.55, 0.3);
    camera->SetViewAngle(70);
    s.Renderer->ResetCameraClippingRange();
    camera->SetClippingRange(0.01, 5.0);
    failures += Check("camera inside", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.006, 0.06, 1000);
  }
  {
    // an opaque sphere inside the smoke: the volume must stop at its depth
    Scene s = MakeScene(SmokeField(48), 200, 160);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(0.45, 0.45, 0.5);
    sphere->SetRadius(0.17);
    sphere->SetThetaResolution(48);
    sphere->SetPhiResolution(48);
    vtkNew<vtkPolyDataMapper> pm;
    pm->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(pm);
    actor->GetProperty()->SetColor(0.9, 0.3, 0.3);
    s.Renderer->AddActor(actor);
    s.Renderer->ResetCamera();
    failures += Check("opaque sphere inside the smoke", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.005, 0.05);
    // the same in a multisampled window (VTK's default): the depth is resolved by a blit
    {
      Scene m = MakeScene(SmokeField(48), 200, 160);
      m.Window->SetMultiSamples(8);
      vtkNew<vtkActor> msActor;
      msActor->SetMapper(pm);
      msActor->GetProperty()->SetColor(0.9, 0.3, 0.3);
      m.Renderer->AddActor(msActor);
      m.Renderer->ResetCamera();
      // antialiased sphere edges mix sphere and smoke: allow a larger max there
      failures += Check("opaque sphere, 8x MSAA window", CompareWithReference(m, vtkPlumeVolumeReference::COMPOSITE), 0.006, 0.3);
    }
    // the same with the depth ignored must be measurably wrong (the test can fail)
    s.Mapper->UseOpaqueDepthOff();
    const Result wrong = CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE);
    std::printf("  (without opaque depth: RMS %.4f max %.3f)\n", wrong.RMS, wrong.Max);
    if (wrong.RMS < 0.01)
    {
      std::printf("FAIL: ignoring the opaque depth should change the image\n");
      ++failures;
    }
  }
  {
    // the box crosses the near plane
    Scene s = MakeScene(SmokeField(48), 160, 160);
    vtkCamera* camera = s.Renderer->GetActiveCamera();
    camera->SetPosition(0.5, 0.5, 1.6);
    camera->SetFocalPoint(0.5, 0.5, 0.0);
    camera->SetClippingRange(1.3, 4.0); // near plane inside the box
    failures += Check("box crossing the near plane", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.005, 0.05, 1000);
  }
  {
    // far from the origin
    Scene s = MakeScene(SmokeField(48, 1e6), 160, 120);
    s.Renderer->ResetCamera();
    failures += Check("data at 1e6", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.006, 0.06);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
