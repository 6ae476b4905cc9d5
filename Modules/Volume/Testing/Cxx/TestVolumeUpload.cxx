// Skip what did not change: re-rendering uploads neither the 3D texture nor
// the transfer-function table; touching the data re-uploads the texture only;
// editing a transfer function re-tabulates only; and the image changes;
// switching shading on or off re-uploads once (the gradient channels);
// changing the transfer functions' range re-tabulates and uploads no volume
// (and setting it back to the data range gives the same image); a
// producer's hand-over of the same values is bound instead of an upload and
// gives the same image.
#include "plumeVolumeTestUtil.h"

#include "vtkFloatArray.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPlumeTextureHandOver.h"
#include "vtkTextureObject.h"

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

  // a fresh scene (the one above ends fully transparent, drawing nothing)
  auto fresh = SmokeField(32);
  vtkDataArray* fa = fresh->GetPointData()->GetScalars();
  Scene f = MakeScene(fresh, 96, 96);
  auto check = [&](const char* what, int uploads, int tables) {
    const bool ok = f.Mapper->GetUploadCount() == uploads && f.Mapper->GetTableCount() == tables;
    std::printf("%-36s uploads %d (want %d) tables %d (want %d)%s\n", what, f.Mapper->GetUploadCount(),
      uploads, f.Mapper->GetTableCount(), tables, ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
  };
  // the transfer functions' range: the raw texture is mapped by a scale and
  // bias. A range narrower than the data clamps the values outside it to the
  // table's end entries (the tabulation over a wider range matches the
  // functions themselves: same image), so the image changes
  const plume::test::FloatImage dataRange = plume::test::ReadBack(f.Window);
  double r[2];
  fa->GetRange(r, 0);
  f.Mapper->SetTransferFunctionRange(r[0] + 0.3 * (r[1] - r[0]), r[1] - 0.3 * (r[1] - r[0]));
  const plume::test::FloatImage narrower = plume::test::ReadBack(f.Window);
  check("transfer-function range narrowed", 1, 2);
  f.Renderer->GetActiveCamera()->Azimuth(-20);
  f.Renderer->GetActiveCamera()->Azimuth(20);
  f.Mapper->SetTransferFunctionRange(r[0], r[1]);
  const plume::test::FloatImage back = plume::test::ReadBack(f.Window);
  check("transfer-function range = data range", 1, 3);
  const double narrowerRMS = plume::test::Compare(dataRange, narrower).RMS;
  const double backRMS = plume::test::Compare(dataRange, back).RMS;
  std::printf("narrowed range: RMS %.3g from the data range's image; set back: %.3g\n", narrowerRMS, backRMS);
  if (narrowerRMS < 1e-3 || backRMS > 1e-6)
  {
    std::printf("FAIL: the transfer-function range is not applied (or not undone)\n");
    ++failures;
  }
  {
    // the narrowed range must read the table as data clamped to it would
    // (tabulated over its own range, which is then the narrowed one); equal up
    // to trilinear interpolation across the clamp
    vtkNew<vtkImageData> clamped;
    clamped->DeepCopy(fresh);
    vtkDataArray* c = clamped->GetPointData()->GetScalars();
    const double lo = r[0] + 0.3 * (r[1] - r[0]), hi = r[1] - 0.3 * (r[1] - r[0]);
    for (vtkIdType i = 0; i < c->GetNumberOfTuples(); ++i)
    {
      c->SetTuple1(i, std::min(hi, std::max(lo, c->GetTuple1(i))));
    }
    Scene g = MakeScene(clamped, 96, 96);
    g.Volume->SetProperty(f.Volume->GetProperty()); // the same transfer functions
    f.Mapper->SetTransferFunctionRange(lo, hi);
    const double clampRMS = plume::test::Compare(plume::test::ReadBack(g.Window), plume::test::ReadBack(f.Window)).RMS;
    f.Mapper->SetTransferFunctionRange(0, 0);
    std::printf("narrowed range vs data clamped to it: RMS %.3g\n", clampRMS);
    if (clampRMS > 0.01)
    {
      std::printf("FAIL: the narrowed range does not map values as clamped data would\n");
      ++failures;
    }
  }

  // a producer's GPU copy of the scalars (raw R32F, vtkPlumeTextureHandOver) is
  // bound instead of an upload and draws the same image
  vtkNew<vtkFloatArray> produced;
  produced->DeepCopy(fa);
  produced->SetName(fa->GetName());
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(f.Window);
  int dims[3];
  fresh->GetDimensions(dims);
  vtkNew<vtkTextureObject> copy;
  copy->SetContext(gl);
  if (!copy->Create3DFromRaw(dims[0], dims[1], dims[2], 1, VTK_FLOAT, produced->GetPointer(0)))
  {
    std::printf("FAIL: could not make the producer's texture\n");
    return EXIT_FAILURE;
  }
  vtkPlumeTextureHandOver::Attach(produced, copy, gl);
  fresh->GetPointData()->SetScalars(produced);
  const plume::test::FloatImage handed = plume::test::ReadBack(f.Window);
  const bool bound = f.Mapper->GetHandOverCount() == 1 && f.Mapper->GetUploadCount() == 1;
  const double handedRMS = plume::test::Compare(dataRange, handed).RMS;
  std::printf("hand-over: %d bound, %d uploads (want 1, 1); RMS %.3g from the uploaded image\n",
    f.Mapper->GetHandOverCount(), f.Mapper->GetUploadCount(), handedRMS);
  if (!bound || handedRMS > 1e-4)
  {
    std::printf("FAIL: the hand-over was not used, or draws another image\n");
    ++failures;
  }
  copy->ReleaseGraphicsResources(gl);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
