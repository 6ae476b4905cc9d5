// Helpers for the Plume::Sheets tests: a white-background scene, rendering
// with and without the sheet, and the comparison of the rendered
// transmittance with vtkPlumeSheetReference. Windows, float read-back and GL
// error checks come from PlumeTestSupport (Testing/Support).
#ifndef plumeSheetTestUtil_h
#define plumeSheetTestUtil_h

#include "plumeTestSupport.h"

#include "vtkPlumeSheetMapper.h"
#include "vtkPlumeSheetReference.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <cstdlib>
#include <string>

namespace sheettest
{
using plume::test::FloatImage;

struct Scene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkPlumeSheetMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkActor> Ball; // see AddOpaqueSphere

  Scene(vtkPolyData* mesh, int w, int h)
  {
    this->Window = plume::test::MakeOffscreenWindow(w, h);
    this->Renderer->SetBackground(1, 1, 1);
    this->Window->AddRenderer(this->Renderer);
    this->Mapper->SetInputData(mesh);
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
  }

  /**
   * Adds an opaque sphere, drawn before the sheet (the sheet integrates up to
   * the depth of the opaque actors drawn before it). Returns the sphere's actor.
   */
  vtkActor* AddOpaqueSphere(double cx, double cy, double cz, double radius, double r, double g, double b)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(cx, cy, cz);
    sphere->SetRadius(radius);
    sphere->SetThetaResolution(48);
    sphere->SetPhiResolution(24);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    this->Ball->SetMapper(mapper);
    this->Ball->GetProperty()->SetColor(r, g, b);
    this->Renderer->RemoveActor(this->Actor);
    this->Renderer->AddActor(this->Ball);
    this->Renderer->AddActor(this->Actor);
    return this->Ball;
  }

  void Camera(double px, double py, double pz, double fx, double fy, double fz, double angle = 30)
  {
    vtkCamera* cam = this->Renderer->GetActiveCamera();
    cam->SetPosition(px, py, pz);
    cam->SetFocalPoint(fx, fy, fz);
    cam->SetViewUp(0, 1, 0);
    cam->SetViewAngle(angle);
  }
};

/** The reference configured like the mapper (same arrays, constants and modes). */
inline void Configure(vtkPlumeSheetReference* ref, vtkPlumeSheetMapper* m, vtkPolyData* mesh)
{
  ref->SetInputData(mesh);
  ref->SetDensityArrayName(m->GetDensityArrayName());
  ref->SetDensity(m->GetDensity());
  ref->SetDensityScale(m->GetDensityScale());
  ref->SetBlurArrayName(m->GetBlurArrayName());
  ref->SetBlurRadius(m->GetBlurRadius());
  ref->SetThicknessArrayName(m->GetThicknessArrayName());
  ref->SetThickness(m->GetThickness());
  ref->SetAbsorptionArrayName(m->GetAbsorptionArrayName());
  ref->SetThinSheet(m->GetThinSheet());
  ref->SetBoundedByDepth(m->GetBoundedByDepth());
  ref->SetMinimumSigmaPixels(m->GetMinimumSigmaPixels());
}

struct Result
{
  double RMS = 0;   // of the transmittance error, as a fraction of the reference's dynamic range
  double Max = 0;
  double Range = 0; // the reference's dynamic range (max T - min T)
  bool Finite = true;
  std::string GLErrors;
};

/**
 * Render without the sheet (base: opaque scene, white background), then with
 * it; the reference's T times the base colour is what the frame must show.
 * Errors over every pixel and channel, relative to the dynamic range of T.
 */
