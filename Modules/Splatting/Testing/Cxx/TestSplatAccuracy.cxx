// Both backends against the double-precision reference (no cutoff): max and
// RMS error in every mode, the two backends agree to float rounding, the CPU
// result is bit-identical for 1 and 2 threads, voxel-integrated splats keep
// their mass, and the error falls with the cutoff factor k as exp(-k²/2).
#include "plumeSplatTestUtil.h"

#include "vtkSMPTools.h"

#include <cstdio>

namespace
{
const char* ModeName(int mode)
{
  return mode == vtkPlumeGaussianSplatter::VECTOR_SUM ? "vector" : mode == vtkPlumeGaussianSplatter::SCALAR_SUM ? "scalar" : "distance";
}
}

int TestSplatAccuracy(int, char*[])
{
  int failures = 0;
  auto points = splattest::RandomPoints(120, -0.8, 0.8, 0.03, 0.2);

  vtkNew<vtkPlumeGaussianSplatter> splatter;
  splatter->SetInputData(points);
  splatter->SetDimensions(24, 22, 20); // not a cube: catches swapped axes
  splatter->SetModelBounds(-1, 1, -1.1, 0.9, -0.9, 1.0);
  splatter->SetRadiusArrayName("sigma");
  splatter->SetScalarArrayName("s");
  vtkNew<vtkPlumeSplatReference> reference;

  for (int mode : { vtkPlumeGaussianSplatter::VECTOR_SUM, vtkPlumeGaussianSplatter::SCALAR_SUM,
         vtkPlumeGaussianSplatter::DISTANCE_MAX })
  {
    for (bool integrate : { true, false })
    {
      if (mode == vtkPlumeGaussianSplatter::DISTANCE_MAX && !integrate)
      {
        continue; // distance mode is always point-sampled
      }
      splatter->SetMode(mode);
      splatter->SetIntegrateOverVoxel(integrate);
      splatter->SetBackend(vtkPlumeGaussianSplatter::BACKEND_CPU);
      splatter->Update();
      vtkNew<vtkImageData> cpu;
      cpu->DeepCopy(splatter->GetOutput());
      PLUME_CHECK(splatter->GetLastBackend() == vtkPlumeGaussianSplatter::BACKEND_CPU);
      reference->Configure(splatter);
      PLUME_CHECK(reference->GetNumberOfSplats() == 120);
      auto exact = reference->Compute();
      const splattest::Error ec = splattest::Against(splatter, exact);

      splatter->SetBackend(vtkPlumeGaussianSplatter::BACKEND_GPU);
      splatter->Update();
      PLUME_CHECK(splatter->GetLastBackend() == vtkPlumeGaussianSplatter::BACKEND_GPU);
      const splattest::Error eg = splattest::Against(splatter, exact);
      const double agree = splattest::Difference(cpu, splatter->GetOutput());
      std::printf("%s integrate=%d: peak %.4g  CPU max %.3g rms %.3g  GPU max %.3g rms %.3g  (relative max %.2e / %.2e)  "
                  "CPU-GPU %.3g (%.2e)\n",
        ModeName(mode), int(integrate), ec.Peak, ec.Max, ec.RMS, eg.Max, eg.RMS, ec.Max / ec.Peak, eg.Max / eg.Peak,
        agree, agree / ec.Peak);
      PLUME_CHECK(ec.Peak > 0 && ec.Finite && eg.Finite);
      // k = 4: the cut-off tails cost at most ~exp(-8) = 3.4e-4 of a splat's peak
      PLUME_CHECK(ec.Max <= 1e-3 * ec.Peak);
      PLUME_CHECK(eg.Max <= 1e-3 * eg.Peak);
      PLUME_CHECK(ec.RMS <= 1e-4 * ec.Peak);
      PLUME_CHECK(eg.RMS <= 1e-4 * eg.Peak);
      PLUME_CHECK(agree <= 2e-6 * ec.Peak); // float rounding (summation order) only
    }
  }

  // CPU: bit-identical whatever the thread count
  splatter->SetMode(vtkPlumeGaussianSplatter::VECTOR_SUM);
  splatter->SetIntegrateOverVoxel(true);
  splatter->SetBackend(vtkPlumeGaussianSplatter::BACKEND_CPU);
  vtkSMPTools::SetBackend("Sequential");
  splatter->Modified();
  splatter->Update();
  vtkNew<vtkImageData> sequential;
  sequential->DeepCopy(splatter->GetOutput());
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(3);
  splatter->Modified();
  splatter->Update();
  PLUME_CHECK(splattest::Difference(sequential, splatter->GetOutput()) == 0.0);

  // mass: voxel-integrated splats sum to their value, even far below one voxel
  {
    splatter->SetMode(vtkPlumeGaussianSplatter::SCALAR_SUM);
    splatter->SetRadiusArrayName("");
    for (double sigma : { 0.002, 0.05 })
    {
      splatter->SetRadius(sigma);
      for (int backend : { vtkPlumeGaussianSplatter::BACKEND_CPU, vtkPlumeGaussianSplatter::BACKEND_GPU })
      {
        splatter->SetBackend(backend);
        splatter->Update();
        double h[3];
        splatter->GetOutput()->GetSpacing(h);
        const double mass = splattest::Total(splatter->GetOutput()) * h[0] * h[1] * h[2];
        double expected = 0;
        for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
        {
          expected += points->GetPointData()->GetScalars()->GetComponent(i, 0);
        }
        std::printf("mass sigma=%g backend=%d: %.8g expected %.8g\n", sigma, backend, mass, expected);
        PLUME_CHECK(std::fabs(mass - expected) <= 1e-4 * expected);
      }
    }
    // point sampling loses mass when sigma is far below a voxel (documented)
    splatter->SetIntegrateOverVoxel(false);
    splatter->SetRadius(0.002);
    splatter->SetBackend(vtkPlumeGaussianSplatter::BACKEND_CPU);
    splatter->Update();
    double h[3];
    splatter->GetOutput()->GetSpacing(h);
    const double sampled = splattest::Total(splatter->GetOutput()) * h[0] * h[1] * h[2];
    std::printf("mass sigma=0.002 point-sampled: %.6g\n", sampled);
    splatter->SetIntegrateOverVoxel(true);
  }

  // error against k: falls like exp(-k²/2) (relative to the peak)
  {
    splatter->SetMode(vtkPlumeGaussianSplatter::VECTOR_SUM);
    splatter->SetRadiusArrayName("sigma");
    splatter->SetBackend(vtkPlumeGaussianSplatter::BACKEND_CPU);
    double previous = HUGE_VAL;
    for (double k : { 2.0, 3.0, 4.0, 5.0, 6.0 })
    {
      splatter->SetCutoffFactor(k);
      splatter->Update();
      reference->Configure(splatter);
      auto exact = reference->Compute();
      const splattest::Error e = splattest::Against(splatter, exact);
      std::printf("k=%g: max %.3e rms %.3e (relative to peak), exp(-k^2/2) = %.3e\n", k, e.Max / e.Peak,
        e.RMS / e.Peak, std::exp(-0.5 * k * k));
      PLUME_CHECK(e.Max < previous || e.Max <= 1e-6 * e.Peak);
      PLUME_CHECK(e.Max <= 2 * std::exp(-0.5 * k * k) * e.Peak + 1e-6 * e.Peak);
      previous = e.Max;
    }
    splatter->SetCutoffFactor(4);
  }
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
