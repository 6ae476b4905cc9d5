#include "vtkPlumePressureSolver.h"

#include "vtkObjectFactory.h"
#include "vtkPlumeParameterTable.h"

#include "plumeGridRows.h"

#include <HYPRE_struct_ls.h>
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>

vtkStandardNewMacro(vtkPlumePressureSolver);

using plume::smoke::ForRows;

namespace
{
double Seconds()
{
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

// hypre needs MPI. A plain serial program has not initialised it: do it
// here, once, and finalise at exit only what we initialised (a host such as
// ParaView initialises and finalises MPI itself).
bool InitializedMPIHere = false;
void FinalizeAtExit()
{
  HYPRE_Finalize();
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (InitializedMPIHere && !finalized)
  {
    MPI_Finalize();
  }
}
void EnsureMPIAndHypre()
{
  static const bool ready = [] {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized)
    {
      int provided = 0;
      MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
      InitializedMPIHere = true;
    }
    HYPRE_Init();
    std::atexit(FinalizeAtExit);
    return true;
  }();
  (void)ready;
}
}

//------------------------------------------------------------------------------
struct vtkPlumePressureSolver::HypreState
{
  HYPRE_StructGrid Grid = nullptr;
  HYPRE_StructStencil Stencil = nullptr;
  HYPRE_StructMatrix Matrix = nullptr;
  HYPRE_StructVector B = nullptr;
  HYPRE_StructVector X = nullptr;
  HYPRE_StructSolver Solver = nullptr;
  HYPRE_StructSolver Preconditioner = nullptr;
  double Tolerance = -1;
  int MaximumIterations = -1;
  int SmoothingSweeps = -1;
  std::vector<double> Buffer;
};

//------------------------------------------------------------------------------
const vtkPlumeParameterTable& vtkPlumePressureSolver::GetParameterTable()
{
  static const vtkPlumeParameterTable table = [] {
    using T = vtkPlumePressureSolver;
    vtkPlumeParameterTable t("vtkPlumePressureSolver", "");
    t.Choice("pressure_solver", "Method", "pcg")
      .Choice("jacobi", JACOBI, "the seed's Jacobi iterations (damped by jacobi_weight); iterations grow with the grid")
      .Choice("pcg", PCG, "hypre's PFMG-multigrid-preconditioned conjugate gradients; iterations nearly flat in the grid size")
      .Panel("Pressure")
      .Doc("Method solving the pressure Poisson equation of the projection.")
      .Bind(&T::SetMethod, &T::GetMethod);
    t.Real("pressure_tolerance", "Tolerance", 1e-6)
      .Between(0.0, 1.0)
      .Panel("Pressure")
      .Doc("Relative residual ‖b − Aq‖ / ‖b‖ at which the pressure solve stops; 0 runs pressure_max_iterations.")
      .Bind(&T::SetTolerance, &T::GetTolerance);
    t.Integer("pressure_max_iterations", "MaximumIterations", 1000)
      .Between(1, 10000000)
      .Panel("Pressure")
      .Doc("Most iterations of one pressure solve (the seed runs 40 Jacobi iterations).")
      .Bind(&T::SetMaximumIterations, &T::GetMaximumIterations);
    t.Integer("pressure_smoothing_sweeps", "SmoothingSweeps", 2)
      .Between(1, 10)
      .Panel("Pressure")
      .Advanced()
      .Doc("PCG: Gauss-Seidel sweeps before and after the coarse-grid correction in each multigrid level; 2 "
           "needs fewer iterations than 1 (10 against 15-18 from 64^3 to 256^3) in less time per solve.")
      .Bind(&T::SetSmoothingSweeps, &T::GetSmoothingSweeps);
    t.Real("jacobi_weight", "JacobiWeight", 0.8)
      .Between(0.05, 1.0)
      .Panel("Pressure")
      .Advanced()
      .Doc("Damping of the Jacobi iterations; 1 is the seed's, which never converges in a closed box.")
      .Bind(&T::SetJacobiWeight, &T::GetJacobiWeight);
    return t;
  }();
  return table;
}

