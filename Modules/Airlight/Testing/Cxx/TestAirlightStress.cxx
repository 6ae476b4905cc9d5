// Stress test (no baseline): the degenerate and extreme configurations of the
// closed form. gamma -> 0 (a light on a view ray, the 1/d^2 integral diverges
// on that ray only) and gamma -> pi (a light right behind the eye, where Sun's
// A0 and arctan argument blow up), a light at the eye (every ray diverges),
// ks -> 0 and very large ks, surfaces 1e4 mean free paths away (far beyond
// any table), a camera inside an opaque box, a light inside the sphere, spot
// cones of 0.5 and 89.9 degrees with exponent 128, more lights than one
// shader takes, and the unchanged frame after it all. Every case: no NaN or Inf
// pixel, no GL error; where the reference is finite, the float image matches
// it to 0.5 % RMS / 2 % max of the airlight range.
#include "plumeAirlightTestUtil.h"

namespace
{
int failures = 0;

// Float frame through the pass; checks finiteness and GL errors.
airtest::FloatImage Clean(airtest::Scene& s, const char* what)
{
  const airtest::FloatImage image = s.RenderFloat(s.Pass);
  const std::string gl = plume::test::GLErrors(s.Window);
  if (plume::test::HasNonFinite(image) || !gl.empty())
  {
    std::cerr << what << ": non-finite pixel or GL error '" << gl << "'\n";
    ++failures;
  }
  return image;
}

// Compares with the reference on the pixels where the reference is finite and below `cap`.
void Against(airtest::Scene& s, const char* what, const airtest::FloatImage& plain,
  const airtest::FloatImage& image, double cap = 1e3)
{
  airtest::FloatImage air;
  airtest::FloatImage ref = s.Reference(plain, 2, &air, false);
  size_t skipped = 0;
  for (size_t p = 0; p < ref.RGBA.size() / 4; ++p)
  {
    bool singular = false;
    for (int c = 0; c < 3; ++c)
    {
      singular = singular || !std::isfinite(air.RGBA[4 * p + c]) || air.RGBA[4 * p + c] > cap;
    }
    if (singular && !std::isnan(ref.RGBA[4 * p]))
    {
      ++skipped;
      for (int c = 0; c < 4; ++c)
      {
        ref.RGBA[4 * p + c] = air.RGBA[4 * p + c] = std::numeric_limits<float>::quiet_NaN();
      }
    }
  }
  const airtest::Error e = airtest::Compare(image, ref, air);
  std::cout << what << " (" << skipped << " singular pixels left out): ";
  airtest::Print("", e);
  PLUME_CHECK(e.RMS <= 0.005);
  PLUME_CHECK(e.Max <= 0.02);
}

double Largest(const airtest::FloatImage& image)
{
  double hi = 0;
  for (size_t i = 0; i < image.RGBA.size(); i += 4)
  {
    hi = std::max({ hi, double(image.RGBA[i]), double(image.RGBA[i + 1]), double(image.RGBA[i + 2]) });
  }
  return hi;
}
}

