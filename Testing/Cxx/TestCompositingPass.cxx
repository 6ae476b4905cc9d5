// vtkPlumeCompositingPass: the frame does not depend on the order actors are
// added in. A scene with every kind of participant -- an opaque sphere,
// fading glyph lines (surface step), a translucent VTK sphere (translucent
// step: VTK's OIT, or dual depth peeling), a smoke sheet and a raycast volume
// (media step) -- is rendered with the pass for all 24 orders of adding the
// four Plume/opaque props, the translucent sphere added at each of the five
// places in turn: the images must be identical. Without the pass (plain
// vtkRenderer, the documented stand-alone behaviour) the order matters, and
// the pass's image equals the plain renderer's in the one order that is
// right there (opaque first, glyphs, then media back to front; no
// translucent actor, which a plain renderer draws after the sheets). Also:
// dual depth peeling in the translucent step (the same image, any order),
// media sorted back to front, the depth shared once per frame, no GL error,
// no NaN.
#include "plumeTestSupport.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlumeCompositingPass.h"
#include "vtkPlumeSheetMapper.h"
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkPlumeVolumeMapper.h"
#include "vtkPlumeVortexSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace
{
constexpr int W = 120, H = 96;

vtkSmartPointer<vtkImageData> Blob(double x0, double y0, double z0)
{
  const int n = 20;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetSpacing(0.9 / (n - 1), 0.9 / (n - 1), 0.9 / (n - 1));
  image->SetOrigin(x0, y0, z0);
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfTuples(n * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        // an off-centre blob, so the image has no symmetry
        const double x = i / (n - 1.0) - 0.4, y = j / (n - 1.0) - 0.55, z = k / (n - 1.0) - 0.5;
        values->SetValue(i + n * (j + n * k), static_cast<float>(std::exp(-(x * x + y * y + z * z) / 0.06)));
      }
  image->GetPointData()->SetScalars(values);
  return image;
}

vtkSmartPointer<vtkPolyData> Sheet()
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-1.1, -0.9, -0.1);
  points->InsertNextPoint(1.0, -0.8, -0.2);
  points->InsertNextPoint(0.9, 0.9, 0.0);
  points->InsertNextPoint(-1.0, 0.8, 0.1);
  vtkNew<vtkCellArray> cells;
  const vtkIdType a[3] = { 0, 1, 2 }, b[3] = { 0, 2, 3 };
  cells->InsertNextCell(3, a);
  cells->InsertNextCell(3, b);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(cells);
  return poly;
}

struct Scene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkActor> Sphere, Glyphs, SheetActor, Glass;
  vtkSmartPointer<vtkVolume> Volume;
  vtkPlumeCompositingPass* Pass = nullptr;
};

