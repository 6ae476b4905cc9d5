// Numeric test (no baseline): the actor's transform (vtkProp3D matrix:
// rotation, translation, uniform scale, a non-zero origin) is honoured the
// same way by the mapper and by vtkPlumeSheetReference (positions by the
// matrix, sigmas by its length scale, density per world area). The mapper's
// image of the transformed sheet must match the reference within the goal,
// and must not match the reference of the untransformed sheet.
#include "plumeSheetMeshes.h"
#include "plumeSheetTestUtil.h"

int TestSheetActorMatrix(int, char*[])
{
  sheettest::UseThreads();
  int failures = 0;
  auto sheet = sheettest::Plane(3, 2, -0.6, 0.5, -0.4, 0.45, 0.0);
  sheettest::Scene s(sheet, 56, 44);
  s.Mapper->SetDensityArrayName("density");
  s.Mapper->SetDensityScale(0.9);
  s.Mapper->SetBlurRadius(0.05);
  s.Mapper->SetThickness(0.04);
  s.Actor->SetOrigin(0.1, -0.05, 0.0);
  s.Actor->RotateX(35);
  s.Actor->RotateY(-50);
  s.Actor->RotateZ(20);
  s.Actor->SetScale(1.6);
  s.Actor->SetPosition(0.3, -0.2, 0.15);
  s.Camera(0.6, 0.9, 4.0, 0.25, -0.15, 0.1, 40);
  const sheettest::Result r = sheettest::CompareWithReference(s, sheet, "rotated+scaled+moved actor");
  failures += sheettest::CheckGoal(r, "actor matrix");

  // the same comparison against a reference that ignores the matrix must fail
  vtkNew<vtkPlumeSheetReference> plain;
  sheettest::Configure(plain, s.Mapper, sheet);
  const auto img = plume::test::ReadBack(s.Window);
  plain->Compute(s.Renderer, nullptr);
  double worst = 0.0;
  for (int y = 0; y < img.Height; ++y)
  {
    for (int x = 0; x < img.Width; ++x)
    {
      worst = std::max(worst,
        std::fabs(img.Pixel(x, y)[0] - plain->GetTransmittance()[3 * (static_cast<size_t>(y) * img.Width + x)]));
    }
  }
  std::printf("against the identity-matrix reference: max difference %.3f\n", worst);
  PLUME_CHECK(worst > 0.2);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
