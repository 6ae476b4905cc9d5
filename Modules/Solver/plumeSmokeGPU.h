// vtkPlumeSmokeSolver's GPU backend (internal): the seed's step (seed 004,
// Harris, GPU Gems ch. 38) as fragment-shader passes over float 3D textures,
// ping-ponged (vtkPlumePingPongTexture3D), rendered a whole 3D texture at a
// time by layered rendering (a geometry shader sets gl_Layer). Same MAC grid,
// stages, boundary conditions and obstacles as the CPU backend's Jacobi path.
#ifndef plumeSmokeGPU_h
#define plumeSmokeGPU_h

#include <memory>
#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkRenderWindow;
class vtkTextureObject;

namespace plume
{
namespace smoke
{
struct GPUGrid
{
  int Cells[3];
  double H[3];
  bool Open[6]; // x-, x+, y-, y+, z-, z+
};

struct GPUSource // where it acts: SmokeGPU::SetSourceMasks
{
  double Density;
  double Temperature;
  double Velocity[3];
};

struct GPUStepSettings
{
  double Dt;
  double DensityDecay, TemperatureDecay, VelocityDecay; // exp(-rate dt)
  double Ambient;
  double Buoyancy, SmokeWeight;
  double Up[3]; // normalised, or zero
  std::vector<GPUSource> Sources;
  int JacobiIterations;
  double JacobiWeight;
};

class SmokeGPU
{
public:
  SmokeGPU();
  ~SmokeGPU();
  SmokeGPU(const SmokeGPU&) = delete;
  SmokeGPU& operator=(const SmokeGPU&) = delete;

  /** Most sources one step can apply (shader uniform arrays). */
  static constexpr int MaxSources = 16;

  /**
   * Makes the context current (`window`, or an offscreen window of its own)
   * and uploads the state (faces of axis d: (Cells + e_d) values, cells:
   * Cells values; x fastest), allocating the textures if the grid changed.
   */
  bool Upload(vtkRenderWindow* window, const GPUGrid& grid, const std::vector<double> u[3],
    const std::vector<double>& density, const std::vector<double>& temperature,
    const std::vector<unsigned char>& solid, std::string& error);
  /**
   * Where the sources act: per cell (Cells values) and per face of axis d
   * (Cells + e_d values), the index + 1 of the source that sets it (the last
   * one covering it), 0 for none; an empty vector: no source acts there.
   * Decided on the CPU (the CPU backend's test, in double). After Upload().
   */
  bool SetSourceMasks(const std::vector<float>& cells, const std::vector<float> faces[3], std::string& error);
  /** One step; the state stays on the GPU. */
  bool Step(const GPUStepSettings& settings, std::string& error);
  /** The state back to the host (q: the last projection's pressure, p dt). */
  bool Download(std::vector<double> u[3], std::vector<double>& density, std::vector<double>& temperature,
    std::vector<double>& q, std::string& error);
  /** The cell-centred velocity (RGBA32F, a = 1) computed into its texture, and read back into `rgba` if given. */
  bool CellVelocity(float* rgba, std::string& error);
  /** Runs `passes` passes of the trivial Jacobi-sized full-grid work (bench: the floor of one pass). */
  bool TrivialPasses(int passes, std::string& error);
  /** Waits for the GPU to finish its queued passes (timing). */
  void Finish();

  vtkOpenGLRenderWindow* GetWindow() const;
  vtkTextureObject* GetDensityTexture() const;
  vtkTextureObject* GetCellVelocityTexture() const;
  /** Draw calls (layered passes) of the last Step(). */
  int GetLastPassCount() const;
  void Release();

private:
  class Internals;
  std::unique_ptr<Internals> Impl;
};
}
}

#endif