// props: 0 sphere, 1 glyphs, 2 sheet, 3 volume, added in `order`; the
// translucent sphere ("glass") is added before order[glassAt] (4: last; -1:
// not at all)
Scene Make(const std::array<int, 4>& order, bool withPass, bool peeling, double volumeZ, int glassAt = 4)
{
  Scene s;
  s.Window = plume::test::MakeOffscreenWindow(W, H);
  s.Renderer = vtkSmartPointer<vtkRenderer>::New();
  s.Renderer->SetBackground(0.1, 0.12, 0.2);
  s.Renderer->SetUseDepthPeeling(peeling);
  s.Window->AddRenderer(s.Renderer);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.3, -0.1, 0.0);
  sphere->SetRadius(0.35);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  s.Sphere = vtkSmartPointer<vtkActor>::New();
  s.Sphere->SetMapper(sphereMapper);
  s.Sphere->GetProperty()->SetColor(0.9, 0.35, 0.2);

  // translucent, in front of the sheet and overlapping the volume's blob; one
  // layer (back faces culled), which VTK's OIT composites exactly
  vtkNew<vtkSphereSource> glass;
  glass->SetCenter(-0.45, 0.35, 0.35);
  glass->SetRadius(0.4);
  glass->SetThetaResolution(32);
  glass->SetPhiResolution(32);
  vtkNew<vtkPolyDataMapper> glassMapper;
  glassMapper->SetInputConnection(glass->GetOutputPort());
  s.Glass = vtkSmartPointer<vtkActor>::New();
  s.Glass->SetMapper(glassMapper);
  s.Glass->GetProperty()->SetColor(0.3, 0.55, 1.0);
  s.Glass->GetProperty()->SetOpacity(0.5);
  s.Glass->GetProperty()->BackfaceCullingOn();

  vtkNew<vtkPlumeVortexSource> vortex;
  vortex->SetDimensions(9, 7, 1);
  vortex->SetBounds(-1.2, 1.2, -1, 1, 0.25, 0.25);
  vortex->SetCenter(0.2, -0.1, 0);
  vortex->SetCoreRadius(0.6);
  vortex->Update();
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.0, 0.7);
  lut->Build();
  vtkNew<vtkPlumeVelocityGlyphMapper> glyphMapper;
  glyphMapper->SetInputData(vortex->GetOutput());
  glyphMapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
  glyphMapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
  glyphMapper->SetScale(0.5);
  glyphMapper->SetRootAlpha(0.1); // faded roots blend with what is behind them
  glyphMapper->SetLookupTable(lut);
  s.Glyphs = vtkSmartPointer<vtkActor>::New();
  s.Glyphs->SetMapper(glyphMapper);

  vtkNew<vtkPlumeSheetMapper> sheetMapper;
  sheetMapper->SetInputData(Sheet());
  sheetMapper->SetDensity(1.5);
  sheetMapper->SetBlurRadius(0.1);
  sheetMapper->SetThickness(0.15);
  const double smoke[3] = { 0.6, 0.8, 0.9 };
  sheetMapper->SetSmokeColor(smoke);
  s.SheetActor = vtkSmartPointer<vtkActor>::New();
  s.SheetActor->SetMapper(sheetMapper);

  vtkNew<vtkPlumeVolumeMapper> volumeMapper;
  volumeMapper->SetInputData(Blob(-1.3, -0.3, volumeZ));
  volumeMapper->JitterOff();
  s.Volume = vtkSmartPointer<vtkVolume>::New();
  s.Volume->SetMapper(volumeMapper);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.2, 0.9, 0.3);
  color->AddRGBPoint(1.0, 1.0, 1.0, 0.4);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.05, 0.0);
  opacity->AddPoint(1.0, 0.9);
  s.Volume->GetProperty()->SetColor(color);
  s.Volume->GetProperty()->SetScalarOpacity(opacity);
  s.Volume->GetProperty()->SetScalarOpacityUnitDistance(0.05);

  vtkProp* props[4] = { s.Sphere, s.Glyphs, s.SheetActor, s.Volume };
  for (int i = 0; i < 4; ++i)
  {
    if (i == glassAt)
    {
      s.Renderer->AddViewProp(s.Glass);
    }
    s.Renderer->AddViewProp(props[order[i]]);
  }
  if (glassAt == 4)
  {
    s.Renderer->AddViewProp(s.Glass);
  }
  if (withPass)
  {
    s.Pass = vtkPlumeCompositingPass::Install(s.Renderer);
  }
  vtkCamera* camera = s.Renderer->GetActiveCamera();
  camera->SetPosition(0.4, 0.3, 4.0);
  camera->SetFocalPoint(-0.1, 0.0, 0.0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(38);
  s.Renderer->ResetCameraClippingRange();
  return s;
}

plume::test::FloatImage RenderScene(Scene& s, int& failures, const char* what)
{
  plume::test::FloatImage image = plume::test::ReadBack(s.Window);
  const std::string gl = plume::test::GLErrors(s.Window);
  if (!gl.empty())
  {
    std::printf("%s: GL error %s\n", what, gl.c_str());
  }
  PLUME_CHECK(gl.empty());
  PLUME_CHECK(!plume::test::HasNonFinite(image));
  return image;
}
} // namespace

