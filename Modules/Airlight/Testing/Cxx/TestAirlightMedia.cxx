// Numeric and image test: a translucent smoke volume inside the airlight.
// vtkPlumeAirlightPass around vtkPlumeCompositingPass, whose media step draws
// Plume's volume mapper into the pass's media layer. The scene: the room of
// the airlight tests, a slab of uniform coloured smoke (vtkPlumeVolumeMapper,
// composite, unshaded, constant field) between the camera and the room's
// box and sphere, a point light behind the slab and a spot light in front of
// it, in a coloured haze. Against vtkPlumeAirlightReference with the same
// slab as an exact smoke box (its extinction dims the haze, the emission and
// the surfaces along each view ray; double precision, adaptive):
//  - the mapper alone (no haze) matches the smoke model (its colour c * alpha
//    and opacity 1 - exp(-sigma L)): the reference's premise;
//  - the pass matches the reference to the goal (RMS <= 0.5 %, max
//    <= 2 % of the airlight range), on the slab's pixels and on all pixels;
//  - the former behaviour (the smoke drawn into the scene colour, the haze as
//    if the smoke lay on the opaque surface behind it: a plain
//    vtkRenderStepsPass delegate) is far off the reference on the slab's
//    pixels: the test tells the two apart;
//  - the 8-bit picture matches the committed baseline TestAirlightMedia.png
//    within one level.
#include "plumeAirlightTestUtil.h"

#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlumeCompositingPass.h"
#include "vtkPlumeVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

namespace
{
// The slab (world bounds), its extinction and colour.
const double Slab[6] = { -2.2, 1.4, 0.0, 2.6, 0.2, 0.5 };
const double Sigma = 3.0;                      // 1/length: alpha = 0.59 straight through
const double SmokeColour[3] = { 0.85, 0.55, 0.3 };
const double UnitDistance = 0.1;

vtkSmartPointer<vtkVolume> MakeSlab()
{
  const int n[3] = { 10, 8, 4 };
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n[0], n[1], n[2]);
  image->SetOrigin(Slab[0], Slab[2], Slab[4]);
  image->SetSpacing((Slab[1] - Slab[0]) / (n[0] - 1), (Slab[3] - Slab[2]) / (n[1] - 1), (Slab[5] - Slab[4]) / (n[2] - 1));
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfTuples(static_cast<vtkIdType>(n[0]) * n[1] * n[2]);
  values->FillValue(1.0f);
  image->GetPointData()->SetScalars(values);
  vtkNew<vtkPlumeVolumeMapper> mapper;
  mapper->SetInputData(image);
  mapper->SetAutoAdjustSampleDistances(false);
  mapper->SetImageSampleDistance(1);
  mapper->SetSampleDistance(0.1);
  mapper->SetTerminationError(0.0);
  mapper->SetOpacityUnitDistance(UnitDistance);
  mapper->SetTransferFunctionRange(0.0, 2.0);
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  vtkNew<vtkColorTransferFunction> colour;
  colour->AddRGBPoint(0.0, SmokeColour[0], SmokeColour[1], SmokeColour[2]);
  colour->AddRGBPoint(2.0, SmokeColour[0], SmokeColour[1], SmokeColour[2]);
  vtkNew<vtkPiecewiseFunction> opacity;
  const double a = 1.0 - std::exp(-Sigma * UnitDistance); // opacity per unit distance
  opacity->AddPoint(0.0, a);
  opacity->AddPoint(2.0, a);
  volume->GetProperty()->SetColor(colour);
  volume->GetProperty()->SetScalarOpacity(opacity);
  volume->GetProperty()->SetInterpolationTypeToLinear();
  volume->GetProperty()->ShadeOff();
  return volume;
}
}

