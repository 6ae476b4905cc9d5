/**
 * @class   vtkPlumeSmokeSolver
 * @brief   Eulerian smoke simulation as a time-aware VTK image source
 *
 * The simulation of seed 004 ("Simple Fluid Simulation", after Harris, GPU
 * Gems ch. 38), on the CPU with vtkSMPTools threads. Each step (of TimeStep
 * seconds):
 *  1. semi-Lagrangian advection of velocity, density and temperature by the
 *     old velocity (second-order midpoint back-trace, trilinear sampling),
 *     with exponential dissipation exp(−rate·dt) (the seed multiplies by a
 *     per-step factor; a rate keeps results independent of the step);
 *  2. buoyancy along Up: Buoyancy·(T − AmbientTemperature) − SmokeWeight·density
 *     (hot smoke rises, dense cool smoke sinks);
 *     then, if VorticityConfinement > 0, vorticity confinement;
 *  3. impulses: inside each source's sphere (at least the cell containing its
 *     centre) density and temperature are set to the source's values, and
 *     the velocity too if the source's velocity is not zero; then the
 *     points of input port 2 inject smoke mass at a rate (see SetSourcePointsData);
 *  4. projection: the divergence of the velocity, a pressure Poisson solve
 *     (vtkPlumePressureSolver: the seed's Jacobi iterations or hypre's
 *     PFMG-preconditioned CG) and the subtraction of the pressure gradient.
 *
 * Grid: a MAC (staggered) grid, not the seed's collocated one. The output
 * image's points are the centres of the simulation cells (density,
 * temperature, pressure live there); each velocity component lives on the
 * faces normal to it, half a spacing between points. The domain walls lie
 * half a spacing outside the outermost points. Why: on a MAC grid the
 * divergence of the projected velocity is exactly the residual of the
 * pressure solve (the collocated scheme's central differences leave a
 * divergence that no number of iterations removes, and its wide Laplacian
 * decouples odd and even cells into a checkerboard); a wall is exactly a face
 * whose normal velocity is zero; and buoyancy that depends on height alone (a
 * resting stratified atmosphere) is a discrete gradient that the projection
 * removes completely, so fluid at rest stays at rest. Output velocity is the
 * average of the two faces around each point.
 *
 * Boundaries: the six domain sides are closed walls (zero normal velocity)
 * unless named in OpenFaces (free outflow: pressure 0 outside). Obstacles are
 * cells marked solid: spheres and boxes added here, and/or the point array
 * ObstacleArrayName (> 0.5 = solid) of an optional input image on port 0,
 * sampled at the nearest input point; their faces have zero velocity and
 * their cells no smoke. A 2D grid (Dimensions[2] = 1) is simulated in x–y;
 * its z sides are walls whatever OpenFaces says, and if Up has no x–y part,
 * buoyancy acts along +y.
 *
 * Time: the source advertises TIME_STEPS k·TimeStep for k = 0 ..
 * NumberOfTimeSteps and TIME_RANGE. A new request for time t brings the
 * simulation to step round(t / TimeStep): later steps are computed from the
 * current state; an earlier one restarts from step 0 and recomputes (the
 * result is deterministic, so the same step always gives the same data; no
 * history is cached, which would cost a full state per step). A request for
 * the same time as the last one processed does not move the simulation, so
 * Step()/Advance() can be mixed with the pipeline. Without a time request,
 * the output is the current state. Changing the grid, the open faces or the
 * obstacles restarts the simulation; other parameters apply from the next step.
 *
 * Backends: the CPU (vtkSMPTools threads; every feature) or, with Backend
 * GPU, the seed's fragment-shader passes (see SetBackend): the state then
 * lives in float 3D textures and is read back only when the output, a
 * checkpoint or the state accessors need it.
 *
 * Output point arrays: velocity (3 components), density, temperature,
 * pressure, divergence (of the output velocity: the projection's residual),
 * obstacle (1 = solid). Scalars: density. Vectors: velocity.
 * Results do not depend on the number of threads.
 */
#ifndef vtkPlumeSmokeSolver_h
#define vtkPlumeSmokeSolver_h

#include "PlumeSolverModule.h" // For export macro
#include "vtkImageAlgorithm.h"
#include "vtkSmartPointer.h"  // For vtkSmartPointer
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <string> // For std::string
#include <vector> // For std::vector

