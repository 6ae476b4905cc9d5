// The error-controlled ray lattice (ImageSampleDistance > 1): rays every L
// pixels, interpolated where their second differences are small and the
// opaque depth agrees, each pixel's own ray elsewhere. Checked, at L = 4, with
// jitter off (so one ray per pixel is the same ray wherever a pixel casts its
// own) against the image with one ray per pixel (L = 1) and against the CPU
// reference:
//  - smoke composite, an opaque sphere in the smoke (depth edges: rays between
//    lattice rays that hit the sphere and lattice rays that pass it), the
//    isosurface (silhouettes), the camera inside the volume: within the
//    accuracy bounds of the one-ray-per-pixel tests, and no pixel further from
//    the one-ray image than the bound given per case (0.015 in the smoke
//    cases: interpolating every pixel gives 0.039 there, and 0.25 at the
//    isosurface's silhouettes); the images must differ somewhere (pixels were
//    interpolated). (The rod, thinner than the lattice, is caught by the
//    colours of the lattice rays that stop on it, before the depth check.)
//  - fewer rays where the image is smooth, counted (CountRays): the smoke casts
//    at most a third of one ray per pixel, while cells at depth edges and
//    silhouettes cast their own (the opaque sphere and the rod add rays to the
//    smoke's count; lattice rays plus refined cells' pixels, the upper bound
//    the mapper reports); the default image (one ray per pixel) counts every
//    pixel;
//  - a smooth image at lattice 8 casts the lattice's rays: none refine with
//    the colour criterion off (no opaque geometry);
//  - no stale frames: after a camera move, a transfer-function change and a
//    data change, the image equals a fresh mapper's;
//  - ProfilePasses times every pass in order and leaves the image as it is;
//  - VTK's interaction convention: the interactive lattice while the window's
//    DesiredUpdateRate is 15 (the volume's allocated time below 1 s), the still
//    one at the still rate.
#include "plumeVolumeTestUtil.h"

#include "vtkActor.h"
#include "vtkCylinderSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkSphereSource.h"

#include <string>

namespace
{
using plume::test::FloatImage;

// max and RMS difference of RGB, and whether any pixel differs at all
struct Diff
{
  double Max = 0, RMS = 0;
};

Diff Difference(const FloatImage& a, const FloatImage& b)
{
  const plume::test::ImageError e = plume::test::Compare(a, b, 3);
  return { e.Max, e.RMS };
}

// renders the scene with lattice 1 and `lattice`; checks the lattice image
// against the reference and against the one-ray image; `rays` gets the
// lattice image's ray count
int CheckLattice(const char* name, plumevolumetest::Scene& s, int mode, double maxRMS, double maxError,
  double maxFromOneRay, size_t minCovered = 100, double* rays = nullptr)
{
  using namespace plumevolumetest;
  s.Mapper->CountRaysOn();
  s.Mapper->SetImageSampleDistance(1);
  const FloatImage one = plume::test::ReadBack(s.Window);
  const double oneRays = s.Mapper->GetLastRayCount();
  s.Mapper->SetImageSampleDistance(4);
  FloatImage latticeImage;
  const Result r = CompareWithReference(s, mode, 0.125, &latticeImage);
  const int used = s.Mapper->GetLastImageSampleDistance();
  const double latticeRays = s.Mapper->GetLastRayCount();
  if (rays)
  {
    *rays = latticeRays;
  }
  const double pixels = double(latticeImage.Width) * latticeImage.Height;
  const Diff d = Difference(latticeImage, one);
  int failures = Check(name, r, maxRMS, maxError, minCovered);
  const bool ok = used == 4 && d.Max <= maxFromOneRay && d.RMS > 0 && oneRays == pixels && latticeRays < pixels;
  std::printf("%-40s lattice %d; vs one ray per pixel: max %.4f (<= %.3f), RMS %.5f (> 0); rays %.0f of %.0f px "
              "(one ray per pixel: %.0f)%s\n",
    name, used, d.Max, maxFromOneRay, d.RMS, latticeRays, pixels, oneRays, ok ? "" : "  FAIL");
  return failures + (ok ? 0 : 1);
}
}