int TestAirlightMedia(int, char*[])
{
  int failures = 0;
  const int W = 96, H = 72;
  airtest::Scene s(W, H);
  s.AddRoom();
  s.AddPointLight(-0.4, 1.7, -2.6, 1.0, 0.85, 0.7, 1.0); // behind the slab
  const double p[3] = { 2.2, 3.4, 2.4 }, f[3] = { 0.6, 0.0, 0.9 };
  s.AddSpotLight(p, f, 32.0, 1.0, 0.7, 0.8, 1.0, 1.0); // in front of it
  s.Pass->SetScattering(0.2, 0.22, 0.26);
  s.Pass->SetAbsorption(0.03, 0.03, 0.04);
  s.Pass->SetIntensityScale(8.0);
  vtkSmartPointer<vtkVolume> slab = MakeSlab();
  s.Renderer->AddVolume(slab);
  s.Camera(2.4, 1.7, 5.2, -0.4, 1.0, -2.0);
  vtkNew<vtkPlumeCompositingPass> compositing;

  // The surfaces without the smoke (the reference's input), and the smoke
  // alone over them without haze (the mapper against the smoke model).
  slab->SetVisibility(false);
  const airtest::FloatImage plain = s.RenderFloat(nullptr);
  slab->SetVisibility(true);
  const airtest::FloatImage smokeOnly = s.RenderFloat(compositing);

  // The pass around the compositing pass (media in the layer).
  s.Pass->SetDelegatePass(compositing);
  const airtest::FloatImage image = s.RenderFloat(s.Pass);
  PLUME_CHECK(s.Pass->GetNumberOfMediaInLayer() == 1);
  PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
  PLUME_CHECK(!plume::test::HasNonFinite(image));
  // The former behaviour: the smoke drawn into the scene colour (no layer).
  s.Pass->SetDelegatePass(s.Steps);
  const airtest::FloatImage former = s.RenderFloat(s.Pass);
  PLUME_CHECK(s.Pass->GetNumberOfMediaInLayer() == 0);
  s.Pass->SetDelegatePass(compositing);

  // The reference with the slab as an exact smoke box.
  vtkNew<vtkPlumeAirlightReference> ref;
  ref->SetScattering(s.Pass->GetScattering());
  ref->SetAbsorption(s.Pass->GetAbsorption());
  ref->SetIntensityScale(s.Pass->GetIntensityScale());
  ref->SetLights(s.Renderer);
  ref->AddSmokeBox(Slab, Sigma, SmokeColour);
  std::vector<float> surface(plain.RGBA);
  for (float& v : surface)
  {
    v = std::min(std::max(v, 0.0f), 1.0f);
  }
  airtest::FloatImage expected = plain, air = plain;
  ref->ComputeImage(s.Renderer, W, H, surface.data(), plain.Depth.data(), expected.RGBA, 1, &air.RGBA);
  // The smoke model without haze: the same reference with ks = ka = 0.
  vtkNew<vtkPlumeAirlightReference> bare;
  bare->AddSmokeBox(Slab, Sigma, SmokeColour);
  airtest::FloatImage bareExpected = plain, bareAir = plain;
  bare->ComputeImage(s.Renderer, W, H, surface.data(), plain.Depth.data(), bareExpected.RGBA, 1, &bareAir.RGBA);

  // The slab's pixels: where the smoke layer changes the plain frame.
  airtest::FloatImage refSlab = expected, refBareSlab = bareExpected;
  size_t slabPixels = 0;
  for (size_t q = 0; q < static_cast<size_t>(W) * H; ++q)
  {
    bool changed = false;
    for (int c = 0; c < 3; ++c)
    {
      changed = changed || std::fabs(bareExpected.RGBA[4 * q + c] - surface[4 * q + c]) > 1e-3;
    }
    slabPixels += changed;
    if (!changed)
    {
      refSlab.RGBA[4 * q] = std::numeric_limits<float>::quiet_NaN();
      refBareSlab.RGBA[4 * q] = std::numeric_limits<float>::quiet_NaN();
    }
  }
  std::cout << slabPixels << " of " << W * H << " pixels see the smoke\n";
  PLUME_CHECK(slabPixels > static_cast<size_t>(W * H / 4));

  // Errors in % of the frame's airlight range (the reference's haze airlight).
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (size_t q = 0; q < static_cast<size_t>(W) * H; ++q)
  {
    for (int c = 0; c < 3; ++c)
    {
      lo = std::min(lo, double(air.RGBA[4 * q + c]));
      hi = std::max(hi, double(air.RGBA[4 * q + c]));
    }
  }
  const double range = hi - lo;
  auto compare = [&](const airtest::FloatImage& img, const airtest::FloatImage& reference) {
    airtest::Error e = airtest::Compare(img, reference, air);
    e.RMS *= e.Range / range;
    e.Max *= e.Range / range;
    e.Range = range;
    return e;
  };
  const airtest::Error mapperErr = compare(smokeOnly, refBareSlab);
  const airtest::Error slabErr = compare(image, refSlab);
  const airtest::Error allErr = compare(image, expected);
  const airtest::Error formerErr = compare(former, refSlab);
  airtest::Print("smoke alone (no haze): the volume mapper vs the smoke model", mapperErr);
  airtest::Print("pass with the media layer vs the reference, smoke pixels", slabErr);
  airtest::Print("pass with the media layer vs the reference, all pixels", allErr);
  airtest::Print("former behaviour (smoke in the scene colour) vs the reference, smoke pixels", formerErr);
  airtest::Dump(image, "media pass");
  airtest::Dump(expected, "media reference");
  airtest::Dump(former, "media former");
  airtest::Dump(smokeOnly, "media smoke only");
  if (std::getenv("PLUME_AIRLIGHT_VERBOSE"))
  {
    for (int q : { 42 * W + 50, 36 * W + 48, 30 * W + 30, 50 * W + 20 })
    {
      std::cout << "pixel " << q % W << " " << q / W << ":";
      for (const airtest::FloatImage* img : std::initializer_list<const airtest::FloatImage*>{ &image, &expected, &former, &plain, &smokeOnly, &air })
      {
        std::cout << " (" << img->RGBA[4 * q] << " " << img->RGBA[4 * q + 1] << " " << img->RGBA[4 * q + 2] << ")";
      }
      std::cout << "\n";
    }
  }
  PLUME_CHECK(range > 0.2);
  PLUME_CHECK(mapperErr.RMS <= 0.005 && mapperErr.Max <= 0.02);
  PLUME_CHECK(slabErr.RMS <= 0.005);
  PLUME_CHECK(slabErr.Max <= 0.02);
  PLUME_CHECK(allErr.RMS <= 0.005);
  PLUME_CHECK(allErr.Max <= 0.02);
  PLUME_CHECK(formerErr.RMS >= 0.03); // what the test tells apart

  // The picture (8-bit, as Dump rounds) against the committed baseline.
  size_t overOne = 0;
  const int levels = airtest::BaselineDifference(image, "TestAirlightMedia", &overOne);
  std::cout << "baseline TestAirlightMedia.png: largest difference " << levels << " levels, " << overOne
            << " channels off by more than 1\n";
  PLUME_CHECK(levels >= 0 && levels <= 1);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