int TestAirlightStress(int, char*[])
{
  const int W = 96, H = 72;

  // gamma -> 0: the light straight ahead on the optical axis, in front of the
  // back wall; odd window sizes put the centre pixel's ray through the light.
  {
    airtest::Scene s(W + 1, H + 1);
    s.AddRoom();
    s.AddPointLight(0.0, 1.5, -2.5, 1, 1, 1);
    s.Pass->SetScattering(0.2, 0.2, 0.2);
    s.Pass->SetAbsorption(0.05, 0.05, 0.05);
    s.Camera(0.0, 1.5, 5.0, 0.0, 1.5, -2.5);
    const airtest::FloatImage plain = s.RenderFloat(nullptr);
    const airtest::FloatImage image = Clean(s, "gamma -> 0");
    Against(s, "gamma -> 0", plain, image);
    std::cout << "gamma = 0: brightest pixel " << Largest(image) << "\n";
    PLUME_CHECK(Largest(image) > 1e3); // the ray through the light: huge, finite
  }

  // gamma -> pi: the light right behind the eye on the optical axis (exact limit,
  // no division by sin(gamma)); and a light 1e-6 off the axis behind the eye.
  for (double offset : { 0.0, 1e-6 })
  {
    airtest::Scene s(W, H);
    s.AddRoom();
    s.AddPointLight(offset, 1.5, 7.0, 1, 0.8, 0.6);
    s.Pass->SetScattering(0.2, 0.15, 0.1);
    s.Pass->SetAbsorption(0.0, 0.02, 0.04);
    s.Pass->SetIntensityScale(30.0);
    s.Camera(0.0, 1.5, 5.0, 0.0, 1.5, -2.5);
    const airtest::FloatImage plain = s.RenderFloat(nullptr);
    const airtest::FloatImage image = Clean(s, "gamma -> pi");
    Against(s, offset == 0.0 ? "gamma = pi" : "gamma = pi - 1e-6", plain, image);
  }

  // A medium and no positional light (haze for depth cues, the shader variant
  // without the light code): the surfaces dimmed by exp(-kt ds), no airlight.
  {
    airtest::Scene s(W, H);
    s.AddRoom();
    vtkNew<vtkLight> sun;
    sun->SetLightTypeToSceneLight();
    sun->SetPositional(false);
    sun->SetPosition(1.0, 3.0, 2.0);
    sun->SetFocalPoint(0.0, 0.0, 0.0);
    s.Renderer->AddLight(sun);
    s.Pass->SetScattering(0.2, 0.15, 0.1);
    s.Pass->SetAbsorption(0.0, 0.02, 0.04);
    s.Camera(0.5, 1.6, 6.0, -0.3, 1.2, -2.0);
    const airtest::FloatImage plain = s.RenderFloat(nullptr);
    const airtest::FloatImage image = Clean(s, "no positional light");
    PLUME_CHECK(s.Pass->GetNumberOfLightGroups() == 1);
    Against(s, "no positional light (absolute error)", plain, image);
  }

  // A light at the eye: the integral diverges on every ray; finite, saturated pixels.
  {
    airtest::Scene s(W, H);
    s.AddRoom();
    s.AddPointLight(0.5, 1.6, 6.0, 1, 1, 1);
    s.Pass->SetScattering(0.2, 0.2, 0.2);
    s.Camera(0.5, 1.6, 6.0, -0.3, 1.2, -2.0);
    const airtest::FloatImage image = Clean(s, "light at the eye");
    double lo = HUGE_VAL;
    for (size_t i = 0; i < image.RGBA.size(); i += 4)
    {
      lo = std::min(lo, double(image.RGBA[i]));
    }
    std::cout << "light at the eye: darkest pixel " << lo << "\n";
    PLUME_CHECK(lo >= 1.0);
  }

  // ks -> 0: the frame is the plain frame (to float precision), and matches the reference.
  {
    airtest::Scene s(W, H);
    s.AddRoom();
    s.AddPointLight(-1.0, 2.5, 0.5, 1, 1, 1);
    s.Pass->SetScattering(1e-9, 1e-9, 1e-9);
    s.Camera(0.5, 1.6, 6.0, -0.3, 1.2, -2.0);
    const airtest::FloatImage plain = s.RenderFloat(nullptr);
    const airtest::FloatImage image = Clean(s, "ks -> 0");
    // Surfaces keep their colour; where nothing was drawn the ray runs to
    // infinity, so the background is extinguished and only ~1e-9 airlight is left.
    double diff = 0, background = 0;
    size_t backgroundPixels = 0;
    for (size_t i = 0; i < image.RGBA.size(); i += 4)
    {
      const bool surface = plain.Depth[i / 4] < 1.0f;
      backgroundPixels += surface ? 0 : 1;
      for (int c = 0; c < 3; ++c)
      {
        const double expected = surface ? std::min(1.0f, plain.RGBA[i + c]) : 0.0;
        (surface ? diff : background) =
          std::max(surface ? diff : background, std::fabs(image.RGBA[i + c] - expected));
      }
    }
    std::cout << "ks = 1e-9: largest change on surfaces " << diff << ", largest background "
              << background << " (" << backgroundPixels << " pixels)\n";
    PLUME_CHECK(diff < 1e-5);
    PLUME_CHECK(backgroundPixels > 0 && background < 1e-6);
  }

  // Very large ks (1e3 per unit, mean free path 1 mm): a light 4 mm in front of
  // the eye, slightly off the axis, lights only the air right around the eye.
  {
    airtest::Scene s(W, H);
    s.AddRoom();
    s.AddPointLight(0.0003, 1.6002, 4.996, 1, 1, 1);
    s.Pass->SetScattering(1e3, 1e3, 1e3);
    s.Pass->SetIntensityScale(1e-3);
    s.Camera(0.0, 1.6, 5.0, 0.0, 1.6, -2.0);
    s.Renderer->GetActiveCamera()->SetClippingRange(0.001, 20.0);
    const airtest::FloatImage plain = s.RenderFloat(nullptr);
    const airtest::FloatImage image = Clean(s, "ks = 1e3");
    Against(s, "ks = 1e3", plain, image);
  }

  // Surfaces 1e4 units away with kt = 1 (1e4 mean free paths): airlight near the eye only.
  {
    airtest::Scene s(W, H);
    s.AddBox(-2e4, 2e4, -0.1, 0.0, -2e4, 2e4, 0.6, 0.6, 0.6);
    s.AddBox(-2e4, 2e4, 0.0, 2e4, -1e4 - 1, -1e4, 0.6, 0.6, 0.6);
    s.AddPointLight(1.0, 2.0, 3.0, 1, 1, 1);
    s.Pass->SetScattering(0.8, 0.8, 0.8);
    s.Pass->SetAbsorption(0.2, 0.2, 0.2);
    s.Camera(0.0, 1.5, 5.0, 0.0, 1.5, -1e4);
    const airtest::FloatImage plain = s.RenderFloat(nullptr);
    const airtest::FloatImage image = Clean(s, "far surfaces");
    Against(s, "far surfaces", plain, image);
  }

  // The camera inside an opaque box (every pixel at the box's inside), a light in the sphere.
  {
    airtest::Scene s(W, H);
    s.AddRoom();
    s.AddPointLight(1.6, 0.7, -1.0, 1, 1, 1); // the sphere's centre
    s.Pass->SetScattering(0.3, 0.2, 0.1);
    s.Pass->SetIntensityScale(10.0);
    s.Camera(0.5, 1.6, 6.0, -0.3, 1.2, -2.0);
    const airtest::FloatImage plain = s.RenderFloat(nullptr);
    const airtest::FloatImage image = Clean(s, "light inside the sphere");
    Against(s, "light inside the sphere", plain, image);
    s.Camera(-1.9, 0.8, -1.4, 3.0, 1.0, -1.4);
    s.Renderer->GetActiveCamera()->SetClippingRange(0.01, 100.0);
    const airtest::FloatImage plainInside = s.RenderFloat(nullptr);
    const airtest::FloatImage inside = Clean(s, "camera inside the box");
    Against(s, "camera inside the box", plainInside, inside);
  }

  // Spot cones of 0.5 and 89.9 degrees, exponent 128, and 10 lights (two light groups).
  {
    airtest::Scene s(W, H);
    s.AddRoom();
    const double p1[3] = { -2.0, 3.5, 0.0 }, f1[3] = { -1.0, 0.0, -1.0 };
    s.AddSpotLight(p1, f1, 0.5, 0.0, 1, 1, 1, 50.0);
    const double p2[3] = { 2.0, 3.0, 1.0 }, f2[3] = { 1.0, 0.0, -1.0 };
    s.AddSpotLight(p2, f2, 89.9, 128.0, 1, 0.8, 0.5, 3.0);
    s.Pass->SetScattering(0.2, 0.2, 0.2);
    s.Pass->SetIntensityScale(5.0);
    s.Camera(0.5, 1.6, 6.0, -0.3, 1.2, -2.0);
    const airtest::FloatImage plain = s.RenderFloat(nullptr);
    const airtest::FloatImage image = Clean(s, "extreme spots");
    Against(s, "extreme spots", plain, image);
    for (int k = 0; k < 8; ++k)
    {
      s.AddPointLight(-3.0 + 0.7 * k, 3.0, 2.0, 0.2, 0.2, 0.2);
    }
    Clean(s, "10 lights");
  }
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
