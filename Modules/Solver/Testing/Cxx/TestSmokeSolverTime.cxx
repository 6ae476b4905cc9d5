// vtkPlumeSmokeSolver in the pipeline:
//  - it advertises TIME_STEPS k·dt (k = 0..N) and TIME_RANGE;
//  - a request for a later time takes exactly the missing steps, the same
//    time again takes none, an earlier time restarts and recomputes, and
//    the recomputed state equals the first computation bit for bit;
//  - the output carries the six arrays, DATA_TIME_STEP and the grid;
//  - explicit Step() mixes with the pipeline (the stale request does not
//    rewind it), and a grid change restarts;
//  - a checkpoint written at step 6 and read into a new solver continues
//    bit for bit; another grid's or a missing checkpoint is refused, named.
#include "vtkPlumeSmokeSolver.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "plumeSolverTestUtilities.h"

#include <cstdio>
#include <cstring>
#include <string>

using namespace plume_solver_test;

namespace
{
void Configure(vtkPlumeSmokeSolver* solver)
{
  solver->SetDimensions(12, 10, 16);
  solver->SetSpacing(0.1, 0.1, 0.1);
  solver->SetOrigin(-0.5, 0.25, 1.0);
  solver->SetTimeStep(0.1);
  solver->SetNumberOfTimeSteps(10);
  const double center[3] = { 0.05, 0.7, 1.3 };
  const double velocity[3] = { 0.2, 0, 0 };
  solver->AddSource(center, 0.15, 1.0, 2.0, velocity);
}

std::vector<float> Density(vtkImageData* image)
{
  auto* a = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("density"));
  return a ? std::vector<float>(a->GetPointer(0), a->GetPointer(0) + a->GetNumberOfTuples()) : std::vector<float>();
}
}

