// The pass in a renderer that covers only the right half of the window (a
// second, plain renderer on the left): its pixels must equal the same scene
// rendered through the pass in a window of the half's size, and the left
// renderer must keep its own background.
#include "plumeAirlightTestUtil.h"

namespace
{
void Setup(airtest::Scene& s)
{
  s.AddRoom();
  s.AddPointLight(-3.0, 3.0, 1.0, 1.0, 0.9, 0.7);
  const double sp[3] = { 2.5, 3.5, -1.5 }, sf[3] = { 0.5, 0.0, -1.5 };
  s.AddSpotLight(sp, sf, 35.0, 2.0, 0.7, 0.8, 1.0);
  s.Pass->SetScattering(0.25, 0.2, 0.15);
  s.Pass->SetAbsorption(0.02, 0.04, 0.08);
  s.Pass->SetIntensityScale(30.0);
  s.Camera(0.5, 1.6, 6.0, -0.3, 1.2, -2.0);
}
}

int TestAirlightViewport(int, char*[])
{
  int failures = 0;
  const int W = 120, H = 90;
  airtest::Scene alone(W, H);
  Setup(alone);
  const airtest::FloatImage expected = alone.RenderAirlight();

  airtest::Scene half(2 * W, H);
  Setup(half);
  half.Renderer->SetViewport(0.5, 0.0, 1.0, 1.0);
  vtkNew<vtkRenderer> left;
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  left->SetBackground(0.9, 0.2, 0.1);
  half.Window->AddRenderer(left);
  const airtest::FloatImage image = half.RenderAirlight();
  PLUME_CHECK(plume::test::GLErrors(half.Window).empty());

  double worst = 0, leftWorst = 0;
  for (int y = 0; y < H; ++y)
  {
    for (int x = 0; x < W; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::fabs(double(image.Pixel(W + x, y)[c]) - expected.Pixel(x, y)[c]));
        const double bg[3] = { 0.9, 0.2, 0.1 };
        leftWorst = std::max(leftWorst, std::fabs(double(image.Pixel(x, y)[c]) - bg[c]));
      }
    }
  }
  std::cout << "right-half renderer vs its own window: max difference " << worst
            << "; left renderer vs its background: " << leftWorst << "\n";
  PLUME_CHECK(worst <= 2.0 / 255.0);
  PLUME_CHECK(leftWorst <= 1.0 / 255.0);
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
