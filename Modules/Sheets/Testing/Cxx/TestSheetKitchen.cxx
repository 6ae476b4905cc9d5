// Numeric test (no baseline): the real kitchen stream sheet
// (kitchen_stream_sheet.vtp, traced from the VTK Kitchen example's rake),
// cropped to its first 12 s of integration time (5,482 of 31,200 triangles,
// 318 of them longer than 0.5 m: stretched where neighbouring streamlines
// separate), density from its concentration array c1, against
// vtkPlumeSheetReference on every fourth pixel (x and y) of a 96x72 image
// (the full lattice takes the reference ~160 s). The crop keeps the reference
// within the test budget: every stretched triangle near a ray costs it ~20
// subdivided quadrature rules, and the whole sheet has 6,500 of them.
#include "plumeSheetTestUtil.h"

#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkPointData.h"

int TestSheetKitchen(int, char*[])
{
  sheettest::UseThreads();
  int failures = 0;
  const auto data = plume::test::LoadDataset("derived/kitchen_stream_sheet.vtp");
  vtkPolyData* sheet = vtkPolyData::SafeDownCast(data);
  vtkDataArray* time = sheet ? sheet->GetPointData()->GetArray("IntegrationTime") : nullptr;
  if (!sheet || sheet->GetNumberOfPolys() < 1000 || !time || !sheet->GetPointData()->GetArray("c1"))
  {
    std::cerr << "could not read derived/kitchen_stream_sheet.vtp (IntegrationTime, c1)\n";
    return EXIT_FAILURE;
  }
  // the triangles whose corners were all reached within 12 s
  vtkNew<vtkCellArray> early;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < sheet->GetNumberOfCells(); ++c)
  {
    sheet->GetCellPoints(c, ids);
    bool keep = ids->GetNumberOfIds() == 3;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds() && keep; ++k)
    {
      keep = time->GetComponent(ids->GetId(k), 0) <= 12.0;
    }
    if (keep)
    {
      early->InsertNextCell(ids);
    }
  }
  vtkNew<vtkPolyData> cropped;
  cropped->ShallowCopy(sheet);
  cropped->SetPolys(early);
  vtkNew<vtkCleanPolyData> clean; // drop the unused points (bounds, camera reset)
  clean->SetInputData(cropped);
  clean->PointMergingOff();
  clean->Update();
  vtkPolyData* mesh = clean->GetOutput();
  std::printf("kitchen sheet, first 12 s: %lld triangles\n", static_cast<long long>(mesh->GetNumberOfPolys()));
  PLUME_CHECK(mesh->GetNumberOfPolys() == 5482);

  sheettest::Scene s(mesh, 96, 72);
  s.Mapper->SetDensityArrayName("c1"); // concentration 0.03..0.1
  s.Mapper->SetDensityScale(3.0);
  s.Mapper->SetBlurRadius(0.05);
  s.Mapper->SetThickness(0.03);
  s.Camera(2.9, 2.0, 2.0, 0.45, 3.15, 0.35, 44);
  vtkNew<vtkPlumeSheetReference> ref;
  ref->SetPixelStride(4);
  const sheettest::Result r = sheettest::CompareWithReference(s, mesh, "kitchen stream sheet", ref);
  failures += sheettest::CheckGoal(r, "kitchen stream sheet");
  PLUME_CHECK(s.Mapper->GetTriangleCount() == mesh->GetNumberOfPolys());
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