class vtkAlgorithmOutput;
class vtkDataArray;
class vtkDataObject;
class vtkImageData;
class vtkPlumeParameterTable;
class vtkPlumePressureSolver;
class vtkPolyData;
class vtkPlumeTextureHandOver;
class vtkRenderWindow;

class PLUMESOLVER_EXPORT vtkPlumeSmokeSolver : public vtkImageAlgorithm
{
public:
  static vtkPlumeSmokeSolver* New();
  vtkTypeMacro(vtkPlumeSmokeSolver, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The declaration of this class's user parameters (scene type "smoke"). */
  VTK_WRAPEXCLUDE static const vtkPlumeParameterTable& GetParameterTable();

  ///@{
  /** Grid points (= simulation cells) along x, y, z (default 48, 48, 64); z = 1 for 2D. */
  vtkSetVector3Macro(Dimensions, int);
  vtkGetVector3Macro(Dimensions, int);
  ///@}

  ///@{
  /** Position of the first point (default 0, 0, 0). */
  vtkSetVector3Macro(Origin, double);
  vtkGetVector3Macro(Origin, double);
  ///@}

  ///@{
  /** Distance between points (default 0.02, 0.02, 0.02). */
  vtkSetVector3Macro(Spacing, double);
  vtkGetVector3Macro(Spacing, double);
  ///@}

  ///@{
  /** Seconds per step (default 0.02). Semi-Lagrangian advection is stable at any CFL number. */
  vtkSetMacro(TimeStep, double);
  vtkGetMacro(TimeStep, double);
  ///@}

  ///@{
  /** Steps advertised as TIME_STEPS (default 200). Explicit stepping can go past them. */
  vtkSetClampMacro(NumberOfTimeSteps, int, 1, 10000000);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

  enum AdvectionSchemes
  {
    SEMI_LAGRANGIAN = 0,
    MACCORMACK = 1
  };

  ///@{
  /**
   * SEMI_LAGRANGIAN (the seed's, default) or MACCORMACK (Selle et al. 2008:
   * a forward-and-back round trip corrects the first-order error, clamped to
   * the sampled values; less numerical diffusion, twice the advection cost).
   */
  vtkSetClampMacro(AdvectionScheme, int, SEMI_LAGRANGIAN, MACCORMACK);
  vtkGetMacro(AdvectionScheme, int);
  ///@}

  ///@{
  /** Upward acceleration per unit of temperature above ambient (default 1; Harris' σ). */
  vtkSetMacro(Buoyancy, double);
  vtkGetMacro(Buoyancy, double);
  ///@}

  ///@{
  /** Downward acceleration per unit of smoke density (default 0.05; Harris' κ). */
  vtkSetMacro(SmokeWeight, double);
  vtkGetMacro(SmokeWeight, double);
  ///@}

  ///@{
  /** Temperature of the air at rest (default 0): the initial temperature and buoyancy's reference. */
  vtkSetMacro(AmbientTemperature, double);
  vtkGetMacro(AmbientTemperature, double);
  ///@}

  ///@{
  /** Direction buoyancy acts along (default 0, 0, 1; normalised when used). */
  vtkSetVector3Macro(Up, double);
  vtkGetVector3Macro(Up, double);
  ///@}

  ///@{
  /**
   * Vorticity confinement strength ε (default 0 = off, as the seed): adds
   * ε·h·(N × ω) with ω = ∇×u and N = ∇|ω| / |∇|ω||, putting back the small
   * swirls that numerical diffusion removes (Fedkiw, Stam, Jensen 2001).
   */
  vtkSetClampMacro(VorticityConfinement, double, 0.0, 1e6);
  vtkGetMacro(VorticityConfinement, double);
  ///@}

  ///@{
  /** Decay rates per second of density, of temperature (towards ambient) and of velocity (default 0, 0, 0). */
  vtkSetClampMacro(DensityDissipation, double, 0.0, 1e6);
  vtkGetMacro(DensityDissipation, double);
  vtkSetClampMacro(TemperatureDissipation, double, 0.0, 1e6);
  vtkGetMacro(TemperatureDissipation, double);
  vtkSetClampMacro(VelocityDissipation, double, 0.0, 1e6);
  vtkGetMacro(VelocityDissipation, double);
  ///@}

  ///@{
  /**
   * Keep the smoke's total mass through advection (default false, as the
   * seed): semi-Lagrangian and MacCormack advection are not conservative
   * (measured over 1000 steps of a hot blob mixing in a closed 16x16x20 box:
   * −18 % and +99 %); with this on, density after advection is scaled so
   * that its sum is the sum before it (times the dissipation's decay). Only
   * in a closed domain (no open sides), where advection can neither bring
   * smoke in nor carry it out.
   */
  vtkSetMacro(ConserveMass, bool);
  vtkGetMacro(ConserveMass, bool);
  vtkBooleanMacro(ConserveMass, bool);
  ///@}

  ///@{
  /**
   * Domain sides that are open (free outflow), e.g. "zmax" or "xmin,xmax,zmax";
   * names: xmin xmax ymin ymax zmin zmax, or "all" (default "": a closed box).
   */
  vtkSetStdStringFromCharMacro(OpenFaces);
  vtkGetCharFromStdStringMacro(OpenFaces);
  ///@}

  ///@{
  /** Point array of the optional input image marking obstacles (> 0.5 = solid; default "obstacle"). */
  vtkSetStdStringFromCharMacro(ObstacleArrayName);
  vtkGetCharFromStdStringMacro(ObstacleArrayName);
  ///@}

  ///@{
  /**
   * Virtual smoke in a given flow: with an image on input port 1
   * (SetVelocityConnection), each face takes its component of that image's
   * point array VelocityArrayName (default "": its active vectors),
   * trilinear between its points (zero outside it), once when the input
   * changes; the field is projected once if ProjectExternalVelocity (default
   * true), and then never evolves: density and temperature are advected
   * passively and sources emit, but buoyancy, confinement and the pressure
   * solve are skipped. Points whose vtkValidPointMask is 0 (a CFD mesh
   * resampled onto an image) are solid.
   *
   * A time series: if the input advertises TIME_STEPS (a reader of a .pvd
   * or an OpenFOAM case, through a resampling to an image), the smoke moves
   * with the flow of the matching time: each step of dt from t uses the
   * field at t + dt/2 (exact for a field linear in time, like the midpoint
   * rule in space), linear in time between the two written times around it;
   * before the first and after the last written time the field is held.
   * Simulation time t is the flow's time t + VelocityTimeOffset. Each
   * written time is fetched from the input (an update of the upstream
   * algorithm at that time), sampled and projected when a step first needs
   * it; two are kept. Obstacles from vtkValidPointMask come from the first
   * frame read. A static field (one time or none) is asked for no time.
   */
  void SetVelocityConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetVelocityData(vtkDataObject* image) { this->SetInputData(1, image); }
  vtkSetStdStringFromCharMacro(VelocityArrayName);
  vtkGetCharFromStdStringMacro(VelocityArrayName);
  vtkSetMacro(ProjectExternalVelocity, bool);
  vtkGetMacro(ProjectExternalVelocity, bool);
  /** Whether the velocity comes from input port 1 (after Initialize() or an update). */
  bool HasExternalVelocity() const { return !this->ExternalU[0].empty(); }
  /** Flow time at simulation time 0, for a time series on port 1 (default 0). */
  vtkSetMacro(VelocityTimeOffset, double);
  vtkGetMacro(VelocityTimeOffset, double);
  /** Written times of the velocity input (after an update; empty for a static field). */
  const std::vector<double>& GetVelocityTimes() const { return this->VelocityTimes; }
  /** Whether the velocity input is a time series (more than one written time). */
  bool IsVelocityTimeSeries() const { return this->VelocityTimes.size() > 1; }
  /** How many written times of a velocity time series were fetched and sampled so far. */
  vtkGetMacro(NumberOfVelocityFramesRead, int);
  ///@}

  ///@{
  /** Pressure solve (forwarded to GetPressureSolver()): method JACOBI (0) or PCG (1) (default PCG). */
  void SetPressureMethod(int method);
  int GetPressureMethod();
  /** Relative residual the pressure solve stops at (default 1e-6). */
  void SetPressureTolerance(double tolerance);
  double GetPressureTolerance();
  /** Most iterations per pressure solve (default 1000). */
  void SetPressureMaximumIterations(int iterations);
  int GetPressureMaximumIterations();
  /** Damping of the Jacobi iterations (default 0.8). */
  void SetPressureJacobiWeight(double weight);
  double GetPressureJacobiWeight();
  /** Smoothing sweeps of the PCG's multigrid preconditioner, 1..10 (default 2). */
  void SetPressureSmoothingSweeps(int sweeps);
  int GetPressureSmoothingSweeps();
  ///@}

  enum Backends
  {
    BACKEND_CPU = 0,
    BACKEND_GPU = 1
  };

  ///@{
  /**
   * BACKEND_CPU (default) or BACKEND_GPU: the seed's step as fragment-shader
   * passes over float 3D textures (one layered draw per pass fills a whole 3D
   * texture: a geometry shader picks gl_Layer; ping-pong textures as the
   * seed's slabs): semi-Lagrangian advection of density, temperature and
   * velocity, buoyancy, the spherical sources (AddSource, at most 16),
   * divergence, damped Jacobi iterations (JacobiWeight) from q = 0 and the
   * gradient subtraction, on the same MAC grid with the same walls, open
   * sides and static obstacles as the CPU backend's Jacobi path, which it
   * equals to float rounding (TestSmokeSolverGPU). The Jacobi solve runs
   * exactly PressureMaximumIterations iterations (PressureTolerance is not
   * checked: a residual needs a reduction over the grid; in a closed box the
   * pressure's mean over the fluid is removed when it is read back, as the
   * CPU solve does). Whatever PressureMethod says, the GPU runs Jacobi.
   * Not on the GPU (a step is refused with an error naming the setting):
   * MacCormack advection, vorticity confinement, ConserveMass, moving
   * obstacles, a velocity on input port 1, source points on port 2. Needs an
   * OpenGL 3.2 context: RenderWindow's, else an offscreen window of its own.
   */
  vtkSetClampMacro(Backend, int, BACKEND_CPU, BACKEND_GPU);
  vtkGetMacro(Backend, int);
  ///@}

  ///@{
  /**
   * GL context of the GPU backend (a vtkOpenGLRenderWindow). Default none: an
   * offscreen window of its own. Not owned (the window's renderers may hold a
   * mapper whose input is this solver): when the window is deleted the state
   * is read back and the GPU backend falls back to a window of its own.
   */
  void SetRenderWindow(vtkRenderWindow* window);
  vtkRenderWindow* GetRenderWindow();
  ///@}

  ///@{
  /**
   * GPU backend with RenderWindow set (default false): the output's density
   * and velocity arrays carry a vtkPlumeTextureHandOver of the solver's own
   * textures (density: the state's R32F texture; velocity: an RGBA32F texture
   * of the cell-centred velocity, a = 1, computed on the GPU and the one the
   * output array is read back from), so vtkPlumeVolumeMapper and
   * vtkPlumeVelocityGlyphMapper rendering in that window bind them instead of
   * uploading the arrays. The next step revokes them (the textures are
   * overwritten); the arrays stay complete for every other consumer.
   */
  vtkSetMacro(GPUHandOver, bool);
  vtkGetMacro(GPUHandOver, bool);
  vtkBooleanMacro(GPUHandOver, bool);
  ///@}

  /** Layered draws (passes) of the last GPU step (0 after a CPU step). */
  vtkGetMacro(LastGPUPassCount, int);

  /** GPU backend: waits until the queued passes are done (for timing). */
  void FinishGPU();

  /** GPU backend: runs `passes` passes that only write a constant into a cell-sized texture (the floor of a pass). */
  bool RunTrivialGPUPasses(int passes);

  /** Frees the GPU backend's textures and programs (the state is read back first if only the GPU holds it). */
  void ReleaseGraphicsResources();

  /** The pressure solver (its last iteration count and residual). */
  vtkPlumePressureSolver* GetPressureSolver();

  ///@{
  /**
   * Sources, applied every step: a sphere (centre, radius) where density and
   * temperature are set to the given values, and the velocity too unless it is zero.
   */
  void AddSource(const double center[3], double radius, double density, double temperature,
    const double velocity[3]);
  void RemoveAllSources();
  int GetNumberOfSources() const { return static_cast<int>(this->Sources.size()); }
  ///@}

  ///@{
  /**
   * Sources given as points: each point of a vtkPointSet on input port 2
   * (SetSourcePointsConnection / SetSourcePointsData; e.g. inlets or fire
   * positions a CFD engineer marked in the data) is a source that every step
   * injects smoke mass at a rate, where the AddSource spheres set values:
   *  - point array SourceRateArrayName (default "rate"; else SourceRate,
   *    default 1): mass per second, mass being density × volume (model
   *    units³); each step adds rate·dt, spread evenly over the fluid cells
   *    whose centre lies within the radius (at least the cell holding the
   *    point), so the total Σ density·cell volume grows by exactly Σ rate·dt
   *    (with ConserveMass, or with no flow, nothing else changes it);
   *  - SourceTemperatureArrayName ("temperature"; else SourceTemperature,
   *    default 1): the temperature set in those cells;
   *  - SourceRadiusArrayName ("radius"; else SourceRadius, default 0 = the
   *    cell holding the point only);
   *  - SourceVelocityArrayName ("velocity", 3 components; else none): if not
   *    zero, the velocity set on the faces within the radius (at least half a
   *    spacing), as AddSource's velocity.
   * An array missing from the points gives its default; one with the wrong
   * number of components, a non-finite value, or a negative rate or radius
   * is an error naming the point and the value. Points outside the domain
   * (beyond the walls) emit nothing; neither do points whose cells are all
   * solid. The points are those of the last pipeline update (explicit
   * Step() calls use them as they are); changing them does not restart the
   * simulation.
   */
  void SetSourcePointsConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(2, output); }
  void SetSourcePointsData(vtkDataObject* points) { this->SetInputData(2, points); }
  vtkSetStdStringFromCharMacro(SourceRateArrayName);
  vtkGetCharFromStdStringMacro(SourceRateArrayName);
  vtkSetStdStringFromCharMacro(SourceTemperatureArrayName);
  vtkGetCharFromStdStringMacro(SourceTemperatureArrayName);
  vtkSetStdStringFromCharMacro(SourceRadiusArrayName);
  vtkGetCharFromStdStringMacro(SourceRadiusArrayName);
  vtkSetStdStringFromCharMacro(SourceVelocityArrayName);
  vtkGetCharFromStdStringMacro(SourceVelocityArrayName);
  vtkSetMacro(SourceRate, double);
  vtkGetMacro(SourceRate, double);
  vtkSetMacro(SourceTemperature, double);
  vtkGetMacro(SourceTemperature, double);
  vtkSetMacro(SourceRadius, double);
  vtkGetMacro(SourceRadius, double);
  /** Smoke mass (Σ density · cell volume) the point sources injected in the last step. */
  vtkGetMacro(LastInjectedMass, double);
  ///@}