inline Result CompareWithReference(Scene& s, vtkPolyData* mesh, const std::string& name,
  vtkPlumeSheetReference* refIn = nullptr)
{
  Result r;
  // one clipping range (from every visible prop) for both renders and the reference
  s.Renderer->ResetCameraClippingRange();
  s.Actor->SetVisibility(false);
  const FloatImage base = plume::test::ReadBack(s.Window);
  s.Actor->SetVisibility(true);
  const auto t0 = std::chrono::steady_clock::now();
  const FloatImage img = plume::test::ReadBack(s.Window);
  const double gpu = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.Finite = !plume::test::HasNonFinite(img);
  r.GLErrors = plume::test::GLErrors(s.Window);
  vtkNew<vtkPlumeSheetReference> own;
  vtkPlumeSheetReference* ref = refIn ? refIn : own.Get();
  Configure(ref, s.Mapper, mesh);
  ref->SetModelMatrix(s.Actor->GetIsIdentity() ? nullptr : s.Actor->GetMatrix());
  const auto t1 = std::chrono::steady_clock::now();
  ref->Compute(s.Renderer, base.Depth.data());
  const double cpu = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  const std::vector<double>& T = ref->GetTransmittance();
  double lo = 1e300, hi = -1e300;
  for (double t : T)
  {
    if (std::isfinite(t))
    {
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
  }
  r.Range = hi - lo;
  double sum = 0, worst = 0;
  int wx = -1, wy = -1, wc = -1;
  size_t n = 0;
  for (int y = 0; y < img.Height; ++y)
  {
    for (int x = 0; x < img.Width; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        const double t = T[3 * (static_cast<size_t>(y) * img.Width + x) + c];
        if (!std::isfinite(t))
        {
          continue;
        }
        const double expected = base.Pixel(x, y)[c] * t;
        const double e = std::fabs(img.Pixel(x, y)[c] - expected);
        sum += e * e;
        if (e > worst)
        {
          worst = e;
          wx = x;
          wy = y;
          wc = c;
        }
        ++n;
      }
    }
  }
  const double range = std::max(r.Range, 1e-12);
  r.RMS = n ? std::sqrt(sum / n) / range : 0;
  r.Max = worst / range;
  std::printf("%-28s T range %.3f  RMS %.4f  max %.4f  (gpu %.3f s, reference %.2f s)\n",
    name.c_str(), r.Range, r.RMS, r.Max, gpu, cpu);
  if (wx >= 0)
  {
    std::printf("%-28s worst at (%d, %d) channel %d: rendered %.4f, expected %.4f\n", "", wx, wy,
      wc, img.Pixel(wx, wy)[wc], base.Pixel(wx, wy)[wc] * T[3 * (static_cast<size_t>(wy) * img.Width + wx) + wc]);
    if (std::getenv("PLUME_SHEET_DEBUG"))
    {
      for (int y = std::min(img.Height - 1, wy + 3); y >= std::max(0, wy - 3); --y)
      {
        for (int x = std::max(0, wx - 3); x <= std::min(img.Width - 1, wx + 3); ++x)
        {
          std::printf(" %.3f/%.3f", img.Pixel(x, y)[wc], T[3 * (static_cast<size_t>(y) * img.Width + x) + wc]);
        }
        std::printf("\n");
      }
    }
  }
  return r;
}

/** CompareWithReference with the reference at every `stride`-th pixel along x and y only. */
inline Result CompareWithReference(Scene& s, int stride, vtkPolyData* mesh, const std::string& name)
{
  vtkNew<vtkPlumeSheetReference> ref;
  ref->SetPixelStride(stride);
  return CompareWithReference(s, mesh, name, ref);
}

/** The accuracy goal of issue 4: RMS <= 1 %, max <= 5 % of the reference's dynamic range. */
inline int CheckGoal(const Result& r, const std::string& name, double rms = 0.01, double max = 0.05)
{
  int failures = 0;
  if (!r.Finite || !r.GLErrors.empty() || !(r.RMS <= rms) || !(r.Max <= max) || !(r.Range > 0.05))
  {
    std::cerr << name << ": FAILED (RMS " << r.RMS << " > " << rms << " or max " << r.Max << " > "
              << max << ", range " << r.Range << ", finite " << r.Finite << ", GL '" << r.GLErrors
              << "')\n";
    ++failures;
  }
  return failures;
}

inline void UseThreads()
{
  vtkSMPTools::SetBackend("STDThread");
}
}

#endif
