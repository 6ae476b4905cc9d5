// Obstacles from polygonal surfaces and moving obstacles:
//  1. a closed sphere surface (vtkSphereSource) voxelised onto the grid: every
//     cell centre more than 0.6 h inside the exact sphere is solid, every one
//     more than 0.6 h outside is fluid (the polygons cut the sphere by less);
//  2. a plume rising into a surface obstacle: no smoke in its cells and no
//     flow through its faces (exactly 0) over 30 steps;
//  3. a sphere moving at v = (1, 0, 0) through fluid at rest (2D, closed
//     box, no buoyancy): its solid cells follow x0 + v t (centroid within
//     half a cell), the faces on its boundary carry v exactly, the fluid at
//     its front and back is dragged along (> 0.6 v, as potential flow's
//     stagnation points move at v), the projected flow is divergence-free,
//     smoke swept by it stays out of its cells; the same sphere at rest
//     leaves the fluid at rest (the drag comes from the boundary condition);
//     a checkpoint of the moving run continues bit for bit;
//  4. bad obstacles: a surface without polygons, a non-finite velocity.
#include "vtkPlumeSmokeSolver.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"

#include "plumeSolverTestUtilities.h"

#include <cstdio>
#include <string>

using namespace plume_solver_test;

int TestSmokeSolverObstacles(int, char*[])
{
  // 1. voxelised sphere surface against the exact sphere
  {
    const int n = 32;
    const double h = 1.0 / n, r = 0.3, c[3] = { 0.52, 0.47, 0.5 };
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(c[0], c[1], c[2]);
    sphere->SetRadius(r);
    sphere->SetThetaResolution(64);
    sphere->SetPhiResolution(64);
    sphere->Update();
    vtkNew<vtkPlumeSmokeSolver> solver;
    solver->SetDimensions(n, n, n);
    solver->SetSpacing(h, h, h);
    solver->SetOrigin(0.5 * h, 0.5 * h, 0.5 * h);
    solver->AddObstacleSurface(sphere->GetOutput());
    PLUME_CHECK(solver->Initialize(), solver->GetLastError());
    const unsigned char* solid = solver->GetSolidData();
    int wrongInside = 0, wrongOutside = 0, solidCount = 0;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
          const double x = (i + 0.5) * h - c[0], y = (j + 0.5) * h - c[1], z = (k + 0.5) * h - c[2];
          const double distance = std::sqrt(x * x + y * y + z * z) - r;
          const bool s = solid[i + n * (j + n * k)] != 0;
          solidCount += s;
          wrongInside += distance < -0.6 * h && !s;
          wrongOutside += distance > 0.6 * h && s;
        }
    std::cout << "surface sphere: " << solidCount << " solid cells (exact volume "
              << 4.0 / 3.0 * 3.14159265358979 * r * r * r / (h * h * h) << "), " << wrongInside
              << " missed inside, " << wrongOutside << " solid outside\n";
    PLUME_CHECK(wrongInside == 0 && wrongOutside == 0,
      wrongInside << " cells inside not solid, " << wrongOutside << " outside solid");
    PLUME_CHECK(solidCount > 3000, "too few solid cells: " << solidCount);
  }

  // 2. a plume under a surface obstacle: no smoke inside, no flow through
  {
    const int n[3] = { 20, 20, 30 };
    const double h = 0.05;
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(0.5, 0.5, 0.9);
    sphere->SetRadius(0.25);
    sphere->SetThetaResolution(32);
    sphere->SetPhiResolution(32);
    sphere->Update();
    vtkNew<vtkPlumeSmokeSolver> solver;
    solver->SetDimensions(n[0], n[1], n[2]);
    solver->SetSpacing(h, h, h);
    solver->SetTimeStep(0.03);
    solver->SetBuoyancy(4);
    solver->SetOpenFaces("zmax");
    const double src[3] = { 0.5, 0.5, 0.2 }, none[3] = { 0, 0, 0 };
    solver->AddSource(src, 0.12, 1.0, 1.0, none);
    solver->AddObstacleSurface(sphere->GetOutput());
    for (int s = 0; s < 30; ++s)
    {
      PLUME_CHECK(solver->Step(), solver->GetLastError());
    }
    const unsigned char* solid = solver->GetSolidData();
    double smokeInside = 0, smokeTotal = 0, through = 0;
    for (int c = 0; c < n[0] * n[1] * n[2]; ++c)
    {
      smokeTotal += solver->GetDensityData()[c];
      if (solid[c])
      {
        smokeInside += std::abs(solver->GetDensityData()[c]);
      }
    }
    for (int d = 0; d < 3; ++d)
    {
      const int m[3] = { n[0] + (d == 0), n[1] + (d == 1), n[2] + (d == 2) };
      const double* u = solver->GetFaceVelocityData(d);
      for (int k = 0; k < m[2]; ++k)
        for (int j = 0; j < m[1]; ++j)
          for (int i = 0; i < m[0]; ++i)
          {
            const int idx[3] = { i, j, k };
            if (idx[d] == 0 || idx[d] == n[d])
            {
              continue;
            }
            int a[3] = { i, j, k };
            --a[d];
            const bool wall = solid[i + n[0] * (j + n[1] * k)] || solid[a[0] + n[0] * (a[1] + n[1] * a[2])];
            if (wall)
            {
              through = std::max(through, std::abs(u[i + size_t(m[0]) * (j + size_t(m[1]) * k)]));
            }
          }
    }
    std::cout << "plume under a surface obstacle: smoke " << smokeTotal << ", inside " << smokeInside
              << ", max |u| through its faces " << through << "\n";
    PLUME_CHECK(smokeTotal > 10, "no smoke: " << smokeTotal);
    PLUME_CHECK(smokeInside == 0, "smoke inside the obstacle: " << smokeInside);
    PLUME_CHECK(through == 0, "flow through the obstacle's faces: " << through);
  }

  // 3. a moving sphere in 2D
  const int nx = 96, ny = 48;
  const double h = 1.0 / 48, r = 0.12, x0 = 0.4, y0 = 0.5, v = 1.0, dt = 0.01;
  auto configure = [&](vtkPlumeSmokeSolver* solver, double speed) {
    solver->SetDimensions(nx, ny, 1);
    solver->SetSpacing(h, h, h);
    solver->SetOrigin(0.5 * h, 0.5 * h, 0);
    solver->SetTimeStep(dt);
    solver->SetBuoyancy(0);
    solver->SetSmokeWeight(0);
    solver->SetPressureTolerance(1e-10);
    const double center[3] = { x0, y0, 0 }, velocity[3] = { speed, 0, 0 };
    solver->AddObstacleSphere(center, r, velocity);
  };
  {
    vtkNew<vtkPlumeSmokeSolver> solver;
    configure(solver, v);
    PLUME_CHECK(solver->Initialize(), solver->GetLastError());
    // smoke everywhere at the start
    for (int c = 0; c < nx * ny; ++c)
    {
      solver->GetDensityData()[c] = solver->GetSolidData()[c] ? 0.0 : 1.0;
    }
    const int steps = 30;
    const std::string checkpoint = "TestSmokeSolverObstacles_moving.bin";
    for (int s = 0; s < steps; ++s)
    {
      PLUME_CHECK(solver->Step(), solver->GetLastError());
      if (s == 19)
      {
        PLUME_CHECK(solver->WriteCheckpoint(checkpoint.c_str()), solver->GetLastError());
      }
    }
    const double t = steps * dt, xc = x0 + v * t;
    const unsigned char* solid = solver->GetSolidData();
    double sx = 0, sy = 0, count = 0, smokeInside = 0;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        if (solid[i + nx * j])
        {
          sx += (i + 0.5) * h;
          sy += (j + 0.5) * h;
          ++count;
          smokeInside += std::abs(solver->GetDensityData()[i + nx * j]);
        }
      }
    sx /= count;
    sy /= count;
    // faces on the sphere's boundary carry v (x) and 0 (y)
    const double* ux = solver->GetFaceVelocityData(0);
    const double* uy = solver->GetFaceVelocityData(1);
    double bcError = 0;
    int boundaryFaces = 0;
    for (int j = 0; j < ny; ++j)
      for (int i = 1; i < nx; ++i)
      {
        if (solid[i + nx * j] != solid[i - 1 + nx * j])
        {
          bcError = std::max(bcError, std::abs(ux[i + (nx + 1) * j] - v));
          ++boundaryFaces;
        }
      }
    for (int j = 1; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        if (solid[i + nx * j] != solid[i + nx * (j - 1)])
        {
          bcError = std::max(bcError, std::abs(uy[i + nx * j]));
          ++boundaryFaces;
        }
      }
    // the fluid in front of and behind the sphere (one cell off its surface, on its axis)
    auto faceU = [&](double x) {
      const int i = int(std::lround(x / h)), j = int(std::floor(y0 / h));
      return 0.5 * (ux[i + (nx + 1) * j] + ux[i + (nx + 1) * (j - 1 + (y0 / h - j > 0.5 ? 2 : 0))]);
    };
    const double front = faceU(xc + r + 1.5 * h), back = faceU(xc - r - 1.5 * h);
    std::vector<double> div(size_t(nx) * ny);
    solver->ComputeDivergence(div.data());
    std::cout << "moving sphere at t = " << t << ": solid centroid (" << sx << ", " << sy << ") vs (" << xc << ", "
              << y0 << "), " << boundaryFaces << " boundary faces off v by " << bcError << ", fluid u in front "
              << front << ", behind " << back << ", max |div| " << MaxAbs(div) << " (v/h = " << v / h
              << "), smoke in its cells " << smokeInside << "\n";
    PLUME_CHECK(std::abs(sx - xc) < 0.5 * h && std::abs(sy - y0) < 0.5 * h,
      "the solid cells are at (" << sx << ", " << sy << "), not (" << xc << ", " << y0 << ")");
    PLUME_CHECK(boundaryFaces > 20 && bcError == 0, "boundary faces off the obstacle's velocity by " << bcError);
    PLUME_CHECK(front > 0.6 * v && back > 0.6 * v, "fluid not dragged: front " << front << ", back " << back);
    PLUME_CHECK(MaxAbs(div) < 1e-6 * v / h, "divergence left " << MaxAbs(div));
    PLUME_CHECK(smokeInside == 0, "smoke in the moving obstacle's cells: " << smokeInside);

    // a checkpoint of the moving run continues bit for bit
    vtkNew<vtkPlumeSmokeSolver> resumed;
    configure(resumed, v);
    PLUME_CHECK(resumed->ReadCheckpoint(checkpoint.c_str()), resumed->GetLastError());
    for (int s = 20; s < steps; ++s)
    {
      PLUME_CHECK(resumed->Step(), resumed->GetLastError());
    }
    const std::vector<double> a(solver->GetFaceVelocityData(0), solver->GetFaceVelocityData(0) + (nx + 1) * ny);
    const std::vector<double> b(resumed->GetFaceVelocityData(0), resumed->GetFaceVelocityData(0) + (nx + 1) * ny);
    PLUME_CHECK(a == b, "the moving run continued from its checkpoint differs");
    std::remove(checkpoint.c_str());
  }
  {
    vtkNew<vtkPlumeSmokeSolver> solver;
    configure(solver, 0.0);
    for (int s = 0; s < 10; ++s)
    {
      PLUME_CHECK(solver->Step(), solver->GetLastError());
    }
    double speed = 0;
    for (int d = 0; d < 2; ++d)
    {
      const size_t count = size_t(nx + (d == 0)) * (ny + (d == 1));
      speed = std::max(speed, MaxAbs(std::vector<double>(
                                solver->GetFaceVelocityData(d), solver->GetFaceVelocityData(d) + count)));
    }
    std::cout << "sphere at rest: max |u| " << speed << "\n";
    PLUME_CHECK(speed == 0, "a sphere at rest moved the fluid: " << speed);
  }

  // 4. bad obstacles
  {
    vtkNew<vtkPlumeSmokeSolver> solver;
    solver->SetDimensions(8, 8, 8);
    vtkNew<vtkPolyData> empty;
    solver->AddObstacleSurface(empty);
    PLUME_CHECK(!solver->Initialize(), "a surface without polygons was accepted");
    const std::string error = solver->GetLastError();
    PLUME_CHECK(error.find("obstacle 0 is a surface without polygons") != std::string::npos, error);
    solver->RemoveAllObstacles();
    const double c[3] = { 0.1, 0.1, 0.1 }, bad[3] = { 0, std::nan(""), 0 };
    solver->AddObstacleSphere(c, 0.05, bad);
    PLUME_CHECK(!solver->Initialize(), "a NaN obstacle velocity was accepted");
    PLUME_CHECK(std::string(solver->GetLastError()).find("obstacle 0 has a non-finite value (nan)") != std::string::npos,
      solver->GetLastError());
  }
  return Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
