// Image regression: the asymmetric test room (box left, sphere right) in a
// bluish haze with absorption, lit by a warm point light at the upper left
// and a cool spot light (cone 30 degrees, exponent 4) aimed at the floor on
// the right. The baseline was looked at: the point light's glow, the spot's
// cone of scattered light down to its lit floor patch, surfaces fading with
// distance and the background replaced by airlight.
#include "plumeAirlightTestUtil.h"

#include "vtkRegressionTestImage.h"

int TestAirlightRoom(int argc, char* argv[])
{
  int failures = 0;
  airtest::Scene s(300, 200);
  s.AddRoom();
  s.AddPointLight(-3.5, 3.2, 0.5, 1.0, 0.85, 0.6, 1.0);
  const double sp[3] = { 2.2, 3.8, -0.5 }, sf[3] = { 1.2, 0.0, -1.8 };
  s.AddSpotLight(sp, sf, 30.0, 4.0, 0.6, 0.8, 1.0, 1.0);
  s.Pass->SetScattering(0.12, 0.14, 0.18);
  s.Pass->SetAbsorption(0.03, 0.03, 0.02);
  s.Pass->SetIntensityScale(25.0);
  s.Camera(0.8, 1.8, 6.5, -0.4, 1.1, -2.0, 55);
  s.Renderer->SetPass(s.Pass);
  s.Window->Render();
  PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
  const int result = vtkRegressionTestImage(s.Window);
  return (failures == 0 && result != vtkRegressionTester::FAILED) ? EXIT_SUCCESS : EXIT_FAILURE;
}
