// Early ray termination from the error budget (TerminationError): a ray
// stops once its transmittance is below TerminationError / max(R, 1), R the
// brightest radiance a sample can emit per unit opacity. Checked on a dense
// blob (rays saturate) against the same image with termination off:
//  - the threshold is the one the budget gives (R computed here from the
//    transfer function's colours and the lighting);
//  - default budget (0.001): no pixel moves by more than one 8-bit step, the
//    mean change over the blob is within the budget, and the image is within
//    the default accuracy (RMS <= 0.5 % of full scale) of the CPU reference;
//  - a large budget (0.02) with a bright shaded blob (R = 2.2): the change is
//    visible (termination happens) yet no pixel moves by more than the budget
//    (plus one 8-bit step of read-back rounding).
#include "plumeVolumeTestUtil.h"

#include "vtkLight.h"

namespace
{
struct Change
{
  double Max = 0;
  double Mean = 0; // over the pixels the volume covers (differs from the background)
  size_t Pixels = 0;
};

Change Difference(const plume::test::FloatImage& a, const plume::test::FloatImage& b,
  const plume::test::FloatImage& background)
{
  Change c;
  double sum = 0;
  for (size_t p = 0; p + 3 < a.RGBA.size(); p += 4)
  {
    bool covered = false;
    for (int k = 0; k < 3; ++k)
    {
      covered = covered || std::fabs(b.RGBA[p + k] - background.RGBA[p + k]) > 0.5 / 255;
    }
    for (int k = 0; k < 3; ++k)
    {
      const double d = std::fabs(double(a.RGBA[p + k]) - b.RGBA[p + k]);
      c.Max = std::max(c.Max, d);
      if (covered)
      {
        sum += d;
      }
    }
    c.Pixels += covered ? 1 : 0;
  }
  c.Mean = c.Pixels ? sum / (3.0 * c.Pixels) : 0.0;
  return c;
}

// a dense, opaque blob: most rays through it saturate
plumevolumetest::Scene DenseBlob()
{
  using namespace plumevolumetest;
  Scene s = MakeScene(SmokeField(48), 200, 160);
  double range[2];
  s.Image->GetPointData()->GetScalars()->GetRange(range);
  SetTransferFunctions(s.Volume->GetProperty(), range[0], range[1], 1.0, 0.004 * s.Image->GetLength());
  s.Mapper->SetSampleDistance(0.5);
  return s;
}
}

int TestVolumeTermination(int, char*[])
{
  using namespace plumevolumetest;
  int failures = 0;
  // the transfer functions' brightest colour channel where opacity > 0 (SetTransferFunctions: orange 1.0 at the top)
  const double brightest = 1.0;
  {
    Scene s = DenseBlob();
    s.Volume->VisibilityOff();
    const plume::test::FloatImage background = plume::test::ReadBack(s.Window);
    s.Volume->VisibilityOn();
    const plume::test::FloatImage stopped = plume::test::ReadBack(s.Window);
    const double threshold = s.Mapper->GetEffectiveOpacityThreshold();
    s.Mapper->SetTerminationError(0);
    const plume::test::FloatImage full = plume::test::ReadBack(s.Window);
    const double never = s.Mapper->GetEffectiveOpacityThreshold();
    const Change c = Difference(stopped, full, background);
    const double budget = 0.001; // the default
    const double expected = 1.0 - budget / std::max(brightest, 1.0);
    const bool ok = std::fabs(threshold - expected) < 1e-12 && never == 1.0 && c.Pixels > 5000 &&
      c.Max <= 1.0 / 255 + 1e-6 && c.Mean <= budget;
    std::printf("%-44s threshold %.6f (%.6f), off %.1f; vs no termination: max %.5f (<= 1/255), mean %.6f (<= %.4f) over %zu px%s\n",
      "dense blob, default budget", threshold, expected, never, c.Max, c.Mean, budget, c.Pixels, ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
    // the default stays within the accuracy goal against the reference
    s.Mapper->SetTerminationError(budget);
    failures += Check("dense blob, default vs reference", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.005, 0.05);
  }
  {
    // bright shaded blob (a light of intensity 2): R = 1.0 (0.2 + 0.7 * 2) + 0.3 * 2 = 2.2
    Scene s = DenseBlob();
    vtkVolumeProperty* property = s.Volume->GetProperty();
    property->ShadeOn();
    property->SetAmbient(0.2);
    property->SetDiffuse(0.7);
    property->SetSpecular(0.3);
    property->SetSpecularPower(10);
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPosition(0.3, -0.4, 1.0);
    light->SetFocalPoint(0, 0, 0);
    light->SetPositional(false);
    light->SetIntensity(2.0);
    s.Renderer->AddLight(light);
    s.Renderer->AutomaticLightCreationOff();
    const double budget = 0.02;
    s.Mapper->SetTerminationError(budget);
    s.Volume->VisibilityOff();
    const plume::test::FloatImage background = plume::test::ReadBack(s.Window);
    s.Volume->VisibilityOn();
    const plume::test::FloatImage stopped = plume::test::ReadBack(s.Window);
    const double threshold = s.Mapper->GetEffectiveOpacityThreshold();
    s.Mapper->SetTerminationError(0);
    const plume::test::FloatImage full = plume::test::ReadBack(s.Window);
    const Change c = Difference(stopped, full, background);
    const double radiance = brightest * (0.2 + 0.7 * 2.0) + 0.3 * 2.0;
    const double expected = 1.0 - budget / std::max(radiance, 1.0);
    const bool ok = std::fabs(threshold - expected) < 1e-12 && c.Max > 2.0 / 255 && c.Max <= budget + 1.0 / 255 &&
      !plume::test::HasNonFinite(stopped) && plume::test::GLErrors(s.Window).empty();
    std::printf("%-44s threshold %.6f (%.6f); vs no termination: max %.5f (> 2/255, <= %.4f), mean %.6f%s\n",
      "bright shaded blob, budget 0.02", threshold, expected, c.Max, budget + 1.0 / 255, c.Mean, ok ? "" : "  FAIL");
    failures += ok ? 0 : 1;
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
