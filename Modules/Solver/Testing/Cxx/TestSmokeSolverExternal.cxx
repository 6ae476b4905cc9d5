// Virtual smoke released into a given velocity field (input port 1):
//  1. a cellular flow u = (sin πx cos πy, −cos πx sin πy, 0) on its own,
//     finer and offset image grid: the solver's faces match the analytic
//     field within trilinear error, the projection leaves no divergence, the
//     velocity never changes over the steps (no buoyancy, no solve), even
//     with hot smoke;
//  2. a uniform flow (1, 0, 0) with open x sides carries a smoke blob
//     exactly u·t downstream (centroid within 1 % of a cell), mass kept
//     while inside;
//  3. points whose vtkValidPointMask is 0 become solid cells;
//  4. a velocity image without the named array is one clear error.
#include "vtkPlumeSmokeSolver.h"

#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSignedCharArray.h"

#include "plumeSolverTestUtilities.h"

#include <functional>

using namespace plume_solver_test;

namespace
{

vtkSmartPointer<vtkImageData> Field(const int dims[3], const double origin[3], const double spacing[3],
  const std::function<void(const double*, double*)>& f, const char* name)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dims[0], dims[1], dims[2]);
  image->SetOrigin(origin[0], origin[1], origin[2]);
  image->SetSpacing(spacing[0], spacing[1], spacing[2]);
  vtkNew<vtkDoubleArray> v;
  v->SetName(name);
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    double x[3], u[3];
    image->GetPoint(p, x);
    f(x, u);
    v->SetTuple(p, u);
  }
  image->GetPointData()->AddArray(v);
  return image;
}
}

