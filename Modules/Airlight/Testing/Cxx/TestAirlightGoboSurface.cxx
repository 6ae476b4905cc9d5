// Textured spot lights on surfaces (a gobo, a slide projector): the pass
// multiplies the spot's diffuse and specular light on opaque geometry by its
// image in the fragment's direction, the same projection as the airlight's.
//
// 1. Numeric, no medium: a white Lambertian floor lit by a point light and a
//    textured 30-degree spot (exponent 1), with a switched-off light before
//    them in the renderer's list (VTK's shaders count only switched-on
//    lights). Every floor pixel against the expected colour computed here in
//    double: the ray through the pixel's centre meets the floor plane, each
//    light adds colour * intensity * cone weight * max(0, n.l), the spot's
//    term times its image in that direction as vtkPlumeAirlightReference
//    evaluates it (its own projection and bilinear rule). Pixels within 1e-3
//    of the cone's edge (cos) are left out. The image must matter: the same
//    expectation without the image, or with the image turned, is far off.
// 2. Specular: an image of zeros on a shiny floor gives the frame with the
//    spot switched off (its diffuse and specular light both go).
// 3. Image baseline (Data/Baseline/TestAirlightGoboSurface.png, looked at):
//    the test room in haze, the spot's pattern on the floor, the box and
//    the wall and the same pattern in the beam's shafts, within one 8-bit
//    level per channel.
#include "plumeAirlightTestUtil.h"

#include "vtkMatrix4x4.h"

namespace
{
// The expected floor colour (RGB) at world point p (floor plane y = 0, normal
// +y, white, diffuse 1, ambient and specular 0) from the switched-on lights;
// `images` is the reference that knows the images (in its SetLights order),
// textured false leaves them out. `coneMargin`: |cos(angle to the axis) -
// cos(cone)| of the spot; `inCone`: the point is in the spot's cone.
void Expected(vtkRenderer* renderer, const vtkPlumeAirlightReference* images, const double p[3], bool textured,
  double rgb[3], double* coneMargin, bool* inCone)
{
  rgb[0] = rgb[1] = rgb[2] = 0.0;
  *coneMargin = HUGE_VAL;
  *inCone = false;
  vtkLightCollection* lights = renderer->GetLights();
  lights->InitTraversal();
  int positional = 0; // the reference's index: switched-on positional lights
  while (vtkLight* light = lights->GetNextItem())
  {
    if (!light->GetSwitch())
    {
      continue;
    }
    double lp[3], lf[3];
    light->GetTransformedPosition(lp);
    light->GetTransformedFocalPoint(lf);
    double v[3] = { p[0] - lp[0], p[1] - lp[1], p[2] - lp[2] };
    const double dist = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    double weight = std::max(0.0, -v[1] / dist); // n.l with n = +y, l = -v/|v|
    if (light->GetConeAngle() < 90.0)
    {
      double a[3] = { lf[0] - lp[0], lf[1] - lp[1], lf[2] - lp[2] };
      const double al = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
      const double coneDot = (v[0] * a[0] + v[1] * a[1] + v[2] * a[2]) / (dist * al);
      const double cosCone = std::cos(light->GetConeAngle() * M_PI / 180.0);
      *coneMargin = std::min(*coneMargin, std::fabs(coneDot - cosCone));
      weight *= coneDot >= cosCone ? std::pow(coneDot, light->GetExponent()) : 0.0;
      *inCone = *inCone || coneDot >= cosCone;
    }
    double image[3] = { 1.0, 1.0, 1.0 };
    if (textured)
    {
      images->ComputeLightTexture(positional, v, image);
    }
    double color[3];
    light->GetDiffuseColor(color);
    for (int c = 0; c < 3; ++c)
    {
      rgb[c] += light->GetIntensity() * color[c] * weight * image[c];
    }
    positional += light->GetPositional() ? 1 : 0;
  }
}

struct FloorError
{
  double Max = 0;
  size_t Pixels = 0, Lit = 0;
};

// The floor pixels of `image` against Expected (see above), in double.
FloorError CompareFloor(airtest::Scene& s, const airtest::FloatImage& image, bool textured)
{
  vtkNew<vtkPlumeAirlightReference> images;
  images->SetLights(s.Renderer);
  vtkCamera* cam = s.Renderer->GetActiveCamera();
  vtkNew<vtkMatrix4x4> toWorld;
  toWorld->DeepCopy(cam->GetCompositeProjectionTransformMatrix(s.Renderer->GetTiledAspectRatio(), -1, 1));
  toWorld->Invert();
  auto unproject = [&](double x, double y, double z, double out[3]) {
    double in[4] = { x, y, z, 1.0 }, w[4];
    toWorld->MultiplyPoint(in, w);
    for (int k = 0; k < 3; ++k)
    {
      out[k] = w[k] / w[3];
    }
  };
  FloorError e;
  for (int j = 0; j < image.Height; ++j)
  {
    for (int i = 0; i < image.Width; ++i)
    {
      const size_t px = static_cast<size_t>(j) * image.Width + i;
      const double x = 2.0 * (i + 0.5) / image.Width - 1.0, y = 2.0 * (j + 0.5) / image.Height - 1.0;
      double a[3], b[3];
      unproject(x, y, -1.0, a);
      unproject(x, y, 1.0, b);
      const double t = a[1] / (a[1] - b[1]); // the ray meets y = 0
      const double p[3] = { a[0] + t * (b[0] - a[0]), 0.0, a[2] + t * (b[2] - a[2]) };
      if (!(t > 0.0 && t < 1.0) || std::fabs(p[0]) > 4.9 || std::fabs(p[2]) > 3.9 || image.Depth[px] >= 1.0f)
      {
        continue; // not the floor (or too near its edges)
      }
      double rgb[3], margin;
      bool inCone;
      Expected(s.Renderer, images, p, textured, rgb, &margin, &inCone);
      if (margin < 1e-3)
      {
        continue; // VTK's float cone test may decide either way
      }
      ++e.Pixels;
      e.Lit += inCone;
      for (int c = 0; c < 3; ++c)
      {
        e.Max = std::max(e.Max, std::fabs(double(image.RGBA[4 * px + c]) - rgb[c]));
      }
    }
  }
  return e;
}
}

