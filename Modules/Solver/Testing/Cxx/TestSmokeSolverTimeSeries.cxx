// Virtual smoke in a time-varying flow (a time series on input port 1):
//  1. an analytic rotation whose rate is written at t = 0, 0.4, 1 (0, 2, 5;
//     the source answers a request for another time with the nearest written
//     one, as a reader does): a blob's centroid turns by the exact angle of
//     the rate linear between written times (0.1, 0.4, 1.225, 2.5 rad at
//     t = 0.2, 0.4, 0.7, 1), the faces at t = 0.7 hold rate 3.5 exactly, and
//     each written time is fetched once;
//  2. the same run driven by the pipeline's time requests (the frames are
//     fetched from inside RequestData) equals the explicit steps bit for bit,
//     also after a request for an earlier time;
//  3. the real Nek5000 eddy series (11 written times, t = 0 .. 0.1) through
//     the project's reader and resampler: all 11 times are read, the faces
//     between two written times equal the linear blend of the two resampled
//     images probed by VTK (vtkProbeFilter, not the solver's sampling), and a
//     smoke blob's centroid follows an RK4 particle trace through the same
//     blended field within a quarter of a cell.
#include "vtkPlumeDatasetReader.h"
#include "vtkPlumeResampleToImage.h"
#include "vtkPlumeSmokeSolver.h"

#include "vtkDoubleArray.h"
#include "vtkImageAlgorithm.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProbeFilter.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "plumeSolverTestUtilities.h"

#include <array>
#include <string>

using namespace plume_solver_test;

namespace
{
// A rotation about (0.5, 0.5) whose rate is given at a few written times.
class RotationSeries : public vtkImageAlgorithm
{
public:
  static RotationSeries* New();
  vtkTypeMacro(RotationSeries, vtkImageAlgorithm);
  std::vector<double> Times = { 0.0, 0.4, 1.0 };
  std::vector<double> Rates = { 0.0, 2.0, 5.0 };
  std::vector<double> Requests; // the times asked for

protected:
  RotationSeries() { this->SetNumberOfInputPorts(0); }
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkInformation* info = out->GetInformationObject(0);
    const int extent[6] = { 0, 20, 0, 20, 0, 0 };
    info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), this->Times.data(), int(this->Times.size()));
    double range[2] = { this->Times.front(), this->Times.back() };
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
    return 1;
  }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkInformation* info = out->GetInformationObject(0);
    double t = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
      ? info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
      : this->Times.front();
    this->Requests.push_back(t);
    size_t nearest = 0;
    for (size_t k = 1; k < this->Times.size(); ++k)
    {
      if (std::abs(this->Times[k] - t) < std::abs(this->Times[nearest] - t))
      {
        nearest = k;
      }
    }
    const double rate = this->Rates[nearest];
    vtkImageData* image = vtkImageData::GetData(info);
    image->SetExtent(0, 20, 0, 20, 0, 0);
    image->SetOrigin(0, 0, 0);
    image->SetSpacing(0.05, 0.05, 1);
    vtkNew<vtkDoubleArray> v;
    v->SetName("wind");
    v->SetNumberOfComponents(3);
    v->SetNumberOfTuples(image->GetNumberOfPoints());
    for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
    {
      double x[3];
      image->GetPoint(p, x);
      v->SetTuple3(p, -rate * (x[1] - 0.5), rate * (x[0] - 0.5), 0);
    }
    image->GetPointData()->SetVectors(v);
    image->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), this->Times[nearest]);
    return 1;
  }
};
vtkStandardNewMacro(RotationSeries);

// The exact angle turned by time t at the rate linear between written times.
double ExactAngle(const std::vector<double>& times, const std::vector<double>& rates, double t)
{
  double angle = 0;
  for (size_t k = 0; k + 1 < times.size() && times[k] < t; ++k)
  {
    const double end = std::min(t, times[k + 1]);
    const double slope = (rates[k + 1] - rates[k]) / (times[k + 1] - times[k]);
    const double r0 = rates[k], r1 = rates[k] + slope * (end - times[k]);
    angle += 0.5 * (r0 + r1) * (end - times[k]);
  }
  return angle;
}