  ///@{
  /**
   * Solid obstacles (restart the simulation): a cell whose centre is inside
   * is solid. A box is [xmin, xmax, ymin, ymax, zmin, zmax]. A surface is a
   * closed polygonal surface (a vtkPolyData, copied), voxelised with
   * vtkSelectEnclosedPoints (in VTK 9.1 and ParaView 5.11's VTK alike). With a velocity (default none = at rest) the
   * obstacle translates: at time t it lies at its given place + velocity·t,
   * the solid cells are voxelised again every step (and the pressure solve
   * set up again), and the faces between its solid cells and the fluid take
   * its velocity (the boundary condition that drags the fluid; the
   * projection then makes the flow go around it). Cells it leaves are
   * fluid with no smoke, ambient temperature and the velocity the advection
   * brings. Obstacles only move in the solver's own flow; in a given flow
   * (port 1) they stay at their place.
   */
  void AddObstacleSphere(const double center[3], double radius, const double velocity[3] = nullptr);
  void AddObstacleBox(const double bounds[6], const double velocity[3] = nullptr);
  void AddObstacleSurface(vtkPolyData* surface, const double velocity[3] = nullptr);
  void RemoveAllObstacles();
  int GetNumberOfObstacles() const { return static_cast<int>(this->Obstacles.size()); }
  ///@}

