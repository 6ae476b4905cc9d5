// Sources given as points (input port 2):
//  1. mass: four points with per-point rate, radius and temperature arrays
//     in a closed box with a buoyant flow and conserve_mass: every step the
//     smoke mass Σ density · cell volume (summed here) grows by exactly
//     Σ rate · dt of the points inside the fluid (one outside the domain and
//     one inside an obstacle emit nothing), to round-off;
//  2. place: with no flow, a point source of radius 0 puts all its mass in
//     the cell holding the point (the density peak is there, its value is
//     rate · t / cell volume) and sets that cell's temperature; one with a
//     radius spreads it evenly over the cells within the radius, centred on
//     the point;
//  3. velocity injection: a 2D point with a velocity array drives the flow
//     along that direction at the point;
//  4. through the pipeline (SetSourcePointsData, a time request) as through Step();
//  5. bad arrays and values are one error naming the point and the value.
#include "vtkPlumeSmokeSolver.h"

#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "plumeSolverTestUtilities.h"

#include <algorithm>
#include <array>
#include <string>

using namespace plume_solver_test;

namespace
{
vtkSmartPointer<vtkPolyData> Points(const std::vector<std::array<double, 3>>& xs)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  for (const auto& x : xs)
  {
    points->InsertNextPoint(x.data());
  }
  pd->SetPoints(points);
  return pd;
}

void AddArray(vtkPolyData* pd, const char* name, int components, const std::vector<double>& values)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(vtkIdType(values.size()) / components);
  for (size_t v = 0; v < values.size(); ++v)
  {
    a->SetValue(vtkIdType(v), values[v]);
  }
  pd->GetPointData()->AddArray(a);
}

double Mass(vtkPlumeSmokeSolver* s)
{
  const int* n = s->GetDimensions();
  const double* h = s->GetSpacing();
  const double* d = s->GetDensityData();
  double sum = 0;
  for (size_t c = 0; c < size_t(n[0]) * n[1] * n[2]; ++c)
  {
    sum += d[c];
  }
  return sum * h[0] * h[1] * h[2];
}
}

