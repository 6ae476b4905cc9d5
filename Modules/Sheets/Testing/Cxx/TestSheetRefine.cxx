// Numeric test (no baseline): the grid mode coarse while the camera moves and
// refined when it stops (vtkPlumeSheetMapper::AutoAdjustQuality, VTK's
// DesiredUpdateRate convention), against vtkPlumeSheetReference:
// - an interactive frame (window DesiredUpdateRate 15, as the interactor sets
//   while the user drags) takes the fast path (step InteractiveGridSampleDistance,
//   ray lattice InteractiveImageSampleDistance) and stays within the
//   interactive goal (RMS <= 1 %, max <= 5 % of the transmittance range);
// - the still frame (DesiredUpdateRate 0.0001, the interactor's
//   StillUpdateRate) takes the full path and reaches the default quality
//   (RMS <= 0.2 %, max <= 1 %), closer to the reference than the
//   interactive frame;
// - no stale frame: after a camera move, an interactive frame is
//   identical to a fresh mapper's at that camera; after a data change, the
//   interactive frame recomputes the grid and follows the data (reference),
//   and the still frame after it is accurate again; the switch computes no
//   grid;
// - a still frame yields when the window's abort check reports waiting input
//   (VTK's AbortCheckEvent), and is drawn once nothing waits;
// - the opaque depth is read only when another prop may write it (alone, the
//   sheet reads none; with an opaque sphere crossing it, rays stop there);
// - the cheap interactive setting of the speed comparison (lattice 8,
//   tolerance 0.064: Documentation/Renderers.md) stays within its stated
//   bound on this small image (RMS <= 5 %, max <= 25 % of the range; the
//   triangle's blur is ~3 pixels, its edges fall between lattice rays).
#include "plumeSheetMeshes.h"
#include "plumeSheetTestUtil.h"

#include "vtkCallbackCommand.h"
#include "vtkPointData.h"

namespace
{
const double Interactive = 15.0; // frames/s while the camera moves
const double Still = 0.0001;     // vtkRenderWindowInteractor's StillUpdateRate

void Configure(vtkPlumeSheetMapper* m)
{
  m->SetRenderMode(vtkPlumeSheetMapper::RENDER_GRID);
  m->SetDensityArrayName("density");
  m->SetDensityScale(1.5);
  m->SetBlurRadius(0.15);
  m->SetThickness(0.1);
}
}

