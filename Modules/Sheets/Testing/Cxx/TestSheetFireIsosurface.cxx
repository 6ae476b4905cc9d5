// Numeric test (no baseline): an isosurface of a real smoke concentration,
// mfrac = 0.005 of fire_ug.vtu (the mixture fraction of the fire-in-a-room
// CFD snapshot; about 1,300 triangles bounding the smoke plume), drawn as a
// smoke sheet with its density taken from the interpolated temperature, and
// compared with vtkPlumeSheetReference on every second pixel (in x and y)
// of a 96x72 image.
#include "plumeSheetTestUtil.h"

#include "vtkContourFilter.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

int TestSheetFireIsosurface(int, char*[])
{
  sheettest::UseThreads();
  int failures = 0;
  const auto data = plume::test::LoadDataset("classic/fire_ug.vtu");
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (!grid || !grid->GetPointData()->GetArray("mfrac") || !grid->GetPointData()->GetArray("t"))
  {
    std::cerr << "could not read classic/fire_ug.vtu (mfrac, t)\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(grid);
  contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "mfrac");
  contour->SetValue(0, 0.005);
  contour->Update();
  vtkPolyData* mesh = contour->GetOutput();
  std::printf("mfrac = 0.005 isosurface: %lld triangles\n", static_cast<long long>(mesh->GetNumberOfPolys()));
  PLUME_CHECK(mesh->GetNumberOfPolys() > 1000);
  PLUME_CHECK(mesh->GetPointData()->GetArray("t") != nullptr);

  sheettest::Scene s(mesh, 96, 72);
  // hotter parts of the plume boundary carry more smoke: d = t / 2000 (t 300..700 K)
  s.Mapper->SetDensityArrayName("t");
  s.Mapper->SetDensityScale(0.0005);
  s.Mapper->SetBlurRadius(0.06);
  s.Mapper->SetThickness(0.04);
  s.Camera(4.2, 2.4, 5.2, 1.5, 1.5, 1.2, 40);
  vtkNew<vtkPlumeSheetReference> ref;
  ref->SetPixelStride(2); // 48x36 pixels: the reference takes ~18 s for all of them
  const sheettest::Result r = sheettest::CompareWithReference(s, mesh, "fire mfrac isosurface", ref);
  failures += sheettest::CheckGoal(r, "fire mfrac isosurface");
  PLUME_CHECK(s.Mapper->GetTriangleCount() == mesh->GetNumberOfPolys());
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