std::array<double, 2> Centroid(const double* density, int nx, int ny, double h, double ox, double oy)
{
  double m = 0, cx = 0, cy = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
    {
      const double d = density[i + size_t(nx) * j];
      m += d;
      cx += d * (ox + i * h);
      cy += d * (oy + j * h);
    }
  return { cx / m, cy / m };
}

void Configure(vtkPlumeSmokeSolver* solver, int n, double h)
{
  solver->SetDimensions(n, n, 1);
  solver->SetSpacing(h, h, h);
  solver->SetOrigin(0.5 * h, 0.5 * h, 0);
  solver->SetTimeStep(0.02);
  solver->SetNumberOfTimeSteps(50);
  solver->SetVelocityArrayName("wind");
  solver->SetProjectExternalVelocity(false); // a rigid rotation is not tangent to the box's walls
}
}

int TestSmokeSolverTimeSeries(int argc, char* argv[])
{
  const int n = 64;
  const double h = 1.0 / n;
  // 1. explicit steps in the analytic rotation
  {
    vtkNew<RotationSeries> series;
    vtkNew<vtkPlumeSmokeSolver> solver;
    Configure(solver, n, h);
    solver->SetVelocityConnection(series->GetOutputPort());
    solver->Update();
    PLUME_CHECK(solver->IsVelocityTimeSeries(), "the 3 written times were not seen");
    double* density = solver->GetDensityData();
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double x = (i + 0.5) * h - 0.75, y = (j + 0.5) * h - 0.5;
        density[i + size_t(n) * j] = std::exp(-(x * x + y * y) / (0.05 * 0.05));
      }
    const double checkpoints[] = { 0.2, 0.4, 0.7, 1.0 };
    int step = 0;
    for (double t : checkpoints)
    {
      while (step < int(std::lround(t / 0.02)))
      {
        PLUME_CHECK(solver->Step(), solver->GetLastError());
        ++step;
      }
      const auto c = Centroid(solver->GetDensityData(), n, n, h, 0.5 * h, 0.5 * h);
      const double angle = std::atan2(c[1] - 0.5, c[0] - 0.5);
      double exact = ExactAngle(series->Times, series->Rates, t);
      exact = std::atan2(std::sin(exact), std::cos(exact));
      std::cout << "rotation series t = " << t << ": centroid angle " << angle << " rad, exact " << exact
                << ", radius " << std::hypot(c[0] - 0.5, c[1] - 0.5) << "\n";
      PLUME_CHECK(std::abs(angle - exact) < 0.02, "t = " << t << ": angle " << angle << " vs exact " << exact);
      if (t == 0.7)
      {
        // x faces hold u = -rate (y - 0.5) with rate 2 + 5 (0.7 - 0.4) = 3.5
        const double* u = solver->GetFaceVelocityData(0);
        double error = 0;
        for (int j = 0; j < n; ++j)
          for (int i = 1; i < n; ++i)
          {
            error = std::max(error, std::abs(u[i + size_t(n + 1) * j] + 3.5 * ((j + 0.5) * h - 0.5)));
          }
        PLUME_CHECK(error < 1e-12, "faces at t = 0.7 off the blended rate 3.5 by " << error);
      }
    }
    PLUME_CHECK(solver->GetNumberOfVelocityFramesRead() == 3,
      "written times fetched " << solver->GetNumberOfVelocityFramesRead() << " times, expected 3");
    for (double r : series->Requests)
    {
      PLUME_CHECK(r == 0.0 || r == 0.4 || r == 1.0, "the input was asked for time " << r << ", not a written time");
    }
  }

  // 2. pipeline time requests = explicit steps
  {
    const double src[3] = { 0.75, 0.5, 0 }, none[3] = { 0, 0, 0 };
    vtkNew<RotationSeries> seriesA, seriesB;
    vtkNew<vtkPlumeSmokeSolver> a, b;
    Configure(a, n, h);
    Configure(b, n, h);
    a->SetVelocityConnection(seriesA->GetOutputPort());
    b->SetVelocityConnection(seriesB->GetOutputPort());
    a->AddSource(src, 0.04, 1.0, 0.0, none);
    b->AddSource(src, 0.04, 1.0, 0.0, none);
    a->Update();
    std::vector<double> at20;
    for (int s = 0; s < 50; ++s)
    {
      PLUME_CHECK(a->Step(), a->GetLastError());
      if (s == 19)
      {
        at20.assign(a->GetDensityData(), a->GetDensityData() + n * n);
      }
    }
    b->UpdateTimeStep(1.0);
    auto* out = vtkImageData::SafeDownCast(b->GetOutputDataObject(0));
    PLUME_CHECK(b->GetCurrentStep() == 50, "the time request went to step " << b->GetCurrentStep());
    size_t differ = 0;
    for (int c = 0; c < n * n; ++c)
    {
      differ += out->GetPointData()->GetArray("density")->GetComponent(c, 0) != float(a->GetDensityData()[c]);
    }
    PLUME_CHECK(differ == 0, differ << " cells differ between pipeline and explicit steps at t = 1");
    b->UpdateTimeStep(0.4); // earlier: a restart from step 0
    out = vtkImageData::SafeDownCast(b->GetOutputDataObject(0));
    differ = 0;
    for (int c = 0; c < n * n; ++c)
    {
      differ += out->GetPointData()->GetArray("density")->GetComponent(c, 0) != float(at20[c]);
    }
    PLUME_CHECK(differ == 0, differ << " cells differ after a request for the earlier t = 0.4");
  }

  // 3. the real Nek5000 eddy series
  {
    std::string data = PLUME_DATA_DIR;
    for (int a = 1; a + 1 < argc; ++a)
    {
      if (std::string(argv[a]) == "-D")
      {
        data = argv[a + 1];
      }
    }
    if (const char* env = std::getenv("PLUME_DATA_DIR"))
    {
      data = env;
    }
    const std::string path = data + "/nek5000_eddy_uv/vtu/eddy_uv.pvd";
    vtkNew<vtkPlumeDatasetReader> reader;
    reader->SetFileName(path.c_str());
    vtkNew<vtkPlumeResampleToImage> resample;
    resample->SetInputConnection(reader->GetOutputPort());
    resample->SetSamplingDimensions(97, 97, 1);
    const int m = 48;
    const double twoPi = 6.283185307179586, hm = twoPi / m;
    vtkNew<vtkPlumeSmokeSolver> solver;
    solver->SetDimensions(m, m, 1);
    solver->SetSpacing(hm, hm, hm);
    solver->SetOrigin(0.5 * hm, 0.5 * hm, 0);
    solver->SetTimeStep(0.005);
    solver->SetVelocityConnection(resample->GetOutputPort());
    solver->SetVelocityArrayName("velocity");
    solver->SetProjectExternalVelocity(false); // compared with the images as resampled
    solver->Update();
    PLUME_CHECK(reader->GetLastError().empty(), "reading " << path << ": " << reader->GetLastError());
    PLUME_CHECK(solver->GetVelocityTimes().size() == 11, "written times: " << solver->GetVelocityTimes().size());
    PLUME_CHECK(solver->HasExternalVelocity(), "no velocity taken from the series");
    if (solver->GetVelocityTimes().size() != 11 || !solver->HasExternalVelocity())
    {
      return EXIT_FAILURE;
    }
    // the two resampled images around t = 0.025, read by a pipeline of their own
    auto readAt = [&](double t) {
      vtkNew<vtkPlumeDatasetReader> r;
      r->SetFileName(path.c_str());
      vtkNew<vtkPlumeResampleToImage> s;
      s->SetInputConnection(r->GetOutputPort());
      s->SetSamplingDimensions(97, 97, 1);
      s->UpdateTimeStep(t);
      auto image = vtkSmartPointer<vtkImageData>::New();
      image->DeepCopy(s->GetOutput());
      return image;
    };
    auto f2 = readAt(0.02), f3 = readAt(0.03);
    double frameDifference = 0;
    {
      auto* v2 = f2->GetPointData()->GetArray("velocity");
      auto* v3 = f3->GetPointData()->GetArray("velocity");
      for (vtkIdType p = 0; p < v2->GetNumberOfTuples(); ++p)
      {
        frameDifference = std::max(frameDifference, std::abs(v2->GetComponent(p, 0) - v3->GetComponent(p, 0)));
      }
    }
    // faces of axis d probed in an image (VTK's own interpolation)
    auto probeFaces = [&](vtkImageData* image, int d) {
      vtkNew<vtkPoints> points;
      const int mx = m + (d == 0), my = m + (d == 1);
      for (int j = 0; j < my; ++j)
        for (int i = 0; i < mx; ++i)
        {
          points->InsertNextPoint((i + (d == 0 ? 0.0 : 0.5)) * hm, (j + (d == 1 ? 0.0 : 0.5)) * hm, 0);
        }
      vtkNew<vtkPolyData> poly;
      poly->SetPoints(points);
      vtkNew<vtkProbeFilter> probe;
      probe->SetInputData(poly);
      probe->SetSourceData(image);
      probe->Update();
      auto* v = probe->GetOutput()->GetPointData()->GetArray("velocity");
      auto* valid = probe->GetOutput()->GetPointData()->GetArray("vtkValidPointMask");
      std::vector<double> values(size_t(mx) * my);
      for (vtkIdType p = 0; p < vtkIdType(values.size()); ++p)
      {
        values[p] = valid->GetComponent(p, 0) ? v->GetComponent(p, d) : 0.0;
      }
      return values;
    };
    // step to t = 0.02, then check the faces at t = 0.025 (the output's flow after 5 steps)
    for (int s = 0; s < 5; ++s)
    {
      PLUME_CHECK(solver->Step(), solver->GetLastError());
    }
    double error = 0, scale = 0;
    for (int d = 0; d < 2; ++d)
    {
      const auto a = probeFaces(f2, d), b = probeFaces(f3, d);
      const double* u = solver->GetFaceVelocityData(d);
      const int mx = m + (d == 0), my = m + (d == 1);
      for (int j = 0; j < my; ++j)
        for (int i = 0; i < mx; ++i)
        {
          const bool wall = (d == 0 && (i == 0 || i == m)) || (d == 1 && (j == 0 || j == m));
          if (wall)
          {
            continue;
          }
          const size_t f = i + size_t(mx) * j;
          const double blend = 0.5 * (a[f] + b[f]);
          error = std::max(error, std::abs(u[f] - blend));
          scale = std::max(scale, std::abs(blend));
        }
    }
    std::cout << "eddy series t = 0.025: faces vs the probed blend of t = 0.02 and 0.03: max error " << error
              << " (max |u| " << scale << ", the two frames differ by up to " << frameDifference << ")\n";
    PLUME_CHECK(error < 1e-5 * scale, "faces off the blend by " << error);
    PLUME_CHECK(frameDifference > 1e3 * error, "the frames hardly differ (" << frameDifference << ")");

    // a blob of smoke released at t = 0, where the flow is fastest, against
    // RK4 traces of its cells (weighted by their density) through the
    // blended field: the exact centroid of smoke carried by the flow
    std::vector<vtkSmartPointer<vtkImageData>> frames;
    for (int k = 0; k <= 10; ++k)
    {
      frames.push_back(readAt(0.01 * k));
    }
    double start[2] = { 0, 0 };
    {
      auto* v0 = frames[0]->GetPointData()->GetArray("velocity");
      double fastest = 0;
      for (vtkIdType p = 0; p < v0->GetNumberOfTuples(); ++p)
      {
        double x[3];
        frames[0]->GetPoint(p, x);
        const double speed = std::hypot(v0->GetComponent(p, 0), v0->GetComponent(p, 1));
        if (speed > fastest && x[0] > 1 && x[0] < twoPi - 1 && x[1] > 1 && x[1] < twoPi - 1)
        {
          fastest = speed;
          start[0] = x[0];
          start[1] = x[1];
        }
      }
    }
    const int readBefore = solver->GetNumberOfVelocityFramesRead();
    solver->Reset();
    const double sigma = 0.2;
    double* density = solver->GetDensityData();
    std::vector<std::array<double, 3>> particles; // x, y, weight
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
      {
        const double x = (i + 0.5) * hm - start[0], y = (j + 0.5) * hm - start[1];
        const double d = std::exp(-(x * x + y * y) / (sigma * sigma));
        density[i + size_t(m) * j] = d;
        if (d > 1e-6)
        {
          particles.push_back({ (i + 0.5) * hm, (j + 0.5) * hm, d });
        }
      }
    const auto c0 = Centroid(density, m, m, hm, 0.5 * hm, 0.5 * hm);
    for (int s = 0; s < 20; ++s)
    {
      PLUME_CHECK(solver->Step(), solver->GetLastError());
    }
    const auto c1 = Centroid(solver->GetDensityData(), m, m, hm, 0.5 * hm, 0.5 * hm);
    PLUME_CHECK(solver->GetNumberOfVelocityFramesRead() - readBefore == 11,
      "frames read " << solver->GetNumberOfVelocityFramesRead() - readBefore
                     << " over t = 0..0.1, expected the 11 written times once each");
    // the velocity of every particle at time t: the images probed, linear in time
    auto velocityAt = [&](double t, const std::vector<std::array<double, 2>>& x,
                        std::vector<std::array<double, 2>>& v) {
      const int k = std::min(std::max(int(std::floor(t / 0.01)), 0), 9);
      const double w = std::min(std::max(t / 0.01 - k, 0.0), 1.0);
      vtkNew<vtkPoints> p;
      for (const auto& q : x)
      {
        p->InsertNextPoint(q[0], q[1], 0);
      }
      vtkNew<vtkPolyData> poly;
      poly->SetPoints(p);
      v.assign(x.size(), { 0, 0 });
      for (int e = 0; e < 2; ++e)
      {
        vtkNew<vtkProbeFilter> probe;
        probe->SetInputData(poly);
        probe->SetSourceData(frames[size_t(k + e)]);
        probe->Update();
        auto* u = probe->GetOutput()->GetPointData()->GetArray("velocity");
        const double weight = e == 0 ? 1 - w : w;
        for (size_t q = 0; q < x.size(); ++q)
        {
          v[q][0] += weight * u->GetComponent(vtkIdType(q), 0);
          v[q][1] += weight * u->GetComponent(vtkIdType(q), 1);
        }
      }
    };
    std::vector<std::array<double, 2>> x(particles.size()), y, k1, k2, k3, k4;
    for (size_t q = 0; q < particles.size(); ++q)
    {
      x[q] = { particles[q][0], particles[q][1] };
    }
    auto shifted = [&](const std::vector<std::array<double, 2>>& k, double f) {
      y = x;
      for (size_t q = 0; q < y.size(); ++q)
      {
        y[q][0] += f * k[q][0];
        y[q][1] += f * k[q][1];
      }
      return y;
    };
    const double dt = 0.0025;
    for (int s = 0; s < 40; ++s)
    {
      const double t = s * dt;
      velocityAt(t, x, k1);
      velocityAt(t + 0.5 * dt, shifted(k1, 0.5 * dt), k2);
      velocityAt(t + 0.5 * dt, shifted(k2, 0.5 * dt), k3);
      velocityAt(t + dt, shifted(k3, dt), k4);
      for (size_t q = 0; q < x.size(); ++q)
      {
        for (int a = 0; a < 2; ++a)
        {
          x[q][a] += dt / 6 * (k1[q][a] + 2 * k2[q][a] + 2 * k3[q][a] + k4[q][a]);
        }
      }
    }
    double total = 0, reference[2] = { 0, 0 };
    for (size_t q = 0; q < x.size(); ++q)
    {
      total += particles[q][2];
      reference[0] += particles[q][2] * x[q][0];
      reference[1] += particles[q][2] * x[q][1];
    }
    reference[0] /= total;
    reference[1] /= total;
    const double moved = std::hypot(reference[0] - c0[0], reference[1] - c0[1]);
    const double miss = std::hypot(c1[0] - reference[0], c1[1] - reference[1]);
    std::cout << "eddy series: blob released at (" << start[0] << ", " << start[1] << "), centroid moved "
              << std::hypot(c1[0] - c0[0], c1[1] - c0[1]) << " over t = 0..0.1, the traced smoke's " << moved
              << " (" << particles.size() << " particles), apart by " << miss << " (" << miss / hm << " cells)\n";
    PLUME_CHECK(moved > 1.5 * hm, "the reference smoke hardly moved: " << moved);
    PLUME_CHECK(miss < 0.25 * hm, "the blob is " << miss / hm << " cells off the traced smoke");
  }
  return Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