  ///@{
  /**
   * Explicit stepping: Step() advances by TimeStep, Advance(dt) by one step of
   * dt. The simulation starts (or restarts after a grid change) at the first
   * call; an obstacle input image is the one of the last pipeline update.
   * Return false, with GetLastError() set, on a bad set-up or a failed solve.
   */
  bool Step();
  bool Advance(double dt);
  /** Back to step 0: fluid at rest, no smoke, ambient temperature. */
  void Reset();
  ///@}

  ///@{
  /**
   * Checkpoint: the full state (velocity faces, density, temperature,
   * pressure, solid cells, step and time) in a binary file. Reading it back
   * into a solver with the same grid, open sides and obstacles continues
   * bit for bit as the original would have; anything else is refused with
   * GetLastError() naming the difference. Return false on failure.
   */
  bool WriteCheckpoint(const char* path);
  bool ReadCheckpoint(const char* path);
  ///@}

  ///@{
  /** Current simulation time, current step, and steps computed since construction (restarts recompute). */
  vtkGetMacro(SimulationTime, double);
  vtkGetMacro(CurrentStep, vtkIdType);
  vtkGetMacro(StepsTaken, vtkIdType);
  ///@}

  /** The last error ("" if none): one line naming the problem and the value. */
  const char* GetLastError() const { return this->LastError.c_str(); }

