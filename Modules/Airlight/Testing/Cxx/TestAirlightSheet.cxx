// Numeric test (no baseline): a smoke sheet inside the airlight. Smoke sheets
// do not blend "over" with one opacity: they multiply the frame by an RGB
// transmittance and add their colour, so the compositing pass draws them a
// second time over a white layer (MEDIA_TRANSMITTANCE) and the pass takes
// their RGB transmittance Tv from the difference. The scene: the airlight
// tests' room, a thin sheet (vtkPlumeSheetMapper, thin mode, varying density,
// an RGB absorption and a smoke colour) in the plane z = Z in front of the box and the sphere, a
// point light behind it and one in front of it, in a coloured haze.
// Expected per pixel, from the sheet's own colour Cv and transmittance Tv
// (the compositing frame without haze over a black and over a white
// background, opaque props hidden) and the independent double-precision
// reference airlight split at the ray's crossing xp of the sheet's plane:
//   A[0, xp] + T(xp) Cv + Tv (T(xp) A'[xp, ds] + T(ds) Cs),  T(x) = exp(-kt x).
// The pass must match it to the goal (RMS <= 0.5 %, max <= 2 % of the
// airlight range); the former behaviour (the sheet drawn into the scene
// colour: a plain vtkRenderStepsPass delegate) must not.
#include "plumeAirlightTestUtil.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkMatrix4x4.h"
#include "vtkPlumeCompositingPass.h"
#include "vtkPlumeSheetMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <glm/glm.hpp>

namespace
{
const double Z = 0.4;
const double X0 = -2.2, X1 = 1.4, Y0 = 1.0, Y1 = 2.6; // its blur (3 sigma) stays clear of the floor

vtkSmartPointer<vtkPolyData> Sheet()
{
  const int nx = 12, ny = 8;
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> d;
  d->SetName("density");
  vtkNew<vtkDoubleArray> absorption; // coloured smoke: an RGB transmittance, not one opacity
  absorption->SetName("absorption");
  absorption->SetNumberOfComponents(3);
  for (int j = 0; j <= ny; ++j)
  {
    for (int i = 0; i <= nx; ++i)
    {
      const double x = X0 + (X1 - X0) * i / nx, y = Y0 + (Y1 - Y0) * j / ny;
      pts->InsertNextPoint(x, y, Z);
      d->InsertNextValue(0.3 + 0.9 * (x - X0) / (X1 - X0)); // asymmetric: denser to the right
      absorption->InsertNextTuple3(0.5, 1.0, 1.6);
    }
  }
  vtkNew<vtkCellArray> cells;
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const vtkIdType a = j * (nx + 1) + i;
      const vtkIdType q[4] = { a, a + 1, a + nx + 2, a + nx + 1 };
      cells->InsertNextCell(4, q);
    }
  }
  poly->SetPoints(pts);
  poly->SetPolys(cells);
  poly->GetPointData()->AddArray(d);
  poly->GetPointData()->AddArray(absorption);
  return poly;
}
}