int TestAirlightGoboSurface(int, char*[])
{
  int failures = 0;
  const int W = 96, H = 72;
  airtest::Scene s(W, H);
  vtkActor* floor = s.AddBox(-5, 5, -0.1, 0, -4, 4, 1.0, 1.0, 1.0);
  floor->GetProperty()->SetAmbient(0.0);
  floor->GetProperty()->SetDiffuse(1.0);
  floor->GetProperty()->SetSpecular(0.0);
  vtkLight* off = s.AddPointLight(0.0, 2.0, 0.0, 1.0, 1.0, 1.0, 0.7);
  off->SwitchOff();
  s.AddPointLight(-3.0, 2.5, 1.0, 0.25, 0.2, 0.15);
  const double sp[3] = { 0.4, 3.0, -0.6 }, sf[3] = { 0.9, 0.0, -1.4 };
  vtkLight* spot = s.AddSpotLight(sp, sf, 30.0, 1.0, 1.0, 0.9, 0.8, 0.8);
  vtkPlumeAirlightPass::SetLightTexture(spot, airtest::Gobo());
  vtkPlumeAirlightPass::SetLightTextureUp(spot, 0.0, 0.0, -1.0);
  s.Camera(0.6, 3.4, 3.2, 0.7, 0.0, -1.3, 50);

  // 1. The floor against the double-precision expectation (no medium: the
  // pass only draws its delegate, with the image on the surfaces).
  const airtest::FloatImage image = s.RenderSurfaces();
  PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
  PLUME_CHECK(!plume::test::HasNonFinite(image));
  PLUME_CHECK(s.Surfaces->GetNumberOfTexturedLights() == 1);
  airtest::Dump(image, "gobo surface pass");
  const FloorError e = CompareFloor(s, image, true);
  std::cout << "floor under the textured spot: max error " << e.Max << " over " << e.Pixels << " pixels ("
            << e.Lit << " in the cone)\n";
  PLUME_CHECK(e.Pixels > static_cast<size_t>(W * H / 2));
  PLUME_CHECK(e.Lit > static_cast<size_t>(W * H / 8));
  PLUME_CHECK(e.Max <= 1e-4);
  // The image matters: without it, or turned by 90 degrees, the expectation is far off.
  const FloorError plain = CompareFloor(s, image, false);
  std::cout << "the same frame against the untextured expectation: max " << plain.Max << "\n";
  PLUME_CHECK(plain.Max > 0.2);
  vtkPlumeAirlightPass::SetLightTextureUp(spot, 1.0, 0.0, 0.0);
  const FloorError turned = CompareFloor(s, image, true);
  std::cout << "against the expectation with the image turned: max " << turned.Max << "\n";
  PLUME_CHECK(turned.Max > 0.2);
  // ... and the frame follows the turned image.
  const FloorError turnedBoth = CompareFloor(s, s.RenderSurfaces(), true);
  std::cout << "turned, frame against expectation: max " << turnedBoth.Max << "\n";
  PLUME_CHECK(turnedBoth.Max <= 1e-4);
  vtkPlumeAirlightPass::SetLightTextureUp(spot, 0.0, 0.0, -1.0);

  // 2. Diffuse and specular: an image of zeros on a shiny floor is the spot switched off.
  floor->GetProperty()->SetSpecular(1.0);
  floor->GetProperty()->SetSpecularPower(2.0);
  vtkPlumeAirlightPass::SetLightTexture(spot, nullptr);
  const airtest::FloatImage shiny = s.RenderSurfaces();
  vtkPlumeAirlightPass::SetLightTexture(spot, airtest::ConstantImage(2, 2, 0.0f, 0.0f, 0.0f));
  const airtest::FloatImage dark = s.RenderSurfaces();
  spot->SwitchOff();
  const airtest::FloatImage without = s.RenderSurfaces();
  spot->SwitchOn();
  const airtest::Error zero = airtest::Compare(dark, without, without);
  const airtest::Error lit = airtest::Compare(shiny, without, without);
  std::cout << "image of zeros vs the spot off: max " << zero.Max * zero.Range << "; untextured vs off: max "
            << lit.Max * lit.Range << "\n";
  PLUME_CHECK(lit.Max * lit.Range > 0.2);
  PLUME_CHECK(zero.Max * zero.Range <= 1e-6);
  floor->GetProperty()->SetSpecular(0.0);

  // 3. The room in haze: the pattern on the surfaces and in the air (baseline).
  {
    airtest::Scene room(W, H);
    room.AddRoom();
    room.AddPointLight(-4.0, 3.5, 2.5, 1.0, 0.9, 0.7, 0.3);
    const double rp[3] = { -0.5, 4.2, -1.2 }, rf[3] = { 0.2, 0.0, -1.6 };
    vtkLight* gobo = room.AddSpotLight(rp, rf, 32.0, 1.0, 1.0, 0.95, 0.9, 2.5);
    vtkPlumeAirlightPass::SetLightTexture(gobo, airtest::Gobo());
    room.Pass->SetScattering(0.1, 0.09, 0.08);
    room.Pass->SetAbsorption(0.01, 0.015, 0.02);
    room.Pass->SetIntensityScale(16.0);
    room.Camera(0.5, 1.8, 5.0, -0.3, 1.2, -2.0);
    const airtest::FloatImage hazy = room.RenderFloat(room.Pass);
    PLUME_CHECK(plume::test::GLErrors(room.Window).empty());
    size_t overOne = 0;
    const int levels = airtest::BaselineDifference(hazy, "TestAirlightGoboSurface", &overOne);
    std::cout << "room in haze vs baseline: " << levels << " levels at most, " << overOne
              << " channels off by more than one\n";
    PLUME_CHECK(levels >= 0 && levels <= 1);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