  ///@{
  /**
   * Direct access to the state (after Initialize() or a step), for tests and
   * hand-made initial conditions. Cells are x fastest; the face grid of axis
   * d has Dimensions[d] + 1 entries along d (face i lies at Origin + (i − ½)·Spacing).
   * Solid flags per cell; Pressure holds p·dt of the last projection.
   */
  bool Initialize();
  VTK_WRAPEXCLUDE double* GetFaceVelocityData(int axis);
  VTK_WRAPEXCLUDE double* GetDensityData();
  VTK_WRAPEXCLUDE double* GetTemperatureData();
  VTK_WRAPEXCLUDE double* GetPressureData();
  VTK_WRAPEXCLUDE const unsigned char* GetSolidData();
  /** Whether the face (axis, i, j, k) is a wall (domain side or touching a solid cell). */
  bool IsWallFace(int axis, int i, int j, int k) const;
  /** Projects the current face velocities (divergence, pressure solve, gradient subtraction). */
  bool Project();
  /** Divergence of the face velocities per cell (0 in solid cells). */
  VTK_WRAPEXCLUDE void ComputeDivergence(double* divergence) const;
  ///@}

protected:
  vtkPlumeSmokeSolver();
  ~vtkPlumeSmokeSolver() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  /** An executive whose "returned failure for request" dump is silenced (the error itself is reported once). */
  vtkExecutive* CreateDefaultExecutive() override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /** "" if the set-up is valid, else one line naming the problem and the value. */
  std::string Validate() const;
  /** Validates and (re)allocates the state if the grid, open faces or obstacles changed. */
  bool EnsureState();
  void FillOutput(vtkImageData* output);

