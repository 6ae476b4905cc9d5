// Jitter against wood-grain. With a coarse step (2 voxels) and a narrow
// opacity band, un-jittered rays all sample the same depths relative to the
// box's entry face, and the error against the reference shows as coherent
// bands (wood-grain). Jitter turns it into pixel-scale noise. The measure is
// the energy of the error image in the band of spatial frequencies where the
// bands live (a band-pass: 5x5 mean minus 17x17 mean, i.e. periods of ~5 to
// ~17 pixels): it must drop by at least 30% with jitter (measured: 42%), while the total
// error may not grow much.
#include "plumeVolumeTestUtil.h"

namespace
{
// box average of e over (2r+1)^2 pixels around (x, y), from a summed-area table
struct Box
{
  int W, H;
  std::vector<double> S; // (W+1)*(H+1)
  Box(const std::vector<double>& e, int w, int h)
    : W(w)
    , H(h)
    , S(static_cast<size_t>(w + 1) * (h + 1), 0.0)
  {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        S[(y + 1) * (W + 1) + x + 1] = e[static_cast<size_t>(y) * w + x] + S[y * (W + 1) + x + 1] +
          S[(y + 1) * (W + 1) + x] - S[y * (W + 1) + x];
  }
  double Mean(int x, int y, int r) const
  {
    const int x0 = x - r, x1 = x + r + 1, y0 = y - r, y1 = y + r + 1;
    return (S[y1 * (W + 1) + x1] - S[y0 * (W + 1) + x1] - S[y1 * (W + 1) + x0] + S[y0 * (W + 1) + x0]) /
      double((2 * r + 1) * (2 * r + 1));
  }
};

// RMS of the band-passed error: (5x5 mean) - (17x17 mean). Pixel-scale noise
// (jitter) is averaged away by the first, smooth bias by the second; the
// banded wood-grain (a few pixels per band) remains.
double GrainRMS(const plume::test::FloatImage& a, const std::vector<float>& b)
{
  const int w = a.Width, h = a.Height, r = 8;
  std::vector<double> e(static_cast<size_t>(w) * h);
  for (size_t p = 0; p < e.size(); ++p)
  {
    e[p] = (a.RGBA[4 * p] - b[4 * p]) + (a.RGBA[4 * p + 1] - b[4 * p + 1]) + (a.RGBA[4 * p + 2] - b[4 * p + 2]);
  }
  const Box box(e, w, h);
  double sum = 0;
  size_t count = 0;
  for (int y = r; y < h - r; ++y)
  {
    for (int x = r; x < w - r; ++x)
    {
      const double v = box.Mean(x, y, 2) - box.Mean(x, y, r);
      sum += v * v;
      ++count;
    }
  }
  return std::sqrt(sum / count);
}
}

int TestVolumeJitter(int, char*[])
{
  using namespace plumevolumetest;
  Scene s = MakeScene(SmokeField(64), 200, 160);
  // a narrow, dense opacity band: a soft shell around each puff
  vtkPiecewiseFunction* opacity = s.Volume->GetProperty()->GetScalarOpacity();
  opacity->RemoveAllPoints();
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(0.4, 0.0);
  opacity->AddPoint(0.45, 0.9);
  opacity->AddPoint(0.5, 0.0);
  s.Volume->GetProperty()->SetScalarOpacityUnitDistance(0.02);
  s.Mapper->SetSampleDistance(2.0);

  s.Mapper->JitterOff();
  plume::test::FloatImage plain;
  const Result r0 = CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE, 0.125, &plain);
  s.Mapper->JitterOn();
  plume::test::FloatImage jittered;
  const Result r1 = CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE, 0.125, &jittered);

  // the reference composited over the background (same for both)
  vtkNew<vtkPlumeVolumeReference> reference;
  reference->SetInputData(s.Image);
  reference->SetVolume(s.Volume);
  reference->SetRenderer(s.Renderer);
  s.Volume->VisibilityOff();
  const plume::test::FloatImage background = plume::test::ReadBack(s.Window);
  s.Volume->VisibilityOn();
  reference->SetOpaqueDepth(background.Depth);
  reference->Compute(plain.Width, plain.Height);
  const std::vector<float> expected = reference->CompositeOver(background.RGBA);

  const double grain0 = GrainRMS(plain, expected);
  const double grain1 = GrainRMS(jittered, expected);
  const bool ok = grain1 < 0.7 * grain0 && r1.RMS < 1.5 * r0.RMS && grain0 > 1e-3;
  std::printf("step 2 voxels: error RMS %.4f (no jitter) / %.4f (jitter); band-passed error RMS %.5f / %.5f "
              "(ratio %.2f)%s\n",
    r0.RMS, r1.RMS, grain0, grain1, grain1 / grain0, ok ? "" : "  FAIL");
  Dump("jitter_off", plain.RGBA, plain.Width, plain.Height);
  Dump("jitter_on", jittered.RGBA, jittered.Width, jittered.Height);
  Dump("jitter_reference", expected, plain.Width, plain.Height);
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
