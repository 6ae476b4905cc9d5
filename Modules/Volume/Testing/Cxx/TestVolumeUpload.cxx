// Skip what did not change: re-rendering uploads neither the 3D texture nor
// the transfer-function table; touching the data re-uploads the texture only;
// editing a transfer function re-tabulates only; and the image changes;
// switching shading on or off re-uploads once (the gradient channels).
#include "plumeVolumeTestUtil.h"

int TestVolumeUpload(int, char*[])
{
  using namespace plumevolumetest;
  int failures = 0;
  auto field = SmokeField(32);
  Scene s = MakeScene(field, 96, 96);
  auto expect = [&](const char* what, int uploads, int tables) {
    const bool ok = s.Mapper->GetUploadCount() == uploads && s.Mapper->GetTableCount() == tables;
    std::printf("%-36s uploads %d (want %d) tables %d (want %d)%s\n", what, s.Mapper->GetUploadCount(),
      uploads, s.Mapper->GetTableCount(), tables, ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
  };
  const plume::test::FloatImage first = plume::test::ReadBack(s.Window);
  expect("first frame", 1, 1);
  s.Renderer->GetActiveCamera()->Azimuth(20);
  s.Window->Render();
  s.Window->Render();
  expect("camera moved, two frames", 1, 1);
  s.Volume->GetProperty()->GetScalarOpacity()->AddPoint(0.6, 0.0);
  const plume::test::FloatImage edited = plume::test::ReadBack(s.Window);
  expect("opacity edited", 1, 2);
  vtkDataArray* a = field->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    a->SetTuple1(i, 0.5 * a->GetTuple1(i));
  }
  a->Modified();
  s.Window->Render();
  expect("data modified", 2, 3); // the range changed too, so the table follows
  s.Mapper->SetScalarComponent(0);
  s.Window->Render();
  expect("component chosen", 3, 3);
  if (plume::test::Compare(first, edited).RMS < 1e-3)
  {
    std::printf("FAIL: editing the opacity did not change the image\n");
    ++failures;
  }
  // shading stores the gradient with the value (one re-upload each way), then
  // nothing (the table follows the property's MTime, as for any property edit)
  s.Volume->GetProperty()->ShadeOn();
  s.Window->Render();
  s.Window->Render();
  expect("shading on (gradients), two frames", 4, 4);
  s.Volume->GetProperty()->ShadeOff();
  s.Window->Render();
  expect("shading off", 5, 5);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