  // GPU backend
  void OnRenderWindowDeleted(); // the state leaves the window's context before it goes
  class GPUBackend;
  GPUBackend* GPU = nullptr;
  int Backend = BACKEND_CPU;
  bool GPUHandOver = false;
  int LastGPUPassCount = 0;
  bool GPUHoldsState = false; // the GPU's state is newer than the CPU's (read back before use)
  bool GPUUpToDate = false;   // the GPU's state equals the CPU's (no upload needed)
  bool GPUSourcesReady = false; // the GPU has the source masks of GPUSourceSignature
  std::vector<double> GPUSourceSignature;
  /** "" if the GPU backend can run the current set-up, else one line naming what it lacks. */
  std::string GPUUnsupported();
  bool AdvanceGPU(double dt);
  /** Reads the GPU's state back into the CPU state if the GPU holds a newer one. */
  bool SyncFromGPU();
  /** The CPU state was changed (reset, checkpoint, accessors): the GPU must upload it again. */
  void InvalidateGPUState();
  void RevokeHandOvers();

  /**
   * Advects `source` (cells if axis < 0, else the faces normal to axis) by
   * the current velocity over dt into `result`, then decays it towards
   * `target` at `rate`; walls / solid cells get 0 / target.
   */
  void Advect(const std::vector<double>& source, int axis, double dt, double rate, double target,
    std::vector<double>& result) const;
  void ApplyBuoyancy(double dt);
  void ApplySources();
  /** The point sources of input port 2 (false, with LastError, on bad values). */
  bool ApplyPointSources(double dt);
  void ApplyVorticityConfinement(double dt);