int TestSmokeSolverExternal(int, char*[])
{
  // 1. cellular flow on [0, 1]² × [0, 0.25]
  {
    const int n[3] = { 20, 20, 5 };
    const double h = 1.0 / 20;
    auto cellular = [](const double* x, double* u) {
      u[0] = std::sin(vtkMath::Pi() * x[0]) * std::cos(vtkMath::Pi() * x[1]);
      u[1] = -std::cos(vtkMath::Pi() * x[0]) * std::sin(vtkMath::Pi() * x[1]);
      u[2] = 0;
    };
    const int dims[3] = { 61, 63, 9 };
    const double origin[3] = { -0.01, -0.02, -0.05 }, spacing[3] = { 1.02 / 60, 1.04 / 62, 0.4 / 8 };
    auto image = Field(dims, origin, spacing, cellular, "wind");
    vtkNew<vtkPlumeSmokeSolver> solver;
    solver->SetDimensions(n[0], n[1], n[2]);
    solver->SetSpacing(h, h, h);
    solver->SetOrigin(0.5 * h, 0.5 * h, 0.5 * h); // walls at 0 and 1
    solver->SetVelocityData(image);
    solver->SetVelocityArrayName("wind");
    solver->SetPressureTolerance(1e-10);
    const double src[3] = { 0.3, 0.5, 0.1 }, none[3] = { 0, 0, 0 };
    solver->AddSource(src, 0.1, 1.0, 5.0, none); // hot: buoyancy must not act
    solver->Update(); // hands the velocity image over
    PLUME_CHECK(solver->HasExternalVelocity(), "the velocity input was not taken");
    double error = 0;
    for (int d = 0; d < 2; ++d)
    {
      const int mx = n[0] + (d == 0), my = n[1] + (d == 1);
      const double* u = solver->GetFaceVelocityData(d);
      for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < my; ++j)
          for (int i = 0; i < mx; ++i)
          {
            const double x[3] = { d == 0 ? i * h : (i + 0.5) * h, d == 1 ? j * h : (j + 0.5) * h, (k + 0.5) * h };
            double exact[3];
            cellular(x, exact);
            error = std::max(error, std::abs(u[i + size_t(mx) * (j + size_t(my) * k)] - exact[d]));
          }
    }
    std::vector<double> div(size_t(n[0]) * n[1] * n[2]);
    solver->ComputeDivergence(div.data());
    const std::vector<double> before(solver->GetFaceVelocityData(1),
      solver->GetFaceVelocityData(1) + size_t(n[0]) * (n[1] + 1) * n[2]);
    for (int s = 0; s < 10; ++s)
    {
      PLUME_CHECK(solver->Step(), solver->GetLastError());
    }
    const std::vector<double> after(solver->GetFaceVelocityData(1),
      solver->GetFaceVelocityData(1) + size_t(n[0]) * (n[1] + 1) * n[2]);
    std::cout << "cellular flow: max face error " << error << ", max |div| " << MaxAbs(div) << "\n";
    PLUME_CHECK(error < 5e-3, "sampled velocity off by " << error);
    PLUME_CHECK(MaxAbs(div) < 1e-7, "divergence left " << MaxAbs(div));
    PLUME_CHECK(before == after, "the given velocity changed over the steps");
    double mass = 0;
    for (int c = 0; c < n[0] * n[1] * n[2]; ++c)
    {
      mass += solver->GetDensityData()[c];
    }
    PLUME_CHECK(mass > 10, "the source emitted nothing: " << mass);
  }

  // 2. uniform flow carries a blob downstream
  {
    const int n[3] = { 40, 10, 10 };
    const double h = 0.1;
    const int dims[3] = { 5, 5, 5 };
    const double origin[3] = { -1, -1, -1 }, spacing[3] = { 2, 1, 1 };
    auto image = Field(dims, origin, spacing, [](const double*, double* u) { u[0] = 1; u[1] = u[2] = 0; }, "velocity");
    vtkNew<vtkPlumeSmokeSolver> solver;
    solver->SetDimensions(n[0], n[1], n[2]);
    solver->SetSpacing(h, h, h);
    solver->SetOpenFaces("xmin,xmax");
    solver->SetVelocityData(image);
    solver->SetVelocityArrayName("velocity");
    solver->SetTimeStep(0.05);
    solver->Update();
    double* rho = solver->GetDensityData();
    auto moments = [&](double& mass, double& cx) {
      mass = cx = 0;
      for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j)
          for (int i = 0; i < n[0]; ++i)
          {
            const double d = rho[i + size_t(n[0]) * (j + size_t(n[1]) * k)];
            mass += d;
            cx += d * i * h;
          }
      cx /= mass;
    };
    for (int k = 3; k < 7; ++k)
      for (int j = 3; j < 7; ++j)
        for (int i = 5; i < 10; ++i)
          rho[i + size_t(n[0]) * (j + size_t(n[1]) * k)] = 1.0;
    double m0, x0, m1, x1;
    moments(m0, x0);
    for (int s = 0; s < 20; ++s)
    {
      PLUME_CHECK(solver->Step(), solver->GetLastError());
      rho = solver->GetDensityData();
    }
    moments(m1, x1);
    std::cout << "uniform flow, 1.0 s: centroid moved " << x1 - x0 << " (exact 1), mass " << m1 / m0 << "\n";
    PLUME_CHECK(std::abs(x1 - x0 - 1.0) < 0.01 * h, "centroid moved " << x1 - x0);
    PLUME_CHECK(std::abs(m1 / m0 - 1) < 1e-12, "mass changed by " << m1 / m0 - 1);
  }

  // 3. masked points are solid; 4. a missing array is an error
  {
    const int dims[3] = { 8, 8, 8 };
    const double origin[3] = { 0, 0, 0 }, spacing[3] = { 0.1, 0.1, 0.1 };
    auto image = Field(dims, origin, spacing, [](const double*, double* u) { u[0] = u[1] = u[2] = 0.1; }, "v");
    vtkNew<vtkSignedCharArray> valid;
    valid->SetName("vtkValidPointMask");
    valid->SetNumberOfTuples(image->GetNumberOfPoints());
    for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
    {
      double x[3];
      image->GetPoint(p, x);
      valid->SetValue(p, x[0] > 0.45 ? 0 : 1);
    }
    image->GetPointData()->AddArray(valid);
    vtkNew<vtkPlumeSmokeSolver> solver;
    solver->SetDimensions(8, 8, 8);
    solver->SetSpacing(0.1, 0.1, 0.1);
    solver->SetVelocityData(image);
    solver->SetVelocityArrayName("v");
    solver->Update();
    int solid = 0;
    for (int c = 0; c < 512; ++c)
    {
      solid += solver->GetSolidData()[c];
    }
    PLUME_CHECK(solid == 3 * 64, "masked points gave " << solid << " solid cells, expected 192");

    solver->SetVelocityArrayName("nope");
    solver->GlobalWarningDisplayOff();
    solver->Update();
    solver->GlobalWarningDisplayOn();
    const std::string message = solver->GetLastError();
    PLUME_CHECK(message.find("no 3-component point array 'nope'") != std::string::npos, message);
  }
  return Failures() == 0 ? 0 : 1;
}