int TestAirlightSheet(int, char*[])
{
  int failures = 0;
  const int W = 80, H = 60;
  airtest::Scene s(W, H);
  s.AddRoom();
  s.AddPointLight(-0.5, 1.6, -2.8, 1.0, 0.85, 0.7, 1.0); // behind the sheet
  s.AddPointLight(2.6, 3.0, 6.5, 0.6, 0.75, 1.0, 0.6);   // in front of it, behind the camera
  s.Pass->SetScattering(0.2, 0.22, 0.26);
  s.Pass->SetAbsorption(0.03, 0.03, 0.04);
  s.Pass->SetIntensityScale(8.0);
  vtkNew<vtkPlumeSheetMapper> mapper;
  mapper->SetInputData(Sheet());
  mapper->SetDensityArrayName("density");
  mapper->SetAbsorptionArrayName("absorption");
  mapper->SetBlurRadius(0.25);
  mapper->ThinSheetOn();
  mapper->SetSmokeColor(0.7, 0.55, 0.4);
  vtkNew<vtkActor> sheet;
  sheet->SetMapper(mapper);
  s.Renderer->AddActor(sheet);
  s.Camera(2.2, 1.6, 5.0, -0.4, 1.1, -2.0);
  vtkNew<vtkPlumeCompositingPass> compositing;

  // The surfaces without the sheet; the sheet alone over black and over white.
  sheet->SetVisibility(false);
  const airtest::FloatImage plain = s.RenderFloat(nullptr);
  sheet->SetVisibility(true);
  std::vector<vtkProp*> opaque;
  {
    vtkPropCollection* props = s.Renderer->GetViewProps();
    vtkCollectionSimpleIterator it;
    props->InitTraversal(it);
    while (vtkProp* p = props->GetNextProp(it))
    {
      if (p != sheet.Get())
      {
        opaque.push_back(p);
        p->SetVisibility(false);
      }
    }
  }
  s.Renderer->SetBackground(0, 0, 0);
  const airtest::FloatImage black = s.RenderFloat(compositing);
  s.Renderer->SetBackground(1, 1, 1);
  const airtest::FloatImage white = s.RenderFloat(compositing);
  s.Renderer->SetBackground(0.1, 0.15, 0.3);
  for (vtkProp* p : opaque)
  {
    p->SetVisibility(true);
  }

  // The pass around the compositing pass, and the former behaviour.
  s.Pass->SetDelegatePass(compositing);
  const airtest::FloatImage image = s.RenderFloat(s.Pass);
  PLUME_CHECK(s.Pass->GetNumberOfMediaInLayer() == 1);
  PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
  PLUME_CHECK(!plume::test::HasNonFinite(image));
  s.Pass->SetDelegatePass(s.Steps);
  const airtest::FloatImage former = s.RenderFloat(s.Pass);
  s.Pass->SetDelegatePass(compositing);

  // The expected frame.
  vtkNew<vtkPlumeAirlightReference> ref;
  ref->SetScattering(s.Pass->GetScattering());
  ref->SetAbsorption(s.Pass->GetAbsorption());
  ref->SetIntensityScale(s.Pass->GetIntensityScale());
  ref->SetLights(s.Renderer);
  vtkCamera* cam = s.Renderer->GetActiveCamera();
  double eye[3];
  cam->GetPosition(eye);
  vtkNew<vtkMatrix4x4> fromClip;
  vtkMatrix4x4::Invert(cam->GetCompositeProjectionTransformMatrix(s.Renderer->GetTiledAspectRatio(), -1, 1), fromClip);
  auto unproject = [&](double nx, double ny, double nz) {
    double in[4] = { nx, ny, nz, 1.0 }, out[4];
    fromClip->MultiplyPoint(in, out);
    return glm::dvec3(out[0], out[1], out[2]) / out[3];
  };
  double kt[3];
  for (int c = 0; c < 3; ++c)
  {
    kt[c] = s.Pass->GetScattering()[c] + s.Pass->GetAbsorption()[c];
  }
  const glm::dvec3 o(eye[0], eye[1], eye[2]);
  airtest::FloatImage expected = plain, air = plain;
  size_t sheetPixels = 0;
  double darkest = 1.0, tvSpread = 0.0;
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      const size_t p = static_cast<size_t>(j) * W + i;
      const double nx = (i + 0.5) / W * 2 - 1, ny = (j + 0.5) / H * 2 - 1;
      const glm::dvec3 r = glm::normalize(unproject(nx, ny, 1.0) - o);
      const double ds = plain.Depth[p] < 1.0f
        ? glm::length(unproject(nx, ny, 2.0 * plain.Depth[p] - 1.0) - o)
        : std::numeric_limits<double>::infinity();
      // the ray's crossing of the sheet's plane, if it is in front of the surface
      double xp = ds;
      if (r.z != 0.0)
      {
        const double t = (Z - o.z) / r.z;
        if (t > 0.0 && t < ds)
        {
          xp = t;
        }
      }
      double front[3], back[3] = { 0, 0, 0 };
      const double origin[3] = { o.x, o.y, o.z }, dir[3] = { r.x, r.y, r.z };
      ref->ComputeRay(origin, dir, xp, front);
      if (xp < ds)
      {
        const glm::dvec3 q = o + xp * r;
        const double qa[3] = { q.x, q.y, q.z };
        ref->ComputeRay(qa, dir, ds - xp, back);
      }
      double tvMean = 0.0, tvMin = 1.0, tvMax = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        const double cv = black.RGBA[4 * p + c];
        const double tv = std::min(std::max(double(white.RGBA[4 * p + c]) - cv, 0.0), 1.0);
        tvMean += tv / 3.0;
        tvMin = std::min(tvMin, tv);
        tvMax = std::max(tvMax, tv);
        const double Tp = std::exp(-kt[c] * xp);
        const double Ts = std::isinf(ds) ? 0.0 : std::exp(-kt[c] * ds);
        const double cs = std::min(std::max(double(plain.RGBA[4 * p + c]), 0.0), 1.0);
        expected.RGBA[4 * p + c] = static_cast<float>(front[c] + Tp * cv + tv * (Tp * back[c] + Ts * cs));
        // (the range as the window shows it: clamped, like the other airlight tests)
        air.RGBA[4 * p + c] = static_cast<float>(std::min(front[c] + Tp * back[c], 1.0));
      }
      sheetPixels += tvMean < 0.99;
      darkest = std::min(darkest, tvMean);
      tvSpread = std::max(tvSpread, tvMax - tvMin);
    }
  }
  std::cout << sheetPixels << " of " << W * H << " pixels see the sheet; lowest mean transmittance " << darkest
            << ", largest spread between channels " << tvSpread << "\n";
  PLUME_CHECK(sheetPixels > static_cast<size_t>(W * H / 4));
  PLUME_CHECK(darkest < 0.6);
  PLUME_CHECK(tvSpread > 0.1); // the transmittance differs between channels
  const airtest::Error err = airtest::Compare(image, expected, air);
  const airtest::Error formerErr = airtest::Compare(former, expected, air);
  airtest::Print("sheet in the airlight vs the expected frame", err);
  airtest::Print("former behaviour (sheet in the scene colour) vs the expected frame", formerErr);
  airtest::Dump(image, "sheet pass");
  airtest::Dump(expected, "sheet expected");
  airtest::Dump(former, "sheet former");
  PLUME_CHECK(err.Range > 0.2);
  PLUME_CHECK(err.RMS <= 0.005);
  PLUME_CHECK(err.Max <= 0.02);
  PLUME_CHECK(formerErr.RMS >= 0.01 && formerErr.Max >= 0.2); // what the test tells apart
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