int TestVolumeLattice(int, char*[])
{
  using namespace plumevolumetest;
  int failures = 0;
  auto field = SmokeField(48);
  double smokeRays = 0;
  {
    Scene s = MakeScene(field, 240, 200);
    s.Mapper->JitterOff();
    failures += CheckLattice("smoke, lattice 4", s, vtkPlumeVolumeReference::COMPOSITE, 0.005, 0.05, 0.015, 100, &smokeRays);
    // a smooth image really casts fewer rays (240 x 200 pixels)
    const bool ok = smokeRays <= 240 * 200 / 3.0;
    std::printf("%-40s %.0f rays (<= a third of %d px)%s\n", "smoke, lattice 4, rays", smokeRays, 240 * 200,
      ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
  }
  {
    // a smooth image at lattice 8 casts the lattice's rays (a volume alone reads no depth):
    //  - with the colour criterion off (tolerance 1) and no opaque geometry,
    //    no cell refines: exactly the lattice's rays (the depth criterion
    //    once refined the cells along the lines through the view's centre,
    //    where rays that miss the opaque scene had their far points clamped to
    //    the box, jumping from one side to the other);
    Scene s = MakeScene(field, 240, 200);
    s.Mapper->CountRaysOn();
    s.Mapper->SetImageSampleDistance(8);
    const double latticeRays = (239 / 8 + 2) * (199 / 8 + 2);
    s.Mapper->SetLatticeTolerance(1.0);
    plume::test::ReadBack(s.Window);
    const double flat = s.Mapper->GetLastRayCount();
    const bool ok = flat == latticeRays;
    std::printf("%-40s colour criterion off: %.0f rays (the lattice's %.0f)%s\n",
      "smooth image, lattice 8, rays", flat, latticeRays, ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
  }
  {
    // depth edges: an opaque sphere inside the smoke
    Scene s = MakeScene(field, 240, 200);
    s.Mapper->JitterOff();
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(0.45, 0.45, 0.5);
    sphere->SetRadius(0.17);
    sphere->SetThetaResolution(48);
    sphere->SetPhiResolution(48);
    vtkNew<vtkPolyDataMapper> pm;
    pm->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(pm);
    s.Renderer->AddActor(actor);
    double rays = 0;
    failures += CheckLattice("opaque sphere, lattice 4", s, vtkPlumeVolumeReference::COMPOSITE, 0.005, 0.05, 0.015, 100, &rays);
    // its depth edges cast their own rays: with the colour criterion off
    // (tolerance 1) the cells along the sphere's silhouette refine (41 cells of
    // 4 x 4 here; at least 20 required), and without the sphere they do not
    s.Mapper->SetLatticeTolerance(1.0);
    plume::test::ReadBack(s.Window);
    const double withSphere = s.Mapper->GetLastRayCount();
    const bool depthRead = s.Mapper->GetLastOpaqueDepth();
    actor->VisibilityOff();
    plume::test::ReadBack(s.Window);
    const double without = s.Mapper->GetLastRayCount();
    // the volume alone reads no depth (the far plane everywhere); with the sphere it must
    const bool depthSkipped = !s.Mapper->GetLastOpaqueDepth();
    const bool ok = rays > smokeRays && withSphere >= without + 20 * 16 && depthRead && depthSkipped;
    std::printf("%-40s %.0f rays (> the smoke's %.0f); depth criterion alone: %.0f rays, %.0f without the sphere "
                "(>= 320 more); depth read with the sphere %d (1), alone %d (0)%s\n",
      "opaque sphere, lattice 4, rays", rays, smokeRays, withSphere, without, int(depthRead), int(!depthSkipped),
      ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
  }
  {
    // a depth edge the colours between lattice rays need not show: a thin rod
    // (about 2 pixels wide) in the middle of the smoke; lattice rays beside it
    // pass through all the smoke, its pixels' rays stop at it
    Scene s = MakeScene(field, 240, 200);
    s.Mapper->JitterOff();
    vtkNew<vtkCylinderSource> rod;
    rod->SetCenter(0.42, 0.42, 0.8);
    rod->SetRadius(0.006);
    rod->SetHeight(1.2);
    rod->SetResolution(16);
    vtkNew<vtkPolyDataMapper> pm;
    pm->SetInputConnection(rod->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(pm);
    actor->SetOrigin(0.42, 0.42, 0.8);
    actor->RotateZ(30);
    s.Renderer->AddActor(actor);
    double rays = 0;
    failures += CheckLattice("thin rod, lattice 4", s, vtkPlumeVolumeReference::COMPOSITE, 0.005, 0.05, 0.015, 100, &rays);
    const bool ok = rays > smokeRays;
    std::printf("%-40s %.0f rays (> the smoke's %.0f)%s\n", "thin rod, lattice 4, rays", rays, smokeRays,
      ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
  }
  {
    // isosurface silhouettes
    Scene s = MakeScene(field, 240, 200);
    s.Mapper->JitterOff();
    s.Mapper->SetBlendModeToIsoSurface();
    s.Mapper->SetIsoValue(0.55);
    s.Volume->GetProperty()->SetAmbient(0.2);
    s.Volume->GetProperty()->SetDiffuse(0.7);
    s.Volume->GetProperty()->SetSpecular(0.3);
    s.Volume->GetProperty()->SetSpecularPower(20);
    // (the lit surface's shading curves too much for the default tolerance at this
    // size: every pixel would cast its own ray; 0.02 interpolates its smooth
    // parts; interpolating across silhouettes would leave 0.25)
    s.Mapper->SetLatticeTolerance(0.02);
    failures += CheckLattice("isosurface, lattice 4", s, vtkPlumeVolumeReference::ISOSURFACE, 0.02, 1.0, 0.05);
  }
  {
    // camera inside the volume
    Scene s = MakeScene(field, 200, 200);
    s.Mapper->JitterOff();
    vtkCamera* camera = s.Renderer->GetActiveCamera();
    camera->SetPosition(0.5, 0.45, 0.55);
    camera->SetFocalPoint(0.2, 0.55, 0.3);
    camera->SetViewAngle(70);
    s.Renderer->ResetCameraClippingRange();
    camera->SetClippingRange(0.01, 5.0);
    failures += CheckLattice("camera inside, lattice 4", s, vtkPlumeVolumeReference::COMPOSITE, 0.006, 0.06, 0.03, 1000);
  }
  {
    // no stale frames: each change, then the image of a fresh mapper with the same state
    Scene s = MakeScene(field, 200, 160);
    s.Mapper->SetImageSampleDistance(4);
    plume::test::ReadBack(s.Window);
    s.Renderer->GetActiveCamera()->Azimuth(25);
    s.Renderer->ResetCameraClippingRange();
    const FloatImage moved = plume::test::ReadBack(s.Window);
    vtkColorTransferFunction* color = s.Volume->GetProperty()->GetRGBTransferFunction(0);
    color->AddRGBPoint(0.6, 0.9, 0.1, 0.1);
    const FloatImage recoloured = plume::test::ReadBack(s.Window);
    auto other = SmokeField(48, 0.05);
    s.Mapper->SetInputData(other);
    const FloatImage newData = plume::test::ReadBack(s.Window);
    auto fresh = [&](vtkImageData* image) {
      vtkNew<vtkPlumeVolumeMapper> m;
      m->SetInputData(image);
      m->SetImageSampleDistance(4);
      s.Volume->SetMapper(m);
      const FloatImage img = plume::test::ReadBack(s.Window);
      s.Volume->SetMapper(s.Mapper);
      return img;
    };
    const Diff d3 = Difference(newData, fresh(other));
    s.Mapper->SetInputData(field);
    color->RemovePoint(0.6);
    const Diff d1 = Difference(moved, fresh(field));
    color->AddRGBPoint(0.6, 0.9, 0.1, 0.1);
    const Diff d2 = Difference(recoloured, fresh(field));
    const Diff changed = Difference(moved, recoloured);
    const bool ok = d1.Max == 0 && d2.Max == 0 && d3.Max == 0 && changed.Max > 0.05;
    std::printf("%-40s after camera %.4f, transfer function %.4f, data %.4f (all 0); recolouring shows %.3f%s\n",
      "no stale frames, lattice 4", d1.Max, d2.Max, d3.Max, changed.Max, ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
  }
  {
    // ProfilePasses (the benchmark's per-pass times): every pass of the
    // lattice path timed, in order, and the same image as without it
    Scene s = MakeScene(field, 200, 160);
    s.Mapper->SetImageSampleDistance(4);
    s.Mapper->JitterOff();
    const FloatImage plain = plume::test::ReadBack(s.Window);
    s.Mapper->ProfilePassesOn();
    const FloatImage profiled = plume::test::ReadBack(s.Window);
    std::string passes;
    double total = 0;
    for (int p = 0; p < s.Mapper->GetNumberOfProfiledPasses(); ++p)
    {
      passes += std::string(p ? " " : "") + s.Mapper->GetProfiledPassName(p);
      total += s.Mapper->GetProfiledPassSeconds(p) >= 0 ? s.Mapper->GetProfiledPassSeconds(p) : -1e9;
    }
    s.Mapper->SetImageSampleDistance(1);
    plume::test::ReadBack(s.Window);
    const int onePass = s.Mapper->GetNumberOfProfiledPasses();
    const std::string last = onePass > 0 ? s.Mapper->GetProfiledPassName(onePass - 1) : "";
    const bool ok = passes == "resources depth setup lattice_rays classify interpolation rays" && total > 0 &&
      Difference(plain, profiled).Max == 0 && onePass == 4 && last == "rays";
    std::printf("%-40s lattice 4: %s (%.2f ms); same image %d; one ray per pixel: %d passes, last %s%s\n",
      "pass profile", passes.c_str(), 1e3 * total, int(Difference(plain, profiled).Max == 0), onePass, last.c_str(),
      ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
  }
  {
    // interactive: the render window's DesiredUpdateRate (what the interactor sets while the camera moves)
    Scene s = MakeScene(field, 200, 160);
    s.Mapper->SetInteractiveImageSampleDistance(3);
    s.Window->SetDesiredUpdateRate(15);
    plume::test::ReadBack(s.Window);
    const int moving = s.Mapper->GetLastImageSampleDistance();
    s.Window->SetDesiredUpdateRate(0.0001);
    plume::test::ReadBack(s.Window);
    const int still = s.Mapper->GetLastImageSampleDistance();
    s.Mapper->AutoAdjustSampleDistancesOff();
    s.Window->SetDesiredUpdateRate(15);
    plume::test::ReadBack(s.Window);
    const int off = s.Mapper->GetLastImageSampleDistance();
    const bool ok = moving == 3 && still == 1 && off == 1;
    std::printf("%-40s moving %d (3), still %d (1), auto-adjust off %d (1)%s\n", "interactive lattice", moving, still,
      off, ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