//------------------------------------------------------------------------------
vtkPlumePressureSolver::vtkPlumePressureSolver()
{
  GetParameterTable().ApplyDefaults(this);
}

vtkPlumePressureSolver::~vtkPlumePressureSolver()
{
  this->ReleaseHypre();
}

bool vtkPlumePressureSolver::IsClosed() const
{
  return std::none_of(this->Open, this->Open + 6, [](bool o) { return o; });
}

//------------------------------------------------------------------------------
void vtkPlumePressureSolver::SetProblem(
  const int cells[3], const double spacing[3], const unsigned char* solid, const bool open[6])
{
  const size_t count = size_t(cells[0]) * cells[1] * cells[2];
  bool same = std::equal(cells, cells + 3, this->Cells) && std::equal(spacing, spacing + 3, this->Spacing) &&
    std::equal(open, open + 6, this->Open) && this->Solid.size() == count;
  if (same)
  {
    same = solid ? std::equal(solid, solid + count, this->Solid.begin())
                 : std::all_of(this->Solid.begin(), this->Solid.end(), [](unsigned char s) { return s == 0; });
  }
  if (same)
  {
    return;
  }
  this->ReleaseHypre();
  std::copy(cells, cells + 3, this->Cells);
  std::copy(spacing, spacing + 3, this->Spacing);
  std::copy(open, open + 6, this->Open);
  if (solid)
  {
    this->Solid.assign(solid, solid + count);
  }
  else
  {
    this->Solid.assign(count, 0);
  }
  for (int d = 0; d < 3; ++d)
  {
    this->InvH2[d] = 1.0 / (spacing[d] * spacing[d]);
  }
  // A 2D grid (one cell along z) has wall faces in z whatever Open says.
  if (cells[2] == 1)
  {
    this->Open[4] = this->Open[5] = false;
  }
  this->Diagonal.assign(count, 0.0);
  const int* n = this->Cells;
  ForRows(n, [&](int j, int k) {
    for (int i = 0; i < n[0]; ++i)
    {
      const size_t c = i + size_t(n[0]) * (j + size_t(n[1]) * k);
      if (this->Solid[c])
      {
        continue;
      }
      const int idx[3] = { i, j, k };
      const size_t stride[3] = { 1, size_t(n[0]), size_t(n[0]) * n[1] };
      double diagonal = 0;
      for (int d = 0; d < 3; ++d)
      {
        // minus side
        if (idx[d] > 0)
        {
          diagonal += this->Solid[c - stride[d]] ? 0.0 : this->InvH2[d];
        }
        else if (this->Open[2 * d])
        {
          diagonal += this->InvH2[d];
        }
        // plus side
        if (idx[d] < n[d] - 1)
        {
          diagonal += this->Solid[c + stride[d]] ? 0.0 : this->InvH2[d];
        }
        else if (this->Open[2 * d + 1])
        {
          diagonal += this->InvH2[d];
        }
      }
      this->Diagonal[c] = diagonal;
    }
  });
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPlumePressureSolver::Apply(const double* q, double* result) const
{
  const int* n = this->Cells;
  const size_t sy = size_t(n[0]), sz = size_t(n[0]) * n[1];
  ForRows(n, [&](int j, int k) {
    for (int i = 0; i < n[0]; ++i)
    {
      const size_t c = i + sy * j + sz * k;
      if (this->Diagonal[c] == 0)
      {
        result[c] = 0;
        continue;
      }
      double sum = 0;
      if (i > 0 && !this->Solid[c - 1])
        sum += this->InvH2[0] * q[c - 1];
      if (i < n[0] - 1 && !this->Solid[c + 1])
        sum += this->InvH2[0] * q[c + 1];
      if (j > 0 && !this->Solid[c - sy])
        sum += this->InvH2[1] * q[c - sy];
      if (j < n[1] - 1 && !this->Solid[c + sy])
        sum += this->InvH2[1] * q[c + sy];
      if (k > 0 && !this->Solid[c - sz])
        sum += this->InvH2[2] * q[c - sz];
      if (k < n[2] - 1 && !this->Solid[c + sz])
        sum += this->InvH2[2] * q[c + sz];
      result[c] = this->Diagonal[c] * q[c] - sum;
    }
  });
}

double vtkPlumePressureSolver::RelativeResidual(const double* b, const double* q) const
{
  const int* n = this->Cells;
  const size_t count = this->Diagonal.size();
  std::vector<double> aq(count);
  this->Apply(q, aq.data());
  std::vector<double> rr(size_t(n[1]) * n[2]), bb(rr.size());
  ForRows(n, [&](int j, int k) {
    const size_t row = j + size_t(n[1]) * k;
    double r2 = 0, b2 = 0;
    for (int i = 0; i < n[0]; ++i)
    {
      const size_t c = i + size_t(n[0]) * row;
      if (this->Diagonal[c] != 0)
      {
        const double r = b[c] - aq[c];
        r2 += r * r;
        b2 += b[c] * b[c];
      }
    }
    rr[row] = r2;
    bb[row] = b2;
  });
  double r2 = 0, b2 = 0;
  for (size_t r = 0; r < rr.size(); ++r)
  {
    r2 += rr[r];
    b2 += bb[r];
  }
  return b2 > 0 ? std::sqrt(r2 / b2) : std::sqrt(r2);
}

void vtkPlumePressureSolver::RemoveMean(double* values) const
{
  double sum = 0;
  size_t count = 0;
  for (size_t c = 0; c < this->Diagonal.size(); ++c) // sequential: a fixed order
  {
    if (this->Diagonal[c] != 0)
    {
      sum += values[c];
      ++count;
    }
  }
  if (count == 0)
  {
    return;
  }
  const double mean = sum / double(count);
  for (size_t c = 0; c < this->Diagonal.size(); ++c)
  {
    values[c] = this->Diagonal[c] != 0 ? values[c] - mean : 0.0;
  }
}

//------------------------------------------------------------------------------
bool vtkPlumePressureSolver::Solve(const double* bIn, double* q)
{
  this->LastError.clear();
  this->LastIterations = 0;
  this->LastRelativeResidual = 0;
  this->LastConverged = true;
  this->LastSetupSeconds = 0;
  this->LastSolveSeconds = 0;
  const size_t count = this->Diagonal.size();
  if (count == 0)
  {
    this->LastError = "the pressure solver has no problem set (SetProblem)";
    return false;
  }
  std::vector<double> b(bIn, bIn + count);
  for (size_t c = 0; c < count; ++c)
  {
    if (this->Diagonal[c] == 0)
    {
      b[c] = 0;
    }
    else if (!std::isfinite(b[c]))
    {
      this->LastError = "the pressure right-hand side (velocity divergence) is not finite";
      std::fill(q, q + count, 0.0);
      return false;
    }
  }
  if (this->IsClosed())
  {
    this->RemoveMean(b.data());
  }
  double b2 = 0;
  for (size_t c = 0; c < count; ++c)
  {
    b2 += b[c] * b[c];
  }
  std::fill(q, q + count, 0.0);
  if (b2 == 0)
  {
    return true;
  }
  const bool ok = this->Method == JACOBI ? this->SolveJacobi(b.data(), q) : this->SolvePCG(b.data(), q);
  if (!ok)
  {
    return false;
  }
  if (this->IsClosed())
  {
    this->RemoveMean(q);
  }
  this->LastRelativeResidual = this->RelativeResidual(b.data(), q);
  if (!std::isfinite(this->LastRelativeResidual) || this->LastRelativeResidual > 1e3)
  {
    this->LastError = "the pressure solve diverged (relative residual " +
      std::to_string(this->LastRelativeResidual) + " after " + std::to_string(this->LastIterations) +
      " iterations)";
    std::fill(q, q + count, 0.0);
    return false;
  }
  this->LastConverged = this->LastRelativeResidual <= this->Tolerance * (1 + 1e-9);
  return true;
}

//------------------------------------------------------------------------------
bool vtkPlumePressureSolver::SolveJacobi(const double* b, double* q)
{
  const double start = Seconds();
  const int* n = this->Cells;
  const size_t sy = size_t(n[0]), sz = size_t(n[0]) * n[1];
  std::vector<double> next(this->Diagonal.size(), 0.0);
  const double w = this->JacobiWeight;
  // The residual costs about one iteration: check it every few iterations.
  const int checkEvery = 10;
  for (int it = 1; it <= this->MaximumIterations; ++it)
  {
    const double* cur = q;
    ForRows(n, [&](int j, int k) {
      for (int i = 0; i < n[0]; ++i)
      {
        const size_t c = i + sy * j + sz * k;
        const double diagonal = this->Diagonal[c];
        if (diagonal == 0)
        {
          next[c] = 0;
          continue;
        }
        double sum = b[c];
        if (i > 0 && !this->Solid[c - 1])
          sum += this->InvH2[0] * cur[c - 1];
        if (i < n[0] - 1 && !this->Solid[c + 1])
          sum += this->InvH2[0] * cur[c + 1];
        if (j > 0 && !this->Solid[c - sy])
          sum += this->InvH2[1] * cur[c - sy];
        if (j < n[1] - 1 && !this->Solid[c + sy])
          sum += this->InvH2[1] * cur[c + sy];
        if (k > 0 && !this->Solid[c - sz])
          sum += this->InvH2[2] * cur[c - sz];
        if (k < n[2] - 1 && !this->Solid[c + sz])
          sum += this->InvH2[2] * cur[c + sz];
        next[c] = (1 - w) * cur[c] + w * sum / diagonal;
      }
    });
    std::copy(next.begin(), next.end(), q);
    this->LastIterations = it;
    if (this->Tolerance > 0 && (it % checkEvery == 0 || it == this->MaximumIterations))
    {
      const double r = this->RelativeResidual(b, q);
      if (!std::isfinite(r))
      {
        this->LastError = "the Jacobi iterations produced a non-finite residual after " + std::to_string(it) +
          " iterations";
        return false;
      }
      if (r <= this->Tolerance)
      {
        break;
      }
    }
  }
  this->LastSolveSeconds = Seconds() - start;
  return true;
}

//------------------------------------------------------------------------------
void vtkPlumePressureSolver::ReleaseHypre()
{
  if (!this->Hypre)
  {
    return;
  }
  HypreState& h = *this->Hypre;
  if (h.Solver)
    HYPRE_StructPCGDestroy(h.Solver);
  if (h.Preconditioner)
    HYPRE_StructPFMGDestroy(h.Preconditioner);
  if (h.X)
    HYPRE_StructVectorDestroy(h.X);
  if (h.B)
    HYPRE_StructVectorDestroy(h.B);
  if (h.Matrix)
    HYPRE_StructMatrixDestroy(h.Matrix);
  if (h.Stencil)
    HYPRE_StructStencilDestroy(h.Stencil);
  if (h.Grid)
    HYPRE_StructGridDestroy(h.Grid);
  this->Hypre.reset();
}

bool vtkPlumePressureSolver::SetupHypre()
{
  EnsureMPIAndHypre();
  this->Hypre.reset(new HypreState);
  HypreState& h = *this->Hypre;
  const int* n = this->Cells;
  const int dim = n[2] == 1 ? 2 : 3;
  HYPRE_Int lower[3] = { 0, 0, 0 };
  HYPRE_Int upper[3] = { n[0] - 1, n[1] - 1, n[2] - 1 };
  HYPRE_StructGridCreate(MPI_COMM_SELF, dim, &h.Grid);
  HYPRE_StructGridSetExtents(h.Grid, lower, upper);
  HYPRE_StructGridAssemble(h.Grid);

  // Stencil: centre, then −/+ along each axis.
  const int entries = 1 + 2 * dim;
  HYPRE_StructStencilCreate(dim, entries, &h.Stencil);
  for (int e = 0; e < entries; ++e)
  {
    HYPRE_Int offset[3] = { 0, 0, 0 };
    if (e > 0)
    {
      offset[(e - 1) / 2] = (e % 2) ? -1 : 1;
    }
    HYPRE_StructStencilSetElement(h.Stencil, e, offset);
  }
  HYPRE_StructMatrixCreate(MPI_COMM_SELF, h.Grid, h.Stencil, &h.Matrix);
  HYPRE_StructMatrixInitialize(h.Matrix);
  const size_t count = this->Diagonal.size();
  std::vector<double> values(count * entries, 0.0);
  const size_t stride[3] = { 1, size_t(n[0]), size_t(n[0]) * n[1] };
  ForRows(n, [&](int j, int k) {
    for (int i = 0; i < n[0]; ++i)
    {
      const size_t c = i + stride[1] * j + stride[2] * k;
      double* v = &values[c * entries];
      if (this->Diagonal[c] == 0)
      {
        v[0] = 1; // solid or isolated cell: q = 0
        continue;
      }
      v[0] = this->Diagonal[c];
      const int idx[3] = { i, j, k };
      for (int d = 0; d < dim; ++d)
      {
        if (idx[d] > 0 && !this->Solid[c - stride[d]])
          v[1 + 2 * d] = -this->InvH2[d];
        if (idx[d] < n[d] - 1 && !this->Solid[c + stride[d]])
          v[2 + 2 * d] = -this->InvH2[d];
      }
    }
  });
  // A closed domain makes A singular (constants in its null space), which
  // PFMG's coarsest levels do not handle: one fluid cell gets a Dirichlet
  // neighbour (q = 0 beyond it). For a consistent b (mean removed) every
  // exact solution of this system is one of A's, so the answer is the same
  // up to the constant that Solve() removes.
  if (this->IsClosed())
  {
    for (size_t c = 0; c < count; ++c)
    {
      if (this->Diagonal[c] != 0)
      {
        values[c * entries] += this->InvH2[0];
        break;
      }
    }
  }
  std::vector<HYPRE_Int> stencilIndices(entries);
  for (int e = 0; e < entries; ++e)
  {
    stencilIndices[e] = e;
  }
  HYPRE_StructMatrixSetBoxValues(h.Matrix, lower, upper, entries, stencilIndices.data(), values.data());
  HYPRE_StructMatrixAssemble(h.Matrix);

  HYPRE_StructVectorCreate(MPI_COMM_SELF, h.Grid, &h.B);
  HYPRE_StructVectorCreate(MPI_COMM_SELF, h.Grid, &h.X);
  HYPRE_StructVectorInitialize(h.B);
  HYPRE_StructVectorInitialize(h.X);
  HYPRE_StructVectorSetConstantValues(h.B, 0.0);
  HYPRE_StructVectorSetConstantValues(h.X, 0.0);
  HYPRE_StructVectorAssemble(h.B);
  HYPRE_StructVectorAssemble(h.X);

  HYPRE_StructPCGCreate(MPI_COMM_SELF, &h.Solver);
  HYPRE_StructPCGSetTwoNorm(h.Solver, 1);
  HYPRE_StructPCGSetRelChange(h.Solver, 0);
  HYPRE_StructPCGSetPrintLevel(h.Solver, 0);
  HYPRE_StructPCGSetLogging(h.Solver, 1);
  h.Tolerance = this->Tolerance;
  h.MaximumIterations = this->MaximumIterations;
  HYPRE_StructPCGSetTol(h.Solver, this->Tolerance);
  HYPRE_StructPCGSetMaxIter(h.Solver, this->MaximumIterations);

  // One V-cycle of PFMG: symmetric red-black Gauss–Seidel smoothing and
  // Galerkin coarse operators (which keep obstacles' walls on coarse grids).
  // Two sweeps each way (not one) keep the iterations flat from 64^3 to
  // 256^3 (10, 10, 11 against 15, 16, 18) and cost less per solve; unequal
  // pre and post sweeps make the preconditioner unsymmetric and CG stall.
  HYPRE_StructPFMGCreate(MPI_COMM_SELF, &h.Preconditioner);
  HYPRE_StructPFMGSetMaxIter(h.Preconditioner, 1);
  HYPRE_StructPFMGSetTol(h.Preconditioner, 0.0);
  HYPRE_StructPFMGSetZeroGuess(h.Preconditioner);
  HYPRE_StructPFMGSetRelaxType(h.Preconditioner, 2);
  HYPRE_StructPFMGSetRAPType(h.Preconditioner, 0);
  HYPRE_StructPFMGSetNumPreRelax(h.Preconditioner, this->SmoothingSweeps);
  HYPRE_StructPFMGSetNumPostRelax(h.Preconditioner, this->SmoothingSweeps);
  h.SmoothingSweeps = this->SmoothingSweeps;
  HYPRE_StructPFMGSetSkipRelax(h.Preconditioner, 0);
  HYPRE_StructPFMGSetPrintLevel(h.Preconditioner, 0);
  HYPRE_StructPFMGSetLogging(h.Preconditioner, 0);
  HYPRE_StructPCGSetPrecond(h.Solver, HYPRE_StructPFMGSolve, HYPRE_StructPFMGSetup, h.Preconditioner);
  HYPRE_StructPCGSetup(h.Solver, h.Matrix, h.B, h.X);
  h.Buffer.resize(count);
  return HYPRE_GetError() == 0;
}

bool vtkPlumePressureSolver::SolvePCG(const double* b, double* q)
{
  double start = Seconds();
  if (this->Hypre && this->Hypre->SmoothingSweeps != this->SmoothingSweeps)
  {
    this->ReleaseHypre(); // the V-cycle changed: set up again
  }
  if (!this->Hypre && !this->SetupHypre())
  {
    this->LastError = "hypre could not set up the PFMG-preconditioned CG solver (error " +
      std::to_string(HYPRE_GetError()) + ")";
    HYPRE_ClearAllErrors();
    this->ReleaseHypre();
    return false;
  }
  HypreState& h = *this->Hypre;
  if (h.Tolerance != this->Tolerance || h.MaximumIterations != this->MaximumIterations)
  {
    HYPRE_StructPCGSetTol(h.Solver, this->Tolerance);
    HYPRE_StructPCGSetMaxIter(h.Solver, this->MaximumIterations);
    h.Tolerance = this->Tolerance;
    h.MaximumIterations = this->MaximumIterations;
  }
  this->LastSetupSeconds = Seconds() - start;
  start = Seconds();
  const int* n = this->Cells;
  HYPRE_Int lower[3] = { 0, 0, 0 };
  HYPRE_Int upper[3] = { n[0] - 1, n[1] - 1, n[2] - 1 };
  std::copy(b, b + h.Buffer.size(), h.Buffer.begin());
  HYPRE_StructVectorSetBoxValues(h.B, lower, upper, h.Buffer.data());
  HYPRE_StructVectorSetConstantValues(h.X, 0.0);
  HYPRE_StructPCGSolve(h.Solver, h.Matrix, h.B, h.X);
  // Not reaching the tolerance sets a hypre error flag: that is reported
  // through LastConverged, not as a failure.
  HYPRE_ClearAllErrors();
  HYPRE_Int iterations = 0;
  HYPRE_StructPCGGetNumIterations(h.Solver, &iterations);
  this->LastIterations = int(iterations);
  HYPRE_StructVectorGetBoxValues(h.X, lower, upper, h.Buffer.data());
  std::copy(h.Buffer.begin(), h.Buffer.end(), q);
  for (size_t c = 0; c < h.Buffer.size(); ++c)
  {
    if (this->Diagonal[c] == 0)
    {
      q[c] = 0;
    }
  }
  this->LastSolveSeconds = Seconds() - start;
  return true;
}

//------------------------------------------------------------------------------
void vtkPlumePressureSolver::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << (this->Method == JACOBI ? "JACOBI" : "PCG") << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MaximumIterations: " << this->MaximumIterations << "\n";
  os << indent << "JacobiWeight: " << this->JacobiWeight << "\n";
  os << indent << "SmoothingSweeps: " << this->SmoothingSweeps << "\n";
  os << indent << "Cells: " << this->Cells[0] << " " << this->Cells[1] << " " << this->Cells[2] << "\n";
  os << indent << "LastIterations: " << this->LastIterations << "\n";
  os << indent << "LastRelativeResidual: " << this->LastRelativeResidual << "\n";
}
