// Numeric test (no baseline): a real stream sheet (office_stream_sheet.vtp,
// 24,000 triangles traced through the VTK Office flow) against the reference
// on every fourth pixel in x and y (the reference is the slow part).
#include "plumeSheetTestUtil.h"


int TestSheetRealMesh(int, char*[])
{
  sheettest::UseThreads();
  int failures = 0;
  const auto data = plume::test::LoadDataset("derived/office_stream_sheet.vtp");
  vtkPolyData* mesh = vtkPolyData::SafeDownCast(data);
  if (!mesh || mesh->GetNumberOfPolys() < 1000)
  {
    std::cerr << "could not read derived/office_stream_sheet.vtp\n";
    return EXIT_FAILURE;
  }
  sheettest::Scene s(mesh, 64, 52);
  s.Mapper->SetDensity(0.02);
  s.Mapper->SetBlurRadius(0.04);
  s.Mapper->SetThickness(0.03);
  s.Camera(1.0, 9.0, 6.0, 1.9, 1.6, 1.2, 32);
  vtkNew<vtkPlumeSheetReference> ref;
  ref->SetPixelStride(4);
  const sheettest::Result r = sheettest::CompareWithReference(s, mesh, "office stream sheet", ref);
  failures += sheettest::CheckGoal(r, "office stream sheet");
  PLUME_CHECK(s.Mapper->GetTriangleCount() == 24000);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
