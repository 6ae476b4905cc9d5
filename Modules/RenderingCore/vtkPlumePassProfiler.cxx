#include "vtkPlumePassProfiler.h"

#include "vtk_glew.h"

#include <ctime>
#include <utility>

//------------------------------------------------------------------------------
void vtkPlumePassProfiler::Finish(std::chrono::steady_clock::time_point& wall, double& cpu) const
{
  glFinish();
  wall = std::chrono::steady_clock::now();
  cpu = static_cast<double>(std::clock()) / CLOCKS_PER_SEC; // all the process's threads
}

//------------------------------------------------------------------------------
void vtkPlumePassProfiler::Start()
{
  if (!this->Enabled)
  {
    return;
  }
  this->Passes.clear();
  this->Finish(this->WallStart, this->CPUStart);
}

//------------------------------------------------------------------------------
void vtkPlumePassProfiler::Mark(const char* name, int level)
{
  if (!this->Enabled)
  {
    return;
  }
  std::chrono::steady_clock::time_point wall;
  double cpu;
  this->Finish(wall, cpu);
  Pass pass{ name, std::chrono::duration<double>(wall - this->WallStart).count(), cpu - this->CPUStart };
  if (level > 0)
  {
    pass.Name += " " + std::to_string(level);
  }
  this->Passes.push_back(std::move(pass));
  this->WallStart = wall;
  this->CPUStart = cpu;
}

//------------------------------------------------------------------------------
const char* vtkPlumePassProfiler::GetPassName(int pass) const
{
  return pass >= 0 && pass < this->GetNumberOfPasses() ? this->Passes[pass].Name.c_str() : nullptr;
}

//------------------------------------------------------------------------------
double vtkPlumePassProfiler::GetPassSeconds(int pass) const
{
  return pass >= 0 && pass < this->GetNumberOfPasses() ? this->Passes[pass].Seconds : 0.0;
}

//------------------------------------------------------------------------------
double vtkPlumePassProfiler::GetPassCPUSeconds(int pass) const
{
  return pass >= 0 && pass < this->GetNumberOfPasses() ? this->Passes[pass].CPUSeconds : 0.0;
}