int TestSmokeSolverTime(int, char*[])
{
  vtkNew<vtkPlumeSmokeSolver> solver;
  Configure(solver);
  solver->UpdateInformation();
  vtkInformation* info = solver->GetOutputInformation(0);
  const int steps = info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  PLUME_CHECK(steps == 11, "advertised " << steps << " time steps");
  if (steps == 11)
  {
    const double* times = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    PLUME_CHECK(std::abs(times[7] - 0.7) < 1e-12, "time step 7 is " << times[7]);
    const double* range = info->Get(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
    PLUME_CHECK(range[0] == 0 && std::abs(range[1] - 1.0) < 1e-12, "range " << range[0] << " " << range[1]);
  }

  solver->UpdateTimeStep(0.5);
  PLUME_CHECK(solver->GetCurrentStep() == 5 && solver->GetStepsTaken() == 5,
    "t = 0.5: step " << solver->GetCurrentStep() << ", taken " << solver->GetStepsTaken());
  vtkImageData* out = solver->GetOutput();
  PLUME_CHECK(std::abs(out->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()) - 0.5) < 1e-12,
    "DATA_TIME_STEP " << out->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()));
  int dims[3];
  out->GetDimensions(dims);
  PLUME_CHECK(dims[0] == 12 && dims[1] == 10 && dims[2] == 16, "dimensions " << dims[0] << " " << dims[1] << " "
                                                                             << dims[2]);
  PLUME_CHECK(out->GetOrigin()[0] == -0.5 && out->GetOrigin()[2] == 1.0, "origin");
  for (const char* name : { "velocity", "density", "temperature", "pressure", "divergence", "obstacle" })
  {
    PLUME_CHECK(out->GetPointData()->GetArray(name) != nullptr, "no array " << name);
  }
  PLUME_CHECK(out->GetPointData()->GetArray("velocity")->GetNumberOfComponents() == 3, "velocity components");
  const std::vector<float> density5 = Density(out);
  double mass = 0;
  for (float d : density5)
  {
    mass += d;
  }
  PLUME_CHECK(mass > 1, "no smoke after 5 steps: " << mass);

  solver->UpdateTimeStep(0.8);
  PLUME_CHECK(solver->GetCurrentStep() == 8 && solver->GetStepsTaken() == 8,
    "t = 0.8: step " << solver->GetCurrentStep() << ", taken " << solver->GetStepsTaken());
  solver->UpdateTimeStep(0.8);
  PLUME_CHECK(solver->GetStepsTaken() == 8, "the same time again took steps: " << solver->GetStepsTaken());
  // a time between steps goes to the nearest step
  solver->UpdateTimeStep(0.86);
  PLUME_CHECK(solver->GetCurrentStep() == 9 && solver->GetStepsTaken() == 9,
    "t = 0.86: step " << solver->GetCurrentStep() << ", taken " << solver->GetStepsTaken());

  // earlier: restart and recompute; same bits as the first time
  solver->UpdateTimeStep(0.5);
  PLUME_CHECK(solver->GetCurrentStep() == 5 && solver->GetStepsTaken() == 14,
    "back to t = 0.5: step " << solver->GetCurrentStep() << ", taken " << solver->GetStepsTaken());
  const std::vector<float> again = Density(solver->GetOutput());
  PLUME_CHECK(again.size() == density5.size() &&
      std::memcmp(again.data(), density5.data(), again.size() * sizeof(float)) == 0,
    "the recomputed step 5 differs from the first");

  // the same as explicit stepping of a fresh solver
  vtkNew<vtkPlumeSmokeSolver> manual;
  Configure(manual);
  for (int s = 0; s < 5; ++s)
  {
    PLUME_CHECK(manual->Step(), manual->GetLastError());
  }
  manual->Update();
  const std::vector<float> manual5 = Density(manual->GetOutput());
  PLUME_CHECK(manual5.size() == density5.size() &&
      std::memcmp(manual5.data(), density5.data(), manual5.size() * sizeof(float)) == 0,
    "explicit steps differ from time requests");

  // explicit steps after a time request: the stale request does not rewind
  PLUME_CHECK(solver->Step() && solver->Step(), solver->GetLastError());
  solver->Update();
  PLUME_CHECK(solver->GetCurrentStep() == 7, "after two explicit steps: step " << solver->GetCurrentStep());
  PLUME_CHECK(std::abs(solver->GetOutput()->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()) - 0.7) < 1e-12,
    "DATA_TIME_STEP after explicit steps");
  PLUME_CHECK(Density(solver->GetOutput()) != density5, "the output did not follow the explicit steps");

  // checkpoint -> restart continues bit for bit
  {
    const std::string path = "plume_smoke_checkpoint.bin"; // in the test's working folder, removed after
    vtkNew<vtkPlumeSmokeSolver> original;
    Configure(original);
    for (int s = 0; s < 6; ++s)
    {
      PLUME_CHECK(original->Step(), original->GetLastError());
    }
    PLUME_CHECK(original->WriteCheckpoint(path.c_str()), original->GetLastError());
    for (int s = 0; s < 4; ++s)
    {
      PLUME_CHECK(original->Step(), original->GetLastError());
    }
    vtkNew<vtkPlumeSmokeSolver> restarted;
    Configure(restarted);
    PLUME_CHECK(restarted->ReadCheckpoint(path.c_str()), restarted->GetLastError());
    PLUME_CHECK(restarted->GetCurrentStep() == 6, "restarted at step " << restarted->GetCurrentStep());
    for (int s = 0; s < 4; ++s)
    {
      PLUME_CHECK(restarted->Step(), restarted->GetLastError());
    }
    const size_t cells = 12 * 10 * 16;
    PLUME_CHECK(std::memcmp(original->GetDensityData(), restarted->GetDensityData(), cells * sizeof(double)) == 0,
      "density after restart differs");
    for (int d = 0; d < 3; ++d)
    {
      const size_t faces = size_t(12 + (d == 0)) * (10 + (d == 1)) * (16 + (d == 2));
      PLUME_CHECK(std::memcmp(original->GetFaceVelocityData(d), restarted->GetFaceVelocityData(d),
                    faces * sizeof(double)) == 0,
        "velocity " << d << " after restart differs");
    }
    PLUME_CHECK(std::abs(original->GetSimulationTime() - restarted->GetSimulationTime()) == 0, "time differs");
    // a checkpoint of another grid is refused, naming it
    vtkNew<vtkPlumeSmokeSolver> other;
    Configure(other);
    other->SetDimensions(12, 10, 17);
    PLUME_CHECK(!other->ReadCheckpoint(path.c_str()), "a checkpoint of another grid was read");
    PLUME_CHECK(std::string(other->GetLastError()).find("12x10x16 grid") != std::string::npos, other->GetLastError());
    PLUME_CHECK(!other->ReadCheckpoint("/nonexistent/checkpoint.bin"), "a missing checkpoint was read");
    PLUME_CHECK(std::string(other->GetLastError()).find("/nonexistent/checkpoint.bin") != std::string::npos,
      other->GetLastError());
    std::remove(path.c_str());
  }

  // a grid change restarts
  solver->SetDimensions(8, 8, 8);
  solver->UpdateTimeStep(0.3);
  PLUME_CHECK(solver->GetCurrentStep() == 3, "after a grid change, t = 0.3: step " << solver->GetCurrentStep());
  solver->GetOutput()->GetDimensions(dims);
  PLUME_CHECK(dims[0] == 8 && dims[2] == 8, "new dimensions " << dims[0]);
  return Failures() == 0 ? 0 : 1;
}
