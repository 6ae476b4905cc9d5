// The projection of vtkPlumeSmokeSolver, against references built here:
//  1. u = ∇×A + ∇φ (discrete curl of an edge potential vanishing on the
//     walls, discrete gradient of a cell field): projection returns ∇×A and
//     leaves no divergence (tolerance 1e-10: error ≤ 1e-7 of the field);
//  2. a random field in a box with an obstacle and an open side: the
//     divergence after projection is the solve's residual (≤ the tolerance);
//  3. fluid at rest in a stably stratified atmosphere (temperature growing
//     with height, buoyancy on, an obstacle) stays at rest over 20 steps:
//     buoyancy depending on height alone is a gradient the projection removes;
//  4. with obstacles and a rising plume, every wall face has exactly zero
//     normal velocity and solid cells hold no smoke.
#include "vtkPlumePressureSolver.h"
#include "vtkPlumeSmokeSolver.h"

#include "vtkMath.h"
#include "vtkNew.h"

#include "plumeSolverTestUtilities.h"

#include <cmath>

using namespace plume_solver_test;

namespace
{

size_t Index(const int m[3], int i, int j, int k)
{
  return i + size_t(m[0]) * (j + size_t(m[1]) * k);
}

void FaceDims(const int n[3], int axis, int m[3])
{
  m[0] = n[0];
  m[1] = n[1];
  m[2] = n[2];
  ++m[axis];
}

// Divergence per cell of face fields (independent of the solver's).
std::vector<double> Divergence(const int n[3], const double h[3], double* const u[3], const unsigned char* solid)
{
  std::vector<double> div(size_t(n[0]) * n[1] * n[2], 0.0);
  int mx[3], my[3], mz[3];
  FaceDims(n, 0, mx);
  FaceDims(n, 1, my);
  FaceDims(n, 2, mz);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
      {
        const size_t c = Index(n, i, j, k);
        if (solid && solid[c])
        {
          continue;
        }
        div[c] = (u[0][Index(mx, i + 1, j, k)] - u[0][Index(mx, i, j, k)]) / h[0] +
          (u[1][Index(my, i, j + 1, k)] - u[1][Index(my, i, j, k)]) / h[1] +
          (u[2][Index(mz, i, j, k + 1)] - u[2][Index(mz, i, j, k)]) / h[2];
      }
  return div;
}

void TestCurlRecovered()
{
  const int n[3] = { 20, 16, 12 };
  const double h[3] = { 0.05, 0.07, 0.06 };
  vtkNew<vtkPlumeSmokeSolver> solver;
  solver->SetDimensions(n[0], n[1], n[2]);
  solver->SetSpacing(h[0], h[1], h[2]);
  solver->SetPressureTolerance(1e-10);
  PLUME_CHECK(solver->Initialize(), solver->GetLastError());

  // Edge potential in index coordinates; s_a vanishes on the walls of axis a
  // (at −1/2 and n − 1/2), so the tangential components vanish on every wall.
  auto s = [&](int a, double x) { return std::sin(vtkMath::Pi() * (x + 0.5) / n[a]); };
  auto Ax = [&](double x, double y, double z) { return std::cos(0.3 * x + 0.2 * z) * s(1, y) * s(2, z); };
  auto Ay = [&](double x, double y, double z) { return (1 + 0.1 * x * y / n[0]) * s(0, x) * s(2, z); };
  auto Az = [&](double x, double y, double z) { return std::sin(0.4 * y + 0.1 * x + z) * s(0, x) * s(1, y); };
  auto phi = [&](int i, int j, int k) { return std::cos(0.5 * i) * std::sin(0.3 * j + 0.2 * k) + 0.01 * i * k; };

  std::vector<double> curl[3];
  for (int d = 0; d < 3; ++d)
  {
    int m[3];
    FaceDims(n, d, m);
    curl[d].assign(size_t(m[0]) * m[1] * m[2], 0.0);
    double* u = solver->GetFaceVelocityData(d);
    for (int k = 0; k < m[2]; ++k)
      for (int j = 0; j < m[1]; ++j)
        for (int i = 0; i < m[0]; ++i)
        {
          // face position in index coordinates
          const double x = i - (d == 0 ? 0.5 : 0.0), y = j - (d == 1 ? 0.5 : 0.0), z = k - (d == 2 ? 0.5 : 0.0);
          double c = 0;
          if (d == 0)
            c = (Az(x, y + 0.5, z) - Az(x, y - 0.5, z)) / h[1] - (Ay(x, y, z + 0.5) - Ay(x, y, z - 0.5)) / h[2];
          else if (d == 1)
            c = (Ax(x, y, z + 0.5) - Ax(x, y, z - 0.5)) / h[2] - (Az(x + 0.5, y, z) - Az(x - 0.5, y, z)) / h[0];
          else
            c = (Ay(x + 0.5, y, z) - Ay(x - 0.5, y, z)) / h[0] - (Ax(x, y + 0.5, z) - Ax(x, y - 0.5, z)) / h[1];
          const size_t f = Index(m, i, j, k);
          curl[d][f] = c;
          int idx[3] = { i, j, k };
          double grad = 0;
          if (idx[d] > 0 && idx[d] < n[d]) // interior faces only: walls stay closed
          {
            int lo[3] = { i, j, k };
            --lo[d];
            grad = (phi(i, j, k) - phi(lo[0], lo[1], lo[2])) / h[d];
          }
          u[f] = c + 3.0 * grad;
        }
  }
  double* u[3] = { solver->GetFaceVelocityData(0), solver->GetFaceVelocityData(1), solver->GetFaceVelocityData(2) };
  const double divBefore = MaxAbs(Divergence(n, h, u, nullptr));
  // the curl part alone is divergence-free: the reference is right
  double* c[3] = { curl[0].data(), curl[1].data(), curl[2].data() };
  const double curlDiv = MaxAbs(Divergence(n, h, c, nullptr));
  PLUME_CHECK(curlDiv < 1e-9, "reference curl divergence " << curlDiv);
  PLUME_CHECK(divBefore > 1, "the gradient part has divergence " << divBefore);

  PLUME_CHECK(solver->Project(), solver->GetLastError());
  const double divAfter = MaxAbs(Divergence(n, h, u, nullptr));
  double err = 0, scale = 0;
  for (int d = 0; d < 3; ++d)
  {
    for (size_t f = 0; f < curl[d].size(); ++f)
    {
      err = std::max(err, std::abs(u[d][f] - curl[d][f]));
      scale = std::max(scale, std::abs(curl[d][f]));
    }
  }
  std::cout << "curl + gradient: divergence " << divBefore << " -> " << divAfter << ", |u - curl A| max " << err
            << " of " << scale << ", " << solver->GetPressureSolver()->GetLastIterations() << " PCG iterations\n";
  PLUME_CHECK(divAfter < 1e-7 * divBefore, "divergence after projection " << divAfter);
  PLUME_CHECK(err < 1e-7 * scale, "curl part not recovered: max error " << err << " of " << scale);
}

void TestRandomFieldWithObstacle(int method)
{
  const int n[3] = { 18, 14, 16 };
  const double h[3] = { 0.1, 0.1, 0.1 };
  vtkNew<vtkPlumeSmokeSolver> solver;
  solver->SetDimensions(n[0], n[1], n[2]);
  solver->SetSpacing(h[0], h[1], h[2]);
  solver->SetOpenFaces("zmax");
  solver->SetPressureMethod(method);
  solver->SetPressureTolerance(1e-9);
  solver->SetPressureMaximumIterations(200000);
  const double box[6] = { 0.5, 1.0, 0.4, 0.9, 0.3, 0.8 };
  solver->AddObstacleBox(box);
  PLUME_CHECK(solver->Initialize(), solver->GetLastError());
  Random random;
  for (int d = 0; d < 3; ++d)
  {
    int m[3];
    FaceDims(n, d, m);
    double* u = solver->GetFaceVelocityData(d);
    for (int k = 0; k < m[2]; ++k)
      for (int j = 0; j < m[1]; ++j)
        for (int i = 0; i < m[0]; ++i)
        {
          u[Index(m, i, j, k)] = solver->IsWallFace(d, i, j, k) ? 0.0 : random.Next();
        }
  }
  double* u[3] = { solver->GetFaceVelocityData(0), solver->GetFaceVelocityData(1), solver->GetFaceVelocityData(2) };
  const unsigned char* solid = solver->GetSolidData();
  const std::vector<double> before = Divergence(n, h, u, solid);
  PLUME_CHECK(solver->Project(), solver->GetLastError());
  const std::vector<double> after = Divergence(n, h, u, solid);
  const double relative = Norm2(after) / Norm2(before);
  std::cout << (method ? "PCG" : "Jacobi") << ", random field, box obstacle, open zmax: |div| "
            << Norm2(before) << " -> " << Norm2(after) << " (relative " << relative << ", "
            << solver->GetPressureSolver()->GetLastIterations() << " iterations)\n";
  PLUME_CHECK(relative <= 1e-9 * 1.0001, "relative divergence after projection " << relative);
  // wall faces (obstacle and closed sides) untouched at zero
  for (int d = 0; d < 3; ++d)
  {
    int m[3];
    FaceDims(n, d, m);
    for (int k = 0; k < m[2]; ++k)
      for (int j = 0; j < m[1]; ++j)
        for (int i = 0; i < m[0]; ++i)
          if (solver->IsWallFace(d, i, j, k) && u[d][Index(m, i, j, k)] != 0)
          {
            PLUME_CHECK(false, "wall face " << d << " " << i << " " << j << " " << k << " moved");
          }
  }
}

void TestStratifiedRest()
{
  const int n[3] = { 14, 12, 20 };
  vtkNew<vtkPlumeSmokeSolver> solver;
  solver->SetDimensions(n[0], n[1], n[2]);
  solver->SetSpacing(0.05, 0.05, 0.05);
  solver->SetBuoyancy(2.0);
  solver->SetSmokeWeight(0.5);
  solver->SetAmbientTemperature(0.0);
  solver->SetTimeStep(0.05);
  solver->SetPressureTolerance(1e-12);
  const double center[3] = { 0.3, 0.25, 0.5 };
  solver->AddObstacleSphere(center, 0.15);
  PLUME_CHECK(solver->Initialize(), solver->GetLastError());
  // temperature and smoke density stratified with height alone
  double* t = solver->GetTemperatureData();
  double* rho = solver->GetDensityData();
  const unsigned char* solid = solver->GetSolidData();
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
      {
        const size_t c = Index(n, i, j, k);
        t[c] = solid[c] ? 0.0 : 1.0 + 0.3 * k + 0.02 * k * k;
        rho[c] = solid[c] ? 0.0 : 0.5 + 0.1 * std::sin(0.4 * k);
      }
  double maxSpeed = 0;
  for (int step = 0; step < 20; ++step)
  {
    PLUME_CHECK(solver->Step(), solver->GetLastError());
    for (int d = 0; d < 3; ++d)
    {
      int m[3];
      FaceDims(n, d, m);
      const double* u = solver->GetFaceVelocityData(d);
      for (size_t f = 0; f < size_t(m[0]) * m[1] * m[2]; ++f)
      {
        maxSpeed = std::max(maxSpeed, std::abs(u[f]));
      }
    }
  }
  // one step's buoyancy impulse is dt * 2 * T ≈ 1.6: rest means many orders below
  std::cout << "stratified atmosphere at rest, 20 steps: max |u| " << maxSpeed << "\n";
  PLUME_CHECK(maxSpeed < 1e-8, "a resting stratified fluid moved: max |u| " << maxSpeed);
}

void TestObstacleWalls()
{
  const int n[3] = { 24, 24, 32 };
  vtkNew<vtkPlumeSmokeSolver> solver;
  solver->SetDimensions(n[0], n[1], n[2]);
  solver->SetSpacing(0.05, 0.05, 0.05);
  solver->SetTimeStep(0.05);
  solver->SetOpenFaces("zmax");
  const double sphere[3] = { 0.6, 0.55, 0.8 };
  solver->AddObstacleSphere(sphere, 0.2);
  const double box[6] = { 0.0, 0.3, 0.0, 1.2, 1.0, 1.1 };
  solver->AddObstacleBox(box);
  const double src[3] = { 0.55, 0.6, 0.2 };
  const double velocity[3] = { 0, 0, 0.5 };
  solver->AddSource(src, 0.12, 1.0, 2.0, velocity);
  for (int step = 0; step < 25; ++step)
  {
    PLUME_CHECK(solver->Step(), solver->GetLastError());
  }
  const unsigned char* solid = solver->GetSolidData();
  const double* rho = solver->GetDensityData();
  size_t solidCells = 0, wallFaces = 0, movingWalls = 0, smokyObstacle = 0;
  double nearObstacleSpeed = 0;
  for (size_t c = 0; c < size_t(n[0]) * n[1] * n[2]; ++c)
  {
    solidCells += solid[c];
    smokyObstacle += solid[c] && rho[c] != 0;
  }
  for (int d = 0; d < 3; ++d)
  {
    int m[3];
    FaceDims(n, d, m);
    const double* u = solver->GetFaceVelocityData(d);
    for (int k = 0; k < m[2]; ++k)
      for (int j = 0; j < m[1]; ++j)
        for (int i = 0; i < m[0]; ++i)
        {
          const double v = u[Index(m, i, j, k)];
          if (solver->IsWallFace(d, i, j, k))
          {
            ++wallFaces;
            movingWalls += v != 0;
          }
          else
          {
            nearObstacleSpeed = std::max(nearObstacleSpeed, std::abs(v));
          }
        }
  }
  double* u[3] = { solver->GetFaceVelocityData(0), solver->GetFaceVelocityData(1), solver->GetFaceVelocityData(2) };
  const double h[3] = { 0.05, 0.05, 0.05 };
  const double div = MaxAbs(Divergence(n, h, u, solid));
  std::cout << "obstacles: " << solidCells << " solid cells, " << wallFaces << " wall faces, " << movingWalls
            << " with normal velocity; max fluid face speed " << nearObstacleSpeed << ", max |div| " << div
            << "\n";
  PLUME_CHECK(solidCells > 100, "the obstacles were not voxelised: " << solidCells);
  PLUME_CHECK(movingWalls == 0, movingWalls << " wall faces have a normal velocity");
  PLUME_CHECK(smokyObstacle == 0, smokyObstacle << " solid cells hold smoke");
  PLUME_CHECK(nearObstacleSpeed > 0.1, "the plume did not move: " << nearObstacleSpeed);
  PLUME_CHECK(div < 1e-4 * nearObstacleSpeed / h[0], "divergence left " << div);
}
}

int TestSmokeSolverProjection(int, char*[])
{
  TestCurlRecovered();
  TestRandomFieldWithObstacle(vtkPlumePressureSolver::PCG);
  TestRandomFieldWithObstacle(vtkPlumePressureSolver::JACOBI);
  TestStratifiedRest();
  TestObstacleWalls();
  return Failures() == 0 ? 0 : 1;
}
