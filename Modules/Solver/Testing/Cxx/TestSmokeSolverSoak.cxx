// Long run (label soak): 10 000 steps (PLUME_SOLVER_SOAK_STEPS to change) of
// a hot, smoky blob in a closed 12 x 12 x 16 box with a spherical obstacle,
// MacCormack advection (PLUME_SOLVER_SOAK_SCHEME=0: semi-Lagrangian) at
// CFL > 1 (time step 0.1 s, h = 0.05), conserve_mass on, no sources and no
// dissipation. Checked every step:
//  - every face velocity finite, the kinetic energy (below);
// every 100 steps:
//  - density and temperature finite;
//  - density within its initial range [0, 1] and temperature within [0, 2]
//    (advection only interpolates, MacCormack is clamped);
//  - (every step) kinetic energy below what buoyancy can release: each parcel's
//    (buoyancy·(T − T0) + smoke_weight·density)·height of the box, summed at
//    the start (the only energy source in a closed box);
//  - the relative divergence after each projection below 1e-5;
// and at the end the smoke's mass within 1e-9 of the start (conserve_mass;
// without it, PLUME_SOLVER_SOAK_CONSERVE=0, the drift is printed, not checked).
#include "vtkPlumeSmokeSolver.h"

#include "vtkPlumePressureSolver.h"

#include "plumeSolverTestUtilities.h"

#include <cstdlib>

using namespace plume_solver_test;

int TestSmokeSolverSoak(int, char*[])
{
  int steps = 10000;
  if (const char* env = std::getenv("PLUME_SOLVER_SOAK_STEPS"))
  {
    steps = std::max(1, std::atoi(env));
  }
  const int n[3] = { 12, 12, 16 };
  const double h = 0.05;
  vtkNew<vtkPlumeSmokeSolver> solver;
  solver->SetDimensions(n[0], n[1], n[2]);
  solver->SetSpacing(h, h, h);
  solver->SetOrigin(0.5 * h, 0.5 * h, 0.5 * h);
  solver->SetTimeStep(0.1);
  solver->SetAdvectionScheme(vtkPlumeSmokeSolver::MACCORMACK);
  if (const char* env = std::getenv("PLUME_SOLVER_SOAK_SCHEME"))
  {
    solver->SetAdvectionScheme(std::atoi(env));
  }
  const double buoyancy = 6.0;
  solver->SetBuoyancy(buoyancy);
  solver->SetSmokeWeight(0.5);
  const bool conserve = !std::getenv("PLUME_SOLVER_SOAK_CONSERVE") || std::atoi(std::getenv("PLUME_SOLVER_SOAK_CONSERVE"));
  solver->SetConserveMass(conserve);
  const double obstacle[3] = { 0.35, 0.3, 0.5 };
  solver->AddObstacleSphere(obstacle, 0.1);
  PLUME_CHECK(solver->Initialize(), solver->GetLastError());
  const size_t cells = size_t(n[0]) * n[1] * n[2];
  const unsigned char* solid = solver->GetSolidData();
  double* density = solver->GetDensityData();
  double* temperature = solver->GetTemperatureData();
  double budget = 0, mass0 = 0;
  const double height = n[2] * h, volume = h * h * h;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
      {
        const size_t c = i + size_t(n[0]) * (j + size_t(n[1]) * k);
        const double x = (i + 0.5) * h - 0.25, y = (j + 0.5) * h - 0.35, z = (k + 0.5) * h - 0.2;
        const double blob = std::exp(-(x * x + y * y + z * z) / (0.1 * 0.1));
        if (!solid[c])
        {
          density[c] = blob;
          temperature[c] = 2.0 * blob;
        }
        budget += (buoyancy * std::abs(temperature[c]) + 0.5 * density[c]) * height * volume;
        mass0 += density[c];
      }
  double maxEnergy = 0, maxSpeed = 0, maxDivergence = 0;
  double minDensity = 0, maxDensity = 0, minT = 0, maxT = 0;
  bool finite = true;
  std::vector<double> div(cells);
  for (int s = 1; s <= steps && finite; ++s)
  {
    if (!solver->Step())
    {
      PLUME_CHECK(false, "step " << s << ": " << solver->GetLastError());
      break;
    }
    double energy = 0, speed = 0;
    for (int d = 0; d < 3; ++d)
    {
      const size_t faces = cells / n[d] * (n[d] + 1);
      const double* u = solver->GetFaceVelocityData(d);
      for (size_t f = 0; f < faces; ++f)
      {
        finite = finite && std::isfinite(u[f]);
        energy += 0.5 * u[f] * u[f] * volume;
        speed = std::max(speed, std::abs(u[f]));
      }
    }
    maxEnergy = std::max(maxEnergy, energy);
    maxSpeed = std::max(maxSpeed, speed);
    PLUME_CHECK(finite, "step " << s << ": a non-finite velocity");
    PLUME_CHECK(energy <= budget, "step " << s << ": kinetic energy " << energy << " above the budget " << budget);
    if (s % 100 != 0 && s != steps)
    {
      continue;
    }
    density = solver->GetDensityData();
    temperature = solver->GetTemperatureData();
    for (size_t c = 0; c < cells; ++c)
    {
      finite = finite && std::isfinite(density[c]) && std::isfinite(temperature[c]);
      minDensity = std::min(minDensity, density[c]);
      maxDensity = std::max(maxDensity, density[c]);
      minT = std::min(minT, temperature[c]);
      maxT = std::max(maxT, temperature[c]);
    }
    solver->ComputeDivergence(div.data());
    maxDivergence = std::max(maxDivergence, MaxAbs(div) * h / std::max(speed, 1e-300));
    PLUME_CHECK(finite, "step " << s << ": a non-finite value");
  }
  double mass = 0;
  for (size_t c = 0; c < cells; ++c)
  {
    mass += solver->GetDensityData()[c];
  }
  const double drift = (mass - mass0) / mass0;
  std::cout << "soak: " << solver->GetCurrentStep() << " steps, max CFL " << maxSpeed * 0.1 / h
            << ", max kinetic energy " << maxEnergy << " (budget " << budget << "), density [" << minDensity
            << ", " << maxDensity << "], temperature [" << minT << ", " << maxT << "], max relative divergence "
            << maxDivergence << ", mass drift " << 100 * drift << " %, last PCG iterations "
            << solver->GetPressureSolver()->GetLastIterations() << "\n";
  PLUME_CHECK(solver->GetCurrentStep() == steps, "stopped at step " << solver->GetCurrentStep());
  PLUME_CHECK(maxSpeed * 0.1 / h > 1, "the run never reached CFL 1: " << maxSpeed * 0.1 / h);
  PLUME_CHECK(minDensity >= 0 && maxDensity <= 1, "density left [0, 1]: " << minDensity << " .. " << maxDensity);
  PLUME_CHECK(minT >= 0 && maxT <= 2, "temperature left [0, 2]: " << minT << " .. " << maxT);
  PLUME_CHECK(maxDivergence < 1e-5, "relative divergence " << maxDivergence);
  PLUME_CHECK(!conserve || std::abs(drift) < 1e-9, "mass drifted by " << 100 * drift << " %");
  return Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