int TestSmokeSolverPointSources(int, char*[])
{
  const double zero[3] = { 0, 0, 0 };
  // 1. mass injected per step = Σ rate · dt, in a moving, closed flow
  {
    vtkNew<vtkPlumeSmokeSolver> s;
    s->SetDimensions(16, 16, 20);
    s->SetSpacing(0.05, 0.05, 0.05);
    s->SetTimeStep(0.03);
    s->SetBuoyancy(2.0);
    s->SetAdvectionScheme(vtkPlumeSmokeSolver::MACCORMACK);
    s->ConserveMassOn();
    const double sphere[3] = { 0.55, 0.4, 0.7 };
    s->AddObstacleSphere(sphere, 0.15);
    // points: three inside the fluid, one outside the domain, one inside the obstacle
    auto points = Points({ { 0.2, 0.3, 0.1 }, { 0.5, 0.5, 0.2 }, { 0.6, 0.25, 0.35 }, { -0.5, 0.3, 0.2 },
      { 0.55, 0.4, 0.7 } });
    AddArray(points, "rate", 1, { 0.3, 0.7, 1.1, 5.0, 9.0 });
    AddArray(points, "radius", 1, { 0.0, 0.08, 0.12, 0.1, 0.05 });
    AddArray(points, "temperature", 1, { 1.0, 2.0, 0.5, 1.0, 1.0 });
    s->SetSourcePointsData(points);
    const double expected = (0.3 + 0.7 + 1.1) * 0.03;
    double previous = 0, worst = 0, maxSpeed = 0;
    for (int step = 1; step <= 25; ++step)
    {
      PLUME_CHECK(s->Step(), s->GetLastError());
      const double mass = Mass(s);
      worst = std::max(worst, std::abs(mass - previous - expected));
      PLUME_CHECK(std::abs(s->GetLastInjectedMass() - expected) <= 1e-15, s->GetLastInjectedMass());
      previous = mass;
      for (int d = 0; d < 3; ++d)
      {
        const double* u = s->GetFaceVelocityData(d);
        const int* n = s->GetDimensions();
        const size_t count = size_t(n[0] + (d == 0)) * (n[1] + (d == 1)) * (n[2] + (d == 2));
        for (size_t f = 0; f < count; ++f)
        {
          maxSpeed = std::max(maxSpeed, std::abs(u[f]));
        }
      }
    }
    std::cout << "point sources: mass after 25 steps " << previous << " (expected " << 25 * expected
              << "), worst per-step error " << worst << ", max speed " << maxSpeed << "\n";
    PLUME_CHECK(worst <= 1e-12 * 25 * expected, "per-step mass error " << worst);
    PLUME_CHECK(std::abs(previous - 25 * expected) <= 1e-12 * 25 * expected, previous);
    PLUME_CHECK(maxSpeed > 0.1, "the flow must move for this to test conservation, max speed " << maxSpeed);
    // the point at (0.5, 0.5, 0.2) sets temperature 2 in its cell (10, 10, 4)
    PLUME_CHECK(s->GetTemperatureData()[10 + 16 * (10 + 16 * 4)] == 2.0, s->GetTemperatureData()[10 + 16 * (10 + 16 * 4)]);
  }

  // 2. place: no flow (no buoyancy, no smoke weight)
  {
    vtkNew<vtkPlumeSmokeSolver> s;
    s->SetDimensions(24, 20, 16);
    s->SetSpacing(0.05, 0.05, 0.05);
    s->SetTimeStep(0.02);
    s->SetBuoyancy(0);
    s->SetSmokeWeight(0);
    s->SetSourceRate(2.0);
    s->SetSourceTemperature(3.0);
    auto points = Points({ { 0.37, 0.61, 0.29 } }); // cell (7.4, 12.2, 5.8) -> (7, 12, 6)
    s->SetSourcePointsData(points);
    for (int step = 0; step < 5; ++step)
    {
      PLUME_CHECK(s->Step(), s->GetLastError());
    }
    double* d = s->GetDensityData();
    const size_t count = 24 * 20 * 16;
    const size_t peak = std::max_element(d, d + count) - d;
    const size_t home = 7 + 24 * (12 + 20 * 6);
    PLUME_CHECK(peak == home, "density peak at cell " << peak << ", expected " << home);
    const double value = 5 * 0.02 * 2.0 / (0.05 * 0.05 * 0.05);
    PLUME_CHECK(std::abs(d[home] - value) <= 1e-12 * value, d[home] << " vs " << value);
    PLUME_CHECK(s->GetTemperatureData()[home] == 3.0, s->GetTemperatureData()[home]);
    // elsewhere only round-off of the back-trace at zero velocity
    size_t nonzero = 0;
    for (size_t c = 0; c < count; ++c)
    {
      nonzero += d[c] > 1e-12 * value;
    }
    PLUME_CHECK(nonzero == 1, nonzero << " cells hold smoke, expected 1");

    // a radius of 0.12 (2.4 cells): every cell within it gets the same share, centred on the point
    s->SetSourceRadius(0.12);
    s->Reset();
    PLUME_CHECK(s->Step(), s->GetLastError());
    d = s->GetDensityData(); // the step swapped the buffers
    double cx = 0, cy = 0, cz = 0, sum = 0, first = -1;
    bool even = true, inside = true;
    for (int k = 0; k < 16; ++k)
      for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 24; ++i)
        {
          const double v = d[i + 24 * (j + 20 * k)];
          if (v <= 1e-9)
          {
            continue;
          }
          const double x = 0.05 * i, y = 0.05 * j, z = 0.05 * k;
          const double r = std::sqrt((x - 0.37) * (x - 0.37) + (y - 0.61) * (y - 0.61) + (z - 0.29) * (z - 0.29));
          inside = inside && r <= 0.12 + 1e-12;
          even = even && (first < 0 || v == first);
          first = v;
          cx += v * x;
          cy += v * y;
          cz += v * z;
          sum += v;
        }
    cx /= sum;
    cy /= sum;
    cz /= sum;
    std::cout << "point source of radius 0.12: centroid " << cx << " " << cy << " " << cz << "\n";
    PLUME_CHECK(inside && even, "smoke outside the radius or unevenly spread");
    PLUME_CHECK(std::abs(cx - 0.37) < 0.01 && std::abs(cy - 0.61) < 0.01 && std::abs(cz - 0.29) < 0.01,
      "centroid " << cx << " " << cy << " " << cz << " vs 0.37 0.61 0.29");
    PLUME_CHECK(std::abs(sum * 0.05 * 0.05 * 0.05 - 0.02 * 2.0) < 1e-14, sum);
  }

  // 3. velocity injection (2D)
  {
    vtkNew<vtkPlumeSmokeSolver> s;
    s->SetDimensions(32, 32, 1);
    s->SetSpacing(1.0 / 32, 1.0 / 32, 1.0 / 32);
    s->SetTimeStep(0.02);
    s->SetBuoyancy(0);
    s->SetSmokeWeight(0);
    s->SetOpenFaces("xmax,ymax");
    auto points = Points({ { 0.4, 0.45, 7.0 } }); // z ignored in 2D
    AddArray(points, "velocity", 3, { 1.0, 0.5, 0.0 });
    AddArray(points, "radius", 1, { 0.08 });
    s->SetSourcePointsData(points);
    PLUME_CHECK(s->Step(), s->GetLastError());
    vtkImageData* out = nullptr;
    s->Update();
    out = s->GetOutput();
    double u[3];
    const int i = int(std::lround(0.4 * 32)), j = int(std::lround(0.45 * 32));
    out->GetPointData()->GetArray("velocity")->GetTuple(i + 32 * j, u);
    const double speed = std::sqrt(u[0] * u[0] + u[1] * u[1]);
    const double cosine = (u[0] * 1.0 + u[1] * 0.5) / (speed * std::sqrt(1.25));
    std::cout << "velocity at the injecting point: " << u[0] << " " << u[1] << "\n";
    PLUME_CHECK(speed > 0.4 && cosine > 0.98, "velocity " << u[0] << " " << u[1] << " (injected 1, 0.5)");
    PLUME_CHECK(s->GetDensityData()[i + 32 * j] > 0, "no smoke at the point");
  }

  // 4. the pipeline's time request, as explicit steps
  {
    auto points = Points({ { 0.3, 0.3, 0.3 }, { 0.6, 0.5, 0.2 } });
    AddArray(points, "flow", 1, { 0.25, 0.5 });
    vtkNew<vtkPlumeSmokeSolver> a, b;
    for (vtkPlumeSmokeSolver* s : { a.Get(), b.Get() })
    {
      s->SetDimensions(16, 16, 16);
      s->SetSpacing(0.05, 0.05, 0.05);
      s->SetTimeStep(0.05);
      s->SetSourceRateArrayName("flow");
      s->ConserveMassOn();
      s->SetSourcePointsData(points);
    }
    a->UpdateTimeStep(0.5);
    for (int step = 0; step < 10; ++step)
    {
      PLUME_CHECK(b->Step(), b->GetLastError());
    }
    const double* da = a->GetDensityData();
    const double* db = b->GetDensityData();
    PLUME_CHECK(a->GetCurrentStep() == 10 && std::equal(da, da + 16 * 16 * 16, db), "pipeline and steps differ");
    PLUME_CHECK(std::abs(Mass(a) - 10 * 0.05 * 0.75) < 1e-12, Mass(a));
  }

  // 5. bad input: one clear error naming the point and the value
  {
    auto check = [&](vtkPolyData* points, const std::string& expect) {
      vtkNew<vtkPlumeSmokeSolver> s;
      s->SetDimensions(8, 8, 8);
      s->SetSourcePointsData(points);
      const bool ok = s->Step();
      const std::string error = s->GetLastError();
      PLUME_CHECK(!ok && error.find(expect) != std::string::npos, "error '" << error << "', expected '" << expect << "'");
    };
    auto negative = Points({ { 0.1, 0.1, 0.1 }, { 0.05, 0.05, 0.05 } });
    AddArray(negative, "rate", 1, { 1.0, -0.5 });
    check(negative, "source point 1 has a negative rate (-0.5)");
    auto nan = Points({ { 0.1, 0.1, 0.1 } });
    AddArray(nan, "radius", 1, { std::nan("") });
    check(nan, "source point 0 has a non-finite value");
    auto flat = Points({ { 0.1, 0.1, 0.1 } });
    AddArray(flat, "velocity", 2, { 1.0, 0.0 });
    check(flat, "the velocity array 'velocity' has 2 components, expected 3");
    (void)zero;
  }
  return Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
