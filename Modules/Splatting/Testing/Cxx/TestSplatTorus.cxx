// Seed 002's torus: a closed circular polyline splats its forward differences
// into a toroidal velocity field. Point-sampled, the field of N chords of a
// circle of radius R is, to within the k = 4 cutoff error, the analytic
// continuous line integral ∫ t(θ) G_σ(x − p(θ)) R dθ = t(φ + π/N) ·
// R e^{-((ρ−R)² + z²)/2σ²} · [e^{−b} I1(b)] / (√(2π) σ³) with b = ρR/σ²,
// scaled by the chord factor sin(π/N)/(π/N) and turned by π/N (each vertex
// carries the chord to its successor). So the field is tangent to the circle
// up to the angle π/N, and its magnitude matches the analytic value.
#include "plumeSplatTestUtil.h"

#include "vtkCellArray.h"
#include "vtkMath.h"

#include <cmath>
#include <cstdio>

int TestSplatTorus(int, char*[])
{
  int failures = 0;
  const int N = 256;
  const double R = 1.0, sigma = 0.15, cx = 0.1, cy = -0.05, cz = 0.02; // off-centre: catches origin mix-ups
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  cells->InsertNextCell(N + 1);
  for (int i = 0; i < N; ++i)
  {
    const double t = 2 * vtkMath::Pi() * i / N;
    cells->InsertCellPoint(pts->InsertNextPoint(cx + R * std::cos(t), cy + R * std::sin(t), cz));
  }
  cells->InsertCellPoint(0); // closed loop: last id = first
  vtkNew<vtkPolyData> circle;
  circle->SetPoints(pts);
  circle->SetLines(cells);

  vtkNew<vtkPlumeGaussianSplatter> splatter;
  splatter->SetLinesData(circle);
  splatter->SetRadius(sigma);
  splatter->SetIntegrateOverVoxel(false);
  splatter->SetDimensions(40, 40, 12);
  splatter->SetModelBounds(cx - 1.5, cx + 1.5, cy - 1.5, cy + 1.5, cz - 0.5, cz + 0.5);
  const double chord = std::sin(vtkMath::Pi() / N) / (vtkMath::Pi() / N);
  const double turn = vtkMath::Pi() / N;

  for (int backend : { vtkPlumeGaussianSplatter::BACKEND_CPU, vtkPlumeGaussianSplatter::BACKEND_GPU })
  {
    splatter->SetBackend(backend);
    splatter->Update();
    vtkImageData* out = splatter->GetOutput();
    vtkDataArray* v = out->GetPointData()->GetVectors();
    PLUME_CHECK(v && std::string(v->GetName()) == "velocity");
    PLUME_CHECK(splatter->GetSplatCount() == N);
    double maxErr = 0, peak = 0, maxAngle = 0;
    for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
    {
      double x[3], got[3];
      out->GetPoint(id, x);
      v->GetTuple(id, got);
      const double dx = x[0] - cx, dy = x[1] - cy, z = x[2] - cz;
      const double rho = std::sqrt(dx * dx + dy * dy);
      double expected[3] = { 0, 0, 0 };
      if (rho > 1e-9)
      {
        const double b = rho * R / (sigma * sigma);
        const double mag = chord * R * std::exp(-((rho - R) * (rho - R) + z * z) / (2 * sigma * sigma)) *
          std::cyl_bessel_i(1.0, b) * std::exp(-b) / (std::sqrt(2 * vtkMath::Pi()) * sigma * sigma * sigma);
        const double phi = std::atan2(dy, dx) + turn;
        expected[0] = -std::sin(phi) * mag;
        expected[1] = std::cos(phi) * mag;
        peak = std::max(peak, mag);
      }
      for (int c = 0; c < 3; ++c)
      {
        maxErr = std::max(maxErr, std::fabs(got[c] - expected[c]));
      }
      const double speed = vtkMath::Norm(got);
      if (speed > 0.1 * 1.0 / (2 * vtkMath::Pi() * sigma * sigma))
      {
        // angle between the field and the circle's tangent at this point
        const double tangent[3] = { -dy / rho, dx / rho, 0 };
        const double cosA = std::min(1.0, std::fabs(vtkMath::Dot(got, tangent)) / speed);
        maxAngle = std::max(maxAngle, std::acos(cosA));
      }
    }
    const double lineDensity = 1.0 / (2 * vtkMath::Pi() * sigma * sigma); // straight-line limit on the line
    std::printf("backend %d: peak %.5g (straight-line limit %.5g), max error %.3g (%.2e of peak), max angle to "
                "tangent %.4f rad (pi/N = %.4f)\n",
      splatter->GetLastBackend(), peak, lineDensity, maxErr, maxErr / peak, maxAngle, turn);
    PLUME_CHECK(splatter->GetLastBackend() == backend);
    PLUME_CHECK(peak > 0.9 * lineDensity && peak < 1.1 * lineDensity);
    PLUME_CHECK(maxErr <= 1e-3 * peak); // the k = 4 cutoff bound (3.4e-4 per splat, a few splats overlap)
    PLUME_CHECK(maxAngle <= turn + 2e-3);
  }

  // Without the closing id the loop is open: the last vertex has no successor
  // and uses the backward difference; a wrap to the first vertex is missing.
  // The field then differs near the gap only.
  {
    vtkNew<vtkCellArray> open;
    open->InsertNextCell(N);
    for (int i = 0; i < N; ++i)
    {
      open->InsertCellPoint(i);
    }
    circle->SetLines(open);
    splatter->SetBackend(vtkPlumeGaussianSplatter::BACKEND_CPU);
    splatter->Update();
    PLUME_CHECK(splatter->GetSplatCount() == N);
  }
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