int TestSheetRefine(int, char*[])
{
  sheettest::UseThreads();
  int failures = 0;
  const int W = 64, H = 52;
  const double a[3] = { -0.8, -0.6, 0.0 }, b[3] = { 0.9, -0.4, 0.1 }, c[3] = { -0.2, 0.8, -0.1 };
  auto tri = sheettest::Triangle(a, b, c, { 0.4, 1.0, 0.7 });
  sheettest::Scene s(tri, W, H);
  Configure(s.Mapper);
  s.Camera(0.3, 0.2, 5.0, 0, 0, 0);

  // ---- interactive frame: fast path, interactive goal
  s.Window->SetDesiredUpdateRate(Interactive);
  const sheettest::Result fast = sheettest::CompareWithReference(s, tri, "interactive frame");
  std::printf("interactive: step %g, lattice %d\n", s.Mapper->GetLastGridSampleDistance(),
    s.Mapper->GetLastImageSampleDistance());
  PLUME_CHECK(s.Mapper->GetLastInteractive());
  PLUME_CHECK(s.Mapper->GetLastGridSampleDistance() == s.Mapper->GetInteractiveGridSampleDistance());
  PLUME_CHECK(s.Mapper->GetLastImageSampleDistance() == s.Mapper->GetInteractiveImageSampleDistance());
  failures += sheettest::CheckGoal(fast, "interactive frame");
  const auto fastImage = plume::test::ReadBack(s.Window);

  // ---- still frame: full path, default quality, same grid
  s.Window->SetDesiredUpdateRate(Still);
  const sheettest::Result still = sheettest::CompareWithReference(s, tri, "still frame");
  std::printf("still: step %g, lattice %d, grids %d\n", s.Mapper->GetLastGridSampleDistance(),
    s.Mapper->GetLastImageSampleDistance(), s.Mapper->GetGridComputeCount());
  PLUME_CHECK(!s.Mapper->GetLastInteractive());
  PLUME_CHECK(s.Mapper->GetLastGridSampleDistance() == s.Mapper->GetGridSampleDistance());
  PLUME_CHECK(s.Mapper->GetLastImageSampleDistance() == 1);
  PLUME_CHECK(s.Mapper->GetGridComputeCount() == 1); // the switch computes no grid
  failures += sheettest::CheckGoal(still, "still frame", 0.002, 0.01);
  PLUME_CHECK(still.RMS < fast.RMS);
  const auto stillImage = plume::test::ReadBack(s.Window);
  const double pathDiff = plume::test::Compare(fastImage, stillImage).Max;
  std::printf("interactive vs still frame: max difference %.4f\n", pathDiff);
  PLUME_CHECK(pathDiff > 0.0); // two different paths drew them

  // ---- camera moved while interacting: the frame is cast anew (a fresh mapper draws the same)
  s.Window->SetDesiredUpdateRate(Interactive);
  s.Camera(1.2, 0.8, 4.6, 0.1, 0, 0);
  s.Renderer->ResetCameraClippingRange();
  const auto moved = plume::test::ReadBack(s.Window);
  {
    sheettest::Scene fresh(tri, W, H);
    Configure(fresh.Mapper);
    fresh.Window->SetDesiredUpdateRate(Interactive);
    fresh.Camera(1.2, 0.8, 4.6, 0.1, 0, 0);
    fresh.Renderer->GetActiveCamera()->SetClippingRange(s.Renderer->GetActiveCamera()->GetClippingRange());
    const auto expected = plume::test::ReadBack(fresh.Window);
    const double d = plume::test::Compare(moved, expected).Max;
    std::printf("moved camera, interactive: max difference to a fresh mapper %.6f\n", d);
    PLUME_CHECK(d == 0.0);
  }

  // ---- data changed while interacting: new grid, the interactive frame follows the data
  auto* density = tri->GetPointData()->GetArray("density");
  density->SetTuple1(1, 0.2);
  density->Modified();
  failures += sheettest::CheckGoal(
    sheettest::CompareWithReference(s, tri, "interactive after data change"), "interactive after data change");
  PLUME_CHECK(s.Mapper->GetGridComputeCount() == 2);
  PLUME_CHECK(s.Mapper->GetLastInteractive());
  // ... and the still frame after it reaches the default quality
  s.Window->SetDesiredUpdateRate(Still);
  failures += sheettest::CheckGoal(
    sheettest::CompareWithReference(s, tri, "still after data change"), "still after data change", 0.002, 0.01);
  PLUME_CHECK(!s.Mapper->GetLastInteractive());
  PLUME_CHECK(s.Mapper->GetGridComputeCount() == 2);

  // ---- input waiting (the application's abort check says so): the still
  // frame yields, and VTK does not show the aborted frame
  {
    vtkNew<vtkCallbackCommand> pending;
    pending->SetCallback([](vtkObject* caller, unsigned long, void*, void*) {
      static_cast<vtkRenderWindow*>(caller)->SetAbortRender(1);
    });
    const int before = s.Mapper->GetAbortedStillFrames();
    const unsigned long tag = s.Window->AddObserver(vtkCommand::AbortCheckEvent, pending);
    s.Window->SetDesiredUpdateRate(Still);
    s.Window->Render();
    s.Window->RemoveObserver(tag);
    std::printf("still frame with input waiting: aborted %d\n", s.Mapper->GetAbortedStillFrames() - before);
    PLUME_CHECK(s.Mapper->GetAbortedStillFrames() == before + 1);
    s.Window->Render(); // nothing waiting: drawn
    PLUME_CHECK(s.Mapper->GetAbortedStillFrames() == before + 1);
    PLUME_CHECK(!s.Mapper->GetLastInteractive());
  }

  // ---- the sheet alone reads no opaque depth (the far plane everywhere)
  s.Window->SetDesiredUpdateRate(Interactive);
  s.Camera(0.3, 0.2, 5.0, 0, 0, 0);
  s.Window->Render();
  PLUME_CHECK(!s.Mapper->GetLastOpaqueDepth());

  // ---- the cheap interactive setting: lattice 8 whose rays are interpolated
  // unless their second differences exceed 8 x 0.064 (loose: the frame
  // differs from the same lattice at the default tolerance)
  s.Mapper->SetInteractiveImageSampleDistance(8);
  s.Renderer->ResetCameraClippingRange();
  const auto tight = plume::test::ReadBack(s.Window);
  s.Mapper->SetInteractiveLatticeTolerance(0.064);
  {
    const sheettest::Result cheap = sheettest::CompareWithReference(s, tri, "cheap interactive frame");
    PLUME_CHECK(s.Mapper->GetLastImageSampleDistance() == 8);
    failures += sheettest::CheckGoal(cheap, "cheap interactive frame (lattice 8, tolerance 0.064)", 0.05, 0.25);
    const double d = plume::test::Compare(tight, plume::test::ReadBack(s.Window)).Max;
    std::printf("lattice 8, tolerance 0.064 vs 0.004: max difference %.4f\n", d);
    PLUME_CHECK(d > 0.0);
  }
  s.Mapper->SetInteractiveImageSampleDistance(2);
  s.Mapper->SetInteractiveLatticeTolerance(0.004);

  // ---- an opaque sphere through the sheet: the depth is read, rays stop at it
  s.AddOpaqueSphere(0.1, -0.1, 0.0, 0.35, 0.9, 0.5, 0.2);
  failures += sheettest::CheckGoal(
    sheettest::CompareWithReference(s, tri, "interactive, opaque crossing"), "interactive, opaque crossing");
  PLUME_CHECK(s.Mapper->GetLastOpaqueDepth());

  // ---- AutoAdjustQuality off: every frame is a still frame
  s.Mapper->AutoAdjustQualityOff();
  s.Window->SetDesiredUpdateRate(Interactive);
  s.Window->Render();
  PLUME_CHECK(!s.Mapper->GetLastInteractive());
  PLUME_CHECK(s.Mapper->GetLastImageSampleDistance() == 1);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
