// Numeric test (no baseline): textured spot lights. A spot light projects an
// asymmetric coloured 16 x 12 image (bars, a colour ramp, a block of zeros)
// into a coloured medium; the pass's closed form (the image weighted per
// sub-interval, two per texel crossed) against the independent
// double-precision vtkPlumeAirlightReference, which evaluates the image at
// every point of its adaptive integral. Goal: RMS <= 0.5 % and max <= 2 % of
// the airlight image's range. The test also shows it can see the image: the
// reference with the image turned (its up hint rotated by 90 degrees) is far
// off the pass. Stress: a 1 x 1 image of colour c equals the untextured light
// of colour c (exponent 0: the sub-intervals telescope); an image of zeros
// is the light switched off; NaN, infinite and negative texels count as
// 0 (no NaN pixel, no GL error); a 1 x 1 image with an exponent.
#include "plumeAirlightTestUtil.h"

#include "vtkActorCollection.h"
#include "vtkFloatArray.h"
#include "vtkUnsignedCharArray.h"

int TestAirlightTexture(int, char*[])
{
  int failures = 0;
  const int W = 96, H = 72;
  const double sp[3] = { -0.5, 4.2, -1.2 }, sf[3] = { 0.2, 0.0, -1.6 };

  airtest::Scene s(W, H);
  // Every pixel evaluated: the stresses compare a textured spot (never on the
  // airlight lattice) with untextured lights (on it by default) to 1e-5.
  s.Pass->SetDownsampling(1);
  s.AddRoom();
  s.AddPointLight(-4.0, 3.5, 2.5, 1.0, 0.9, 0.7, 0.3);
  vtkLight* spot = s.AddSpotLight(sp, sf, 32.0, 1.0, 1.0, 0.95, 0.9, 1.0);
  s.Pass->SetScattering(0.25, 0.2, 0.15);
  s.Pass->SetAbsorption(0.02, 0.04, 0.08);
  s.Pass->SetIntensityScale(40.0);
  s.Camera(0.5, 1.6, 6.0, -0.3, 1.6, -2.0);

  vtkSmartPointer<vtkImageData> gobo = airtest::Gobo();
  vtkPlumeAirlightPass::SetLightTexture(spot, gobo);
  PLUME_CHECK(vtkPlumeAirlightPass::GetLightTexture(spot) == gobo);

  // the surfaces with the image on them, as the pass draws them (TestAirlightGoboSurface checks them)
  const airtest::FloatImage plain = s.RenderSurfaces();
  airtest::FloatImage air;
  const airtest::FloatImage ref = s.Reference(plain, 2, &air, false);
  const airtest::FloatImage image = s.RenderFloat(s.Pass);
  PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
  PLUME_CHECK(!plume::test::HasNonFinite(image));
  PLUME_CHECK(s.Pass->GetNumberOfTexturedLights() == 1);
  const airtest::Error e = airtest::Compare(image, ref, air);
  airtest::Print("textured spot (gobo 16x12), coloured medium (float)", e);
  airtest::Dump(image, "texture pass", 2.0);
  airtest::Dump(ref, "texture reference", 2.0);
  PLUME_CHECK(e.Range > 0.1); // the beam really is in view
  PLUME_CHECK(e.RMS <= 0.005);
  PLUME_CHECK(e.Max <= 0.02);

  // The image matters: untextured, and with the image turned by 90 degrees
  // (up hint along the light's x), the reference is far from the pass.
  {
    vtkPlumeAirlightPass::SetLightTexture(spot, nullptr);
    const airtest::FloatImage plainRef = s.Reference(s.RenderSurfaces(), 4, nullptr, false);
    const airtest::Error untextured = airtest::Compare(image, plainRef, air);
    std::cout << "pass (textured) vs reference untextured: ";
    airtest::Print("", untextured);
    PLUME_CHECK(untextured.RMS > 0.05);
    vtkPlumeAirlightPass::SetLightTexture(spot, gobo);
    vtkPlumeAirlightPass::SetLightTextureUp(spot, 1.0, 0.0, 0.0);
    const airtest::FloatImage turnedRef = s.Reference(s.RenderSurfaces(), 4, nullptr, false);
    const airtest::Error turned = airtest::Compare(image, turnedRef, air);
    std::cout << "pass vs reference with the image turned by 90 degrees: ";
    airtest::Print("", turned);
    PLUME_CHECK(turned.RMS > 0.005 && turned.Max > 0.02); // fails the goal
    // ... and the pass follows the hint too
    const airtest::FloatImage turnedPass = s.RenderFloat(s.Pass);
    const airtest::Error turnedBoth = airtest::Compare(turnedPass, turnedRef, air);
    std::cout << "turned, pass vs reference: ";
    airtest::Print("", turnedBoth);
    PLUME_CHECK(turnedBoth.RMS <= 0.005);
    PLUME_CHECK(turnedBoth.Max <= 0.02);
    vtkPlumeAirlightPass::SetLightTextureUp(spot, 0.0, 1.0, 0.0);
  }

  // Error against SpotSteps (the texture's own rule is two sub-intervals per texel crossed).
  for (int k : { 2, 32 })
  {
    s.Pass->SetSpotSteps(k);
    const airtest::Error ek = airtest::Compare(s.RenderFloat(s.Pass), ref, air);
    std::cout << "spot steps " << k << ": ";
    airtest::Print("", ek);
  }
  s.Pass->SetSpotSteps(8);

  // The brute-force peer with the same image converges to the reference too.
  s.Pass->SetMarchSteps(2048);
  {
    const airtest::Error em = airtest::Compare(s.RenderFloat(s.Pass), ref, air);
    std::cout << "brute-force march, 2048 steps: ";
    airtest::Print("", em);
    PLUME_CHECK(em.RMS <= 0.005);
  }
  s.Pass->SetMarchSteps(0);

  // Stress 1: a 1 x 1 image of colour c at exponent 0 is the untextured light
  // of colour c (the closed form over the cone; the textured path's
  // sub-intervals telescope). Surfaces black from here on, so that the images
  // are the airlight alone.
  {
    vtkActorCollection* actors = s.Renderer->GetActors();
    actors->InitTraversal();
    while (vtkActor* actor = actors->GetNextActor())
    {
      actor->GetProperty()->SetAmbient(0.0);
      actor->GetProperty()->SetDiffuse(0.0);
      actor->GetProperty()->SetSpecular(0.0);
    }
    spot->SetExponent(0.0);
    vtkPlumeAirlightPass::SetLightTexture(spot, airtest::ConstantImage(1, 1, 0.5f, 0.25f, 1.0f));
    const airtest::FloatImage one = s.RenderFloat(s.Pass);
    vtkPlumeAirlightPass::SetLightTexture(spot, nullptr);
    spot->SetColor(0.5 * 1.0, 0.25 * 0.95, 1.0 * 0.9);
    const airtest::FloatImage coloured = s.RenderFloat(s.Pass);
    PLUME_CHECK(!plume::test::HasNonFinite(one));
    const airtest::Error e1 = airtest::Compare(one, coloured, air);
    std::cout << "1x1 image vs the light of its colour: ";
    airtest::Print("", e1);
    PLUME_CHECK(e1.Max <= 1e-4);
    spot->SetColor(1.0, 0.95, 0.9);
    spot->SetExponent(1.0);
  }
  // Stress 2: an image of zeros: only the point light is left.
  {
    vtkPlumeAirlightPass::SetLightTexture(spot, airtest::ConstantImage(3, 2, 0.0f, 0.0f, 0.0f));
    const airtest::FloatImage zero = s.RenderFloat(s.Pass);
    vtkPlumeAirlightPass::SetLightTexture(spot, nullptr);
    spot->SwitchOff();
    const airtest::FloatImage off = s.RenderFloat(s.Pass);
    spot->SwitchOn();
    PLUME_CHECK(!plume::test::HasNonFinite(zero));
    const airtest::Error e0 = airtest::Compare(zero, off, air);
    std::cout << "image of zeros vs the light off: ";
    airtest::Print("", e0);
    PLUME_CHECK(e0.Max <= 1e-5);
  }
  // Stress 3: NaN, infinite and negative texels count as 0; a 1 x 1 image with an exponent.
  {
    auto bad = airtest::ConstantImage(4, 4, 1.0f, 1.0f, 1.0f);
    auto* a = vtkFloatArray::SafeDownCast(bad->GetPointData()->GetScalars());
    a->SetTuple3(0, std::nanf(""), 1.0f, 1.0f);
    a->SetTuple3(5, HUGE_VALF, -HUGE_VALF, -3.0f);
    a->SetTuple3(10, std::nanf(""), std::nanf(""), std::nanf(""));
    vtkPlumeAirlightPass::SetLightTexture(spot, bad);
    const airtest::FloatImage img = s.RenderFloat(s.Pass);
    PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
    PLUME_CHECK(!plume::test::HasNonFinite(img));
    const airtest::FloatImage black = s.RenderFloat(nullptr); // the surfaces are black now
    const airtest::FloatImage badRef = s.Reference(black, 4, nullptr, false);
    const airtest::Error eb = airtest::Compare(img, badRef, air);
    std::cout << "NaN/inf/negative texels: ";
    airtest::Print("", eb);
    PLUME_CHECK(eb.RMS <= 0.005);
    PLUME_CHECK(eb.Max <= 0.02);
    vtkPlumeAirlightPass::SetLightTexture(spot, airtest::ConstantImage(1, 1, 0.8f, 0.6f, 0.4f));
    const airtest::FloatImage img1 = s.RenderFloat(s.Pass);
    PLUME_CHECK(!plume::test::HasNonFinite(img1));
    const airtest::Error e1 = airtest::Compare(img1, s.Reference(black, 4, nullptr, false), air);
    std::cout << "1x1 image, exponent 1: ";
    airtest::Print("", e1);
    PLUME_CHECK(e1.RMS <= 0.005);
    PLUME_CHECK(e1.Max <= 0.02);
  }
  PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
