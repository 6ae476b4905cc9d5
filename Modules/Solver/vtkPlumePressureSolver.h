/**
 * @class   vtkPlumePressureSolver
 * @brief   the pressure Poisson equation of a MAC-grid smoke simulation
 *
 * The unknowns are one value q per cell of an nx × ny × nz cell grid with
 * spacings hx, hy, hz. Each cell is fluid or solid. Between two fluid cells
 * the face is open; faces touching a solid cell are walls; the faces on the
 * domain's six sides are walls unless that side is open, where q = 0 in a
 * ghost cell outside (free outflow). The operator is, for each fluid cell i,
 *
 *     (A q)_i = Σ_{non-wall faces f of i} (q_i − q_j(f)) / h_f²
 *
 * (q_j = 0 across an open domain side): the 7-point (5-point in 2D) negative
 * Laplacian, symmetric positive semi-definite. Solid cells are identity rows
 * with q = 0. Solve() finds q with A q = b to a relative residual
 * ‖b − A q‖₂ / ‖b‖₂ ≤ Tolerance over the fluid cells, starting from q = 0.
 *
 * Methods:
 *  - JACOBI: the seed's Jacobi iterations (GPU Gems ch. 38), damped by
 *    JacobiWeight: with weight 1 (the seed) the checkerboard mode of a closed
 *    box has iteration factor −1 and never converges; 0.8 damps it by 0.6 per
 *    iteration. Iterations grow with the square of the grid size.
 *  - PCG: hypre's structured conjugate gradients preconditioned by one PFMG
 *    multigrid V-cycle (semi-coarsening, Galerkin coarse operators, red-black
 *    Gauss–Seidel): iteration counts nearly independent of the grid size.
 *    The hypre set-up is kept until the problem (grid, mask, open sides) changes.
 *
 * When no side is open, A is singular (constants are in its null space): b is
 * made consistent by removing its mean over the fluid cells first (for a
 * MAC divergence that mean is zero up to rounding), and the solution's mean
 * over the fluid cells is set to zero. Jacobi runs with vtkSMPTools threads
 * (deterministic whatever the thread count: every sum is taken in a fixed
 * order); hypre runs on one MPI rank (MPI_COMM_SELF). MPI is initialised on
 * first use if the program has not done it, and finalised at exit only then.
 */
#ifndef vtkPlumePressureSolver_h
#define vtkPlumePressureSolver_h

#include "PlumeSolverModule.h" // For export macro
#include "vtkObject.h"
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For std::vector

class vtkPlumeParameterTable;

class PLUMESOLVER_EXPORT vtkPlumePressureSolver : public vtkObject
{
public:
  static vtkPlumePressureSolver* New();
  vtkTypeMacro(vtkPlumePressureSolver, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The declaration of this class's user parameters. */
  VTK_WRAPEXCLUDE static const vtkPlumeParameterTable& GetParameterTable();

  enum Methods
  {
    JACOBI = 0,
    PCG = 1
  };

  ///@{
  /** JACOBI or PCG (default PCG). */
  vtkSetClampMacro(Method, int, JACOBI, PCG);
  vtkGetMacro(Method, int);
  ///@}

  ///@{
  /** Relative residual ‖b − A q‖₂ / ‖b‖₂ to reach (default 1e-6); 0 runs MaximumIterations. */
  vtkSetClampMacro(Tolerance, double, 0.0, 1.0);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /** Most iterations per solve (default 1000). */
  vtkSetClampMacro(MaximumIterations, int, 1, 10000000);
  vtkGetMacro(MaximumIterations, int);
  ///@}

  ///@{
  /**
   * PCG: red-black Gauss–Seidel sweeps before and after the coarse-grid
   * correction on each level of the PFMG V-cycle (the same number both ways:
   * CG needs a symmetric preconditioner) (default 2). More sweeps cost more
   * per iteration but need fewer iterations: measured on the bench's closed
   * box with a sphere to 1e-6, 1 sweep takes 15 / 16 / 18 iterations at
   * 64³ / 128³ / 256³, 2 sweeps 10 / 10 / 11, in less time per solve.
   */
  vtkSetClampMacro(SmoothingSweeps, int, 1, 10);
  vtkGetMacro(SmoothingSweeps, int);
  ///@}

  ///@{
  /** Damping ω of the Jacobi iterations, q ← q + ω (Jacobi(q) − q) (default 0.8; the seed's is 1). */
  vtkSetClampMacro(JacobiWeight, double, 0.05, 1.0);
  vtkGetMacro(JacobiWeight, double);
  ///@}

  /**
   * The problem: cell counts (nz = 1 for 2D), spacings, solid flags per cell
   * (x fastest; nullptr = all fluid) and which domain sides are open
   * (x−, x+, y−, y+, z−, z+). The mask is copied. Re-does the set-up only
   * if something changed.
   */
  VTK_WRAPEXCLUDE void SetProblem(
    const int cells[3], const double spacing[3], const unsigned char* solid, const bool open[6]);

  /**
   * Solves A q = b (b and q have one value per cell; q's start value is
   * ignored: the solve starts from 0). Returns false, with a message in
   * GetLastError(), if the iterations produced NaN/Inf or the residual grew a
   * thousandfold; not reaching Tolerance within MaximumIterations is not an
   * error (GetLastConverged() tells).
   */
  VTK_WRAPEXCLUDE bool Solve(const double* b, double* q);

  /** A q (one value per cell; 0 in solid cells). */
  VTK_WRAPEXCLUDE void Apply(const double* q, double* result) const;

  /** ‖b − A q‖₂ / ‖b‖₂ over the fluid cells (0 if b = 0), summed in a fixed order. */
  VTK_WRAPEXCLUDE double RelativeResidual(const double* b, const double* q) const;

  ///@{
  /** Outcome of the last Solve(). */
  vtkGetMacro(LastIterations, int);
  vtkGetMacro(LastRelativeResidual, double);
  vtkGetMacro(LastConverged, bool);
  vtkGetMacro(LastSetupSeconds, double);
  vtkGetMacro(LastSolveSeconds, double);
  const char* GetLastError() const { return this->LastError.c_str(); }
  ///@}

  /** True when the domain has no open side (A is singular, the solution's mean is zero). */
  bool IsClosed() const;

protected:
  vtkPlumePressureSolver();
  ~vtkPlumePressureSolver() override;

  bool SolveJacobi(const double* b, double* q);
  bool SolvePCG(const double* b, double* q);
  /** Sets up hypre's matrix, vectors and solver for the current problem. */
  bool SetupHypre();
  void ReleaseHypre();
  /** Removes the mean over fluid cells (closed domains). */
  void RemoveMean(double* values) const;

  int Method = PCG;
  double Tolerance = 1e-6;
  int MaximumIterations = 1000;
  double JacobiWeight = 0.8;
  int SmoothingSweeps = 2;

  int Cells[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
  bool Open[6] = { false, false, false, false, false, false };
  std::vector<unsigned char> Solid;
  /** 1 / h² per axis, and the diagonal of A per cell (0 in solid cells). */
  double InvH2[3] = { 1, 1, 1 };
  std::vector<double> Diagonal;

  int LastIterations = 0;
  double LastRelativeResidual = 0;
  bool LastConverged = true;
  double LastSetupSeconds = 0;
  double LastSolveSeconds = 0;
  std::string LastError;

  struct HypreState;
  std::unique_ptr<HypreState> Hypre;

private:
  vtkPlumePressureSolver(const vtkPlumePressureSolver&) = delete;
  void operator=(const vtkPlumePressureSolver&) = delete;
};

#endif