  int Dimensions[3] = { 48, 48, 64 };
  double Origin[3] = { 0, 0, 0 };
  double Spacing[3] = { 0.02, 0.02, 0.02 };
  double TimeStep = 0.02;
  int NumberOfTimeSteps = 200;
  int AdvectionScheme = SEMI_LAGRANGIAN;
  double Buoyancy = 1.0;
  double SmokeWeight = 0.05;
  double AmbientTemperature = 0.0;
  double Up[3] = { 0, 0, 1 };
  double VorticityConfinement = 0;
  double DensityDissipation = 0;
  double TemperatureDissipation = 0;
  double VelocityDissipation = 0;
  bool ConserveMass = false;
  std::string OpenFaces;
  std::string ObstacleArrayName = "obstacle";

  struct Source
  {
    double Center[3];
    double Radius;
    double Density;
    double Temperature;
    double Velocity[3];
  };
  std::vector<Source> Sources;
  /** Whether source `s` sets cell (i, j, k) / the face (axis d, i, j, k): one test for both backends. */
  bool SourceCoversCell(const Source& s, int i, int j, int k) const;
  bool SourceCoversFace(const Source& s, int d, int i, int j, int k) const;
  std::string SourceRateArrayName = "rate";
  std::string SourceTemperatureArrayName = "temperature";
  std::string SourceRadiusArrayName = "radius";
  std::string SourceVelocityArrayName = "velocity";
  double SourceRate = 1.0;
  double SourceTemperature = 1.0;
  double SourceRadius = 0.0;
  double LastInjectedMass = 0.0;
  enum ObstacleKind
  {
    SPHERE,
    BOX,
    SURFACE
  };
  struct Obstacle
  {
    ObstacleKind Kind;
    double Values[6]; // sphere: centre, radius; box: bounds
    double Velocity[3];
    vtkSmartPointer<vtkPolyData> Surface;
  };
  std::vector<Obstacle> Obstacles;
  bool HasMovingObstacles() const;
  /** Solid = StaticSolid (the input images' cells) + the obstacles at time t; SolidOwner = obstacle + 1. */
  bool VoxeliseObstacles(double t);
  /** Faces between a moving obstacle's cells and the fluid take its velocity; other walls 0. */
  void ApplyObstacleVelocity();
  std::vector<unsigned char> StaticSolid;
  std::vector<int> SolidOwner;
  unsigned long ObstacleVersion = 0;
  vtkSmartPointer<vtkImageData> ObstacleInput;
  vtkSmartPointer<vtkImageData> VelocityInput;
  std::string VelocityArrayName;
  bool ProjectExternalVelocity = true;
  std::vector<double> ExternalU[3];
  /** Samples `velocity` of `image` onto the faces (projected if asked) into `faces`. */
  bool SampleExternalVelocity(vtkImageData* image, vtkDataArray* velocity, std::vector<double> faces[3]);
  // A time series on port 1: its written times, the two frames kept
  // (sampled faces of written time Index), the time the input holds.
  double VelocityTimeOffset = 0;
  std::vector<double> VelocityTimes;
  struct VelocityFrame
  {
    int Index = -1;
    std::vector<double> U[3];
  };
  VelocityFrame Frames[2];
  double HeldVelocityTime;
  int NumberOfVelocityFramesRead = 0;
  /** The frame of written time `index` (fetched from the input if not kept; the frame `keep` stays). */
  const VelocityFrame* GetVelocityFrame(int index, int keep);
  /** Sets the faces (U and ExternalU) to the time series' velocity at simulation time t. */
  bool SetVelocityAtTime(double t);

  vtkSmartPointer<vtkPlumePressureSolver> Pressure;

  // State
  std::vector<double> Signature; // what the state was allocated for
  int Cells[3] = { 0, 0, 0 };
  double H[3] = { 1, 1, 1 };
  double O[3] = { 0, 0, 0 };
  bool Open[6] = { false, false, false, false, false, false };
  std::vector<double> U[3];
  std::vector<double> Density;
  std::vector<double> Temperature;
  std::vector<double> Q;
  std::vector<unsigned char> Solid;
  double LastProjectionDt = 0;

  double SimulationTime = 0;
  vtkIdType CurrentStep = 0;
  vtkIdType StepsTaken = 0;
  double LastRequestedTime;
  std::string LastError;

private:
  vtkPlumeSmokeSolver(const vtkPlumeSmokeSolver&) = delete;
  void operator=(const vtkPlumeSmokeSolver&) = delete;
};

#endif