int TestCompositingPass(int argc, char* argv[])
{
  int failures = 0;
  const double front = 0.55; // volume in front of the sheet (nearer the camera)

  // ---- with the pass: every order gives the same image (the translucent
  // sphere added first, second, ..., last in turn)
  std::array<int, 4> order = { 0, 1, 2, 3 };
  plume::test::FloatImage reference;
  int permutations = 0;
  double worst = 0;
  do
  {
    Scene s = Make(order, true, false, front, permutations % 5);
    const plume::test::FloatImage image = RenderScene(s, failures, "pass");
    if (permutations == 0)
    {
      reference = image;
      if (argc > 1) // optional: where to save the frame, to look at it
      {
        vtkNew<vtkWindowToImageFilter> grab;
        grab->SetInput(s.Window);
        vtkNew<vtkPNGWriter> writer;
        writer->SetInputConnection(grab->GetOutputPort());
        writer->SetFileName(argv[1]);
        writer->Write();
      }
      PLUME_CHECK(s.Pass->GetLastDepthShared());
      PLUME_CHECK(s.Pass->GetLastSurfaceOrder().size() == 1);
      // media back to front: the sheet is farther than the volume here
      PLUME_CHECK(s.Pass->GetLastMediaOrder().size() == 2);
      PLUME_CHECK(s.Pass->GetLastMediaOrder().size() == 2 &&
        s.Pass->GetLastMediaOrder()[0] == s.SheetActor.Get() &&
        s.Pass->GetLastMediaOrder()[1] == s.Volume.Get());
    }
    else
    {
      worst = std::max(worst, plume::test::Compare(reference, image, 4).Max);
    }
    ++permutations;
  } while (std::next_permutation(order.begin(), order.end()));
  std::printf("pass: %d orders, largest difference from the first %.3g\n", permutations, worst);
  PLUME_CHECK(permutations == 24);
  PLUME_CHECK(worst <= 1e-6);

  // every participant shows: the scene is not trivially order-free
  const double background[3] = { 0.1, 0.12, 0.2 };
  const size_t foreground = plume::test::CountForeground(reference, background, 0.02);
  std::printf("pass: %zu of %d pixels differ from the background\n", foreground, W * H);
  PLUME_CHECK(foreground > static_cast<size_t>(W * H / 4));

  // the translucent sphere shows (its step ran)
  Scene clear = Make({ 0, 1, 2, 3 }, true, false, front, -1);
  const plume::test::FloatImage withoutGlass = RenderScene(clear, failures, "pass, no translucent actor");
  const double glassShows = plume::test::Compare(reference, withoutGlass, 3).Max;
  std::printf("pass: the translucent sphere changes the frame by up to %.3g\n", glassShows);
  PLUME_CHECK(glassShows > 0.05);

  // ---- without the pass: right order = the pass's image; a wrong one differs
  // (no translucent actor: a plain renderer draws it after the sheets)
  {
    Scene right = Make({ 0, 1, 2, 3 }, false, false, front, -1);
    const auto plainRight = RenderScene(right, failures, "plain, right order");
    const double d = plume::test::Compare(withoutGlass, plainRight, 4).Max;
    std::printf("plain renderer, opaque-glyphs-sheet-volume order vs pass: max %.3g\n", d);
    PLUME_CHECK(d <= 2.0 / 255);
    Scene wrong = Make({ 2, 1, 0, 3 }, false, false, front, -1);
    const auto plainWrong = RenderScene(wrong, failures, "plain, sheet first");
    const double w = plume::test::Compare(withoutGlass, plainWrong, 4).Max;
    std::printf("plain renderer, sheet added first vs pass: max %.3g (order matters without the pass)\n", w);
    PLUME_CHECK(w > 0.05);
  }

  // ---- dual depth peeling in the translucent step: same image, any order.
  // Frame alpha under a translucent surface is VTK's own per method (here
  // 0.44 with OIT, 0.66 with peeling over the background): the peeled frames
  // are compared with each other in RGBA and with the OIT frame in RGB.
  {
    double peeled = 0, peeledOrders = 0;
    plume::test::FloatImage firstPeeled;
    int glassAt = 0;
    for (const std::array<int, 4>& o : { std::array<int, 4>{ 0, 1, 2, 3 }, std::array<int, 4>{ 3, 2, 1, 0 },
           std::array<int, 4>{ 2, 0, 3, 1 } })
    {
      Scene s = Make(o, true, true, front, glassAt);
      const auto image = RenderScene(s, failures, "pass + depth peeling");
      peeled = std::max(peeled, plume::test::Compare(reference, image, 3).Max);
      if (glassAt == 0)
      {
        firstPeeled = image;
      }
      else
      {
        peeledOrders = std::max(peeledOrders, plume::test::Compare(firstPeeled, image, 4).Max);
      }
      glassAt += 2; // the translucent sphere first, third, last
    }
    std::printf("pass + dual depth peeling vs pass (OIT): max %.3g (RGB); 3 orders: max %.3g\n", peeled, peeledOrders);
    PLUME_CHECK(peeled <= 2.0 / 255);
    PLUME_CHECK(peeledOrders <= 1e-6);
  }

  // ---- no medium in the frame: no depth copy
  {
    Scene s = Make({ 0, 1, 2, 3 }, true, false, front);
    s.SheetActor->VisibilityOff();
    s.Volume->VisibilityOff();
    RenderScene(s, failures, "no medium");
    PLUME_CHECK(!s.Pass->GetLastDepthShared());
  }

  // ---- a volume behind the sheet is drawn first
  {
    Scene s = Make({ 3, 2, 1, 0 }, true, false, -1.6);
    RenderScene(s, failures, "volume behind");
    const auto& media = s.Pass->GetLastMediaOrder();
    PLUME_CHECK(media.size() == 2 && media[0] == s.Volume.Get() && media[1] == s.SheetActor.Get());
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int main(int argc, char* argv[])
{
  return TestCompositingPass(argc, argv);
}
