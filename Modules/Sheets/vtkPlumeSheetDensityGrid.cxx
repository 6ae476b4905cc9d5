#include "vtkPlumeSheetDensityGrid.h"
#include "vtkPlumeSheetTriangles.h"

#include "vtkPlumeInputValidation.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <utility>
#include <sstream>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkPlumeSheetDensityGrid);

namespace
{
const double MaximumSigma = 1e15; // as vtkPlumeSheetMapper::MaximumSigma

double GridClean(double v)
{
  return std::isfinite(v) && v > 0.0 ? v : 0.0;
}

vtkDataArray* GridArray(vtkPolyData* poly, const std::string& name)
{
  if (name.empty())
  {
    return nullptr;
  }
  vtkDataArray* a = poly->GetPointData()->GetArray(name.c_str());
  return a && a->GetNumberOfTuples() == poly->GetNumberOfPoints() && a->GetNumberOfComponents() >= 1 ? a
                                                                                                      : nullptr;
}

struct Corner
{
  glm::dvec3 P;
  double D, SB, ST;
};


// one quadrature point: a Gaussian of mass M (64 bytes: a million-triangle
// mesh's points take tens of MB, not hundreds)
// every Gaussian is evaluated inside its ellipsoid r^T A r <= 2 Cutoff^2
// (sqrt(2) Cutoff standard deviations: the mass outside is 2e-5 at the
// default Cutoff 3.5)
const double RadiusScale = 2.0;

// a Gaussian to splat: centre, peak value (mass / ((2 pi)^1.5 sqrt(det S))),
// precision A = S^-1 (xx xy xz yy yz zz) and the covariance's yy, yz, zz, xx
struct Blob
{
  glm::dvec3 P;
  double Norm;
  double A[6];
  double S[4];
};

// the moments of the quadrature points of one merge cell (about its centre)
struct CellSum
{
  unsigned long long Key = 0;
  glm::dvec3 Centre{ 0.0 };
  double M = 0.0;
  glm::dvec3 First{ 0.0 };
  glm::dmat3 Second{ 0.0 };
};

struct Source
{
  glm::dvec3 P;
  glm::vec3 N;
  float Pad = 0.f;
  double M, SB, ST;
};
}

vtkPlumeSheetDensityGrid::vtkPlumeSheetDensityGrid() = default;
vtkPlumeSheetDensityGrid::~vtkPlumeSheetDensityGrid() = default;

void vtkPlumeSheetDensityGrid::SetInputData(vtkPolyData* mesh)
{
  this->Mesh = mesh;
  this->Modified();
}

bool vtkPlumeSheetDensityGrid::Compute()
{
  return this->Run(false);
}

std::string vtkPlumeSheetDensityGrid::CheckBudget()
{
  return this->Run(true) ? std::string() : this->LastError;
}

bool vtkPlumeSheetDensityGrid::Run(bool budgetOnly)
{
  const auto start = std::chrono::steady_clock::now();
  vtkPolyData* poly = this->Mesh;
  if (!poly)
  {
    this->LastError = "no input mesh";
    vtkErrorMacro(<< "no input mesh");
    return false;
  }
  vtkDataArray* dArr = GridArray(poly, this->DensityArrayName);
  vtkDataArray* bArr = GridArray(poly, this->BlurArrayName);
  vtkDataArray* tArr = GridArray(poly, this->ThicknessArrayName);
  const double scale = this->DensityScale;

  // ---- triangles with the mapper's conventions; only their point ids are
  // kept (24 bytes each: a million-triangle mesh's corners are read again by
  // the threads that make its quadrature points, not stored twice)
  auto corners = [&](const vtkIdType ids[3], Corner c[3]) { // false: skip the triangle
    bool any = false;
    for (int k = 0; k < 3; ++k)
    {
      double p[3];
      poly->GetPoint(ids[k], p); // (the two-argument reads are thread-safe)
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      {
        return false;
      }
      c[k].P = glm::dvec3(p[0], p[1], p[2]);
      c[k].D = std::min(GridClean((dArr ? dArr->GetComponent(ids[k], 0) : this->Density) * scale), 1e30);
      c[k].SB = std::min(GridClean(bArr ? bArr->GetComponent(ids[k], 0) : this->BlurRadius), MaximumSigma);
      c[k].ST = this->ThinSheet
        ? 0.0
        : std::min(GridClean(tArr ? tArr->GetComponent(ids[k], 0) : this->Thickness), MaximumSigma);
      any = any || c[k].D > 0;
    }
    const double area = glm::length(glm::cross(c[1].P - c[0].P, c[2].P - c[0].P));
    return any && area > 0.0 && std::isfinite(area);
  };
  std::vector<std::array<vtkIdType, 3>> tris;
  double sMin = 1e300, sMax = 0.0;
  glm::dvec3 lo(1e300), hi(-1e300);
  auto add = [&](vtkIdType i0, vtkIdType i1, vtkIdType i2) {
    const std::array<vtkIdType, 3> ids = { i0, i1, i2 };
    Corner c[3];
    if (!corners(ids.data(), c))
    {
      return;
    }
    for (const Corner& q : c)
    {
      sMin = std::min(sMin, this->ThinSheet ? q.SB : std::min(q.SB, q.ST));
      sMax = std::max(sMax, std::max(q.SB, q.ST));
      lo = glm::min(lo, q.P);
      hi = glm::max(hi, q.P);
    }
    tris.push_back(ids);
  };
  {
    size_t count = 0; // (reserved: growing the list cost more than reading the mesh)
    plume::ForEachSheetTriangle(poly, [&count](vtkIdType, vtkIdType, vtkIdType) { ++count; });
    tris.reserve(count);
  }
  plume::ForEachSheetTriangle(poly, add);

  // ---- spacing from the smallest sigma, grown until the grid fits MaximumNodes
  const double k = this->SamplesPerSigma;
  const double extent0 = tris.empty() ? 1.0 : std::max({ hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-30 });
  double h = sMin > 0 ? sMin / k : extent0 / 64.0;
  int dims[3] = { 1, 1, 1 };
  glm::dvec3 origin(0.0);
  for (int iter = 0; iter < 200; ++iter)
  {
    const double floorSigma = k * h;
    const double pad = this->Cutoff * std::max(sMax, floorSigma);
    origin = lo - glm::dvec3(pad);
    double nodes = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      const double len = tris.empty() ? 0.0 : (hi[a] - lo[a]) + 2.0 * pad;
      dims[a] = static_cast<int>(std::min(1e9, std::ceil(len / h))) + 1;
      nodes *= dims[a];
    }
    if (nodes <= this->MaximumNodes || tris.empty())
    {
      break;
    }
    h *= std::max(1.01, std::cbrt(nodes / this->MaximumNodes));
  }
  this->SigmaFloor = k * h;

  // ---- the work this mesh asks for, bounded before any of it is done: a
  // small triangle is one point; the bisection below makes about
  // max(1, 2 area / target^2) pieces of a larger one (at most 2^24), 3
  // quadrature points each, and every Gaussian visits the nodes of its
  // ellipsoid (pi/6 of its box). Merged, the Gaussians are at most one per
  // occupied merge cell (a triangle no wider than a cell: the cell of its
  // centroid; a larger one: 3 area / cell^2 + 2 longest / cell + 1 cells),
  // each as wide as the widest sigma plus a cell's spread.
  const double mergeCell = this->MergeCellSize * h;
  const double cutoff2 = this->Cutoff * this->Cutoff;
  const double radius2 = RadiusScale * cutoff2;
  auto nodesOf = [&](double sigma) {
    const double side = std::min(double(std::max({ dims[0], dims[1], dims[2] })), 2.0 * std::sqrt(radius2) * sigma / h + 1.0);
    return 0.5236 * side * side * side;
  };
  // (triangles are made into points and merged in fixed blocks of this many)
  const vtkIdType blockSize = 4096;
  double points = 0.0, work = 0.0, gaussians = 0.0, cellSums = 0.0;
  {
    double sigmaTop = 0.0;
    // the merge cells of the small triangles: of the current block, then of
    // all blocks (each block's distinct cells once: one cell sum each)
    std::vector<unsigned long long> blockCells, smallCells;
    auto closeBlock = [&]() {
      std::sort(blockCells.begin(), blockCells.end());
      const auto end = std::unique(blockCells.begin(), blockCells.end());
      cellSums += static_cast<double>(end - blockCells.begin());
      smallCells.insert(smallCells.end(), blockCells.begin(), end);
      blockCells.clear();
    };
    size_t ti = 0;
    long long mdims[3];
    for (int a = 0; a < 3; ++a)
    {
      mdims[a] = mergeCell > 0.0 ? static_cast<long long>(std::floor((dims[a] - 1) * h / mergeCell)) + 1 : 1;
    }
    for (const auto& ids : tris)
    {
      if (ti > 0 && ti % blockSize == 0)
      {
        closeBlock();
      }
      ++ti;
      Corner c[3];
      corners(ids.data(), c);
      double sb = 1e300, sMaxT = 0.0;
      for (const Corner& q : c)
      {
        sb = std::min(sb, std::max(q.SB, this->SigmaFloor));
        sMaxT = std::max({ sMaxT, std::max(q.SB, this->SigmaFloor), std::max(q.ST, this->SigmaFloor) });
      }
      sigmaTop = std::max(sigmaTop, sMaxT);
      const double target = this->SubTriangleSize * sb;
      const double area = 0.5 * glm::length(glm::cross(c[1].P - c[0].P, c[2].P - c[0].P));
      const double longest =
        std::max({ glm::length(c[1].P - c[0].P), glm::length(c[2].P - c[1].P), glm::length(c[0].P - c[2].P) });
      const double n = longest <= this->SmallTriangleSize * sb
        ? 1.0
        : 3.0 * std::min(16777216.0, std::max({ 1.0, 2.0 * area / (target * target), longest / target }));
      points += n;
      if (mergeCell > 0.0)
      {
        if (longest <= mergeCell)
        {
          const glm::dvec3 g = (c[0].P + c[1].P + c[2].P) / 3.0;
          long long k[3];
          for (int a = 0; a < 3; ++a)
          {
            k[a] = std::min(mdims[a] - 1, std::max(0LL, static_cast<long long>(std::floor((g[a] - origin[a]) / mergeCell))));
          }
          blockCells.push_back(static_cast<unsigned long long>((k[2] * mdims[1] + k[1]) * mdims[0] + k[0]));
        }
        else
        {
          const double cells = std::min(n, 3.0 * area / (mergeCell * mergeCell) + 2.0 * longest / mergeCell + 1.0);
          gaussians += cells;
          cellSums += cells;
        }
      }
      else
      {
        work += n * nodesOf(sMaxT);
      }
    }
    if (mergeCell > 0.0)
    {
      closeBlock();
      std::sort(smallCells.begin(), smallCells.end());
      gaussians += static_cast<double>(std::unique(smallCells.begin(), smallCells.end()) - smallCells.begin());
      gaussians = std::min({ gaussians, points, double(mdims[0]) * mdims[1] * mdims[2] });
      // (the sort and the moments: a few dozen operations per point)
      work = gaussians * nodesOf(std::sqrt(sigmaTop * sigmaTop + 0.75 * mergeCell * mergeCell)) + 64.0 * points;
    }
    else
    {
      gaussians = points;
    }
  }
  {
    std::ostringstream what;
    what << "the sheet grid of " << tris.size() << " triangles (about " << points << " quadrature points";
    if (mergeCell > 0.0)
    {
      what << " merged into about " << gaussians << " Gaussians";
    }
    what << " on " << dims[0] << "x" << dims[1] << "x" << dims[2] << " nodes)";
    // the points and their merge keys, and the merged Gaussians
    // merged: the blocks' cell sums, their sort keys and the merged Gaussians
    // (the points themselves are not stored); else the points
    const double bytes = mergeCell > 0.0
      ? cellSums * (sizeof(CellSum) + 24.0 + 48.0) + gaussians * (sizeof(Blob) + 8.0)
      : points * sizeof(Source);
    std::string tooMuch = vtkPlumeInputValidation::CheckMemory(bytes, what.str());
    if (tooMuch.empty())
    {
      tooMuch = vtkPlumeInputValidation::CheckWork(work, what.str());
    }
    if (!tooMuch.empty())
    {
      this->LastError = tooMuch + "; use fewer triangles, a larger blur or the exact mode";
      if (!budgetOnly)
      {
        vtkErrorMacro(<< this->LastError);
      }
      return false;
    }
  }
  this->LastError.clear();
  if (budgetOnly)
  {
    return true;
  }

  // ---- quadrature points, in fixed blocks of triangles on the SMP threads
  // (each block keeps its own list, joined in block order: the result does
  // not depend on the thread count). A triangle no wider than
  // SmallTriangleSize x its smallest sigma_b (fine meshes: most of a
  // million-triangle isosurface) is one Gaussian at its mass centroid whose
  // in-plane variance grows by the triangle's own (sum of squared edges / 72,
  // the isotropic part of its second moment): mass, centroid and spread are
  // kept, and it costs a third of the three-point rule. Larger triangles are
  // cut by longest-edge bisection into pieces no wider than SubTriangleSize x
  // the smallest sigma_b (a sliver is cut along its length only: the number
  // of pieces follows its area over sigma^2, not its length^2), each piece
  // adding its edge midpoints (degree 2).
  const vtkIdType blocks = (static_cast<vtkIdType>(tris.size()) + blockSize - 1) / blockSize;
  const double floorSigma = this->SigmaFloor;
  const double subSize = this->SubTriangleSize;
  const double smallSize = this->SmallTriangleSize;
  // the quadrature points of triangle ti, each handed to sink(const Source&)
  auto quadrature = [&](size_t ti, auto&& sink) {
    Corner c[3];
    corners(tris[ti].data(), c);
    for (Corner& q : c)
    {
      q.SB = std::max(q.SB, floorSigma);
      q.ST = std::max(q.ST, floorSigma);
    }
    const glm::dvec3 e1 = c[1].P - c[0].P, e2 = c[2].P - c[0].P;
    const glm::dvec3 cr = glm::cross(e1, e2);
    const double area = 0.5 * glm::length(cr);
    const glm::vec3 n(cr / (2.0 * area));
    const double sbMin = std::min({ c[0].SB, c[1].SB, c[2].SB });
    const double l2[3] = { glm::dot(e1, e1), glm::dot(e2 - e1, e2 - e1), glm::dot(e2, e2) };
    const double longest = std::sqrt(std::max({ l2[0], l2[1], l2[2] }));
    if (longest <= smallSize * sbMin)
    {
      const double dSum = c[0].D + c[1].D + c[2].D;
      if (!(dSum > 0.0))
      {
        return;
      }
      Source s;
      // centroid of a linearly varying density: sum_i p_i (D + d_i) / (4 D)
      s.P = ((dSum + c[0].D) * c[0].P + (dSum + c[1].D) * c[1].P + (dSum + c[2].D) * c[2].P) /
        (4.0 * dSum);
      s.N = n;
      s.M = area * dSum / 3.0;
      const double sb = (c[0].SB + c[1].SB + c[2].SB) / 3.0;
      s.SB = std::sqrt(sb * sb + (l2[0] + l2[1] + l2[2]) / 72.0);
      s.ST = (c[0].ST + c[1].ST + c[2].ST) / 3.0;
      sink(s);
      return;
    }
    const double target = subSize * sbMin;
    auto emit = [&](const glm::dvec3& l, double w) { // barycentric l, weight w (area)
      Source s;
      s.P = l.x * c[0].P + l.y * c[1].P + l.z * c[2].P;
      s.N = n;
      s.M = w * (l.x * c[0].D + l.y * c[1].D + l.z * c[2].D);
      s.SB = l.x * c[0].SB + l.y * c[1].SB + l.z * c[2].SB;
      s.ST = l.x * c[0].ST + l.y * c[1].ST + l.z * c[2].ST;
      if (s.M > 0.0)
      {
        sink(s);
      }
    };
    struct Piece
    {
      glm::dvec3 L[3];
      int Level;
    };
    std::vector<Piece> stack = { { { glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1) }, 0 } };
    while (!stack.empty())
    {
      const Piece piece = stack.back();
      stack.pop_back();
      glm::dvec3 q[3];
      for (int k = 0; k < 3; ++k)
      {
        q[k] = piece.L[k].x * c[0].P + piece.L[k].y * c[1].P + piece.L[k].z * c[2].P;
      }
      const double len[3] = { glm::length(q[1] - q[0]), glm::length(q[2] - q[1]), glm::length(q[0] - q[2]) };
      const int e = len[0] >= len[1] && len[0] >= len[2] ? 0 : (len[1] >= len[2] ? 1 : 2);
      if (len[e] <= target || piece.Level >= 24)
      {
        const double w = area / double(1 << piece.Level) / 3.0;
        emit(0.5 * (piece.L[0] + piece.L[1]), w);
        emit(0.5 * (piece.L[1] + piece.L[2]), w);
        emit(0.5 * (piece.L[2] + piece.L[0]), w);
        continue;
      }
      const glm::dvec3& u = piece.L[e];
      const glm::dvec3& v = piece.L[(e + 1) % 3];
      const glm::dvec3& o = piece.L[(e + 2) % 3];
      const glm::dvec3 m = 0.5 * (u + v);
      stack.push_back({ { u, m, o }, piece.Level + 1 });
      stack.push_back({ { m, v, o }, piece.Level + 1 });
    }
  };
  // ---- the Gaussians to splat. Without merging, one per quadrature point.
  // With MergeCellSize > 0, the points falling in one cubic merge cell (edge
  // MergeCellSize x the spacing) become one Gaussian with their total mass,
  // their mass centroid and their total second moment (each point's own
  // covariance plus the spread of the points): a sheet crossing a cell is
  // one anisotropic Gaussian instead of tens, at the price of the mixture's
  // higher moments (the error grows as (cell / sigma)^3; measured in
  // Documentation/Renderers.md and TestSheetGridMerge). The points are not
  // stored: each block of triangles sums its points' moments per cell as it
  // makes them (about the cell's centre: no cancellation far from the
  // origin), and the blocks' sums of a cell are added in block order, so
  // the sums do not depend on the thread count.
  const double twoPi15 = std::pow(2.0 * 3.14159265358979323846, 1.5);
  auto covarianceOf = [](const Source& s) { // sb^2 I + (st^2 - sb^2) n n^T
    const glm::dvec3 n(s.N);
    return glm::dmat3(s.SB * s.SB) + (s.ST * s.ST - s.SB * s.SB) * glm::outerProduct(n, n);
  };
  auto blobOf = [&](const glm::dvec3& p, double mass, const glm::dmat3& cov) {
    Blob b;
    b.P = p;
    const double det = glm::determinant(cov);
    b.Norm = det > 0.0 ? mass / (twoPi15 * std::sqrt(det)) : 0.0;
    const glm::dmat3 a = det > 0.0 ? glm::inverse(cov) : glm::dmat3(0.0);
    b.A[0] = a[0][0];
    b.A[1] = a[0][1];
    b.A[2] = a[0][2];
    b.A[3] = a[1][1];
    b.A[4] = a[1][2];
    b.A[5] = a[2][2];
    b.S[0] = cov[1][1];
    b.S[1] = cov[1][2];
    b.S[2] = cov[2][2];
    b.S[3] = cov[0][0];
    return b;
  };
  std::vector<Source> sources; // (without merging)
  std::vector<Blob> blobs;     // (merged)
  vtkIdType pointCount = 0;
  // (the quadrature's time: the points made, and merged, their sums per cell in each block)
  auto quadratureDone = std::chrono::steady_clock::now();
  if (mergeCell > 0.0)
  {
    long long mdims[3];
    for (int a = 0; a < 3; ++a)
    {
      mdims[a] = static_cast<long long>(std::floor((dims[a] - 1) * h / mergeCell)) + 1;
    }
    std::vector<std::vector<CellSum>> perBlock(blocks);
    std::vector<vtkIdType> blockPoints(blocks, 0);
    vtkSMPTools::For(0, blocks, [&](vtkIdType b0, vtkIdType b1) {
      std::unordered_map<unsigned long long, size_t> index;
      for (vtkIdType blk = b0; blk < b1; ++blk)
      {
        std::vector<CellSum>& out = perBlock[blk];
        index.clear();
        unsigned long long lastKey = ~0ULL;
        CellSum* last = nullptr;
        vtkIdType made = 0;
        auto sink = [&](const Source& s) {
          long long k[3];
          for (int a = 0; a < 3; ++a)
          {
            k[a] = std::min(mdims[a] - 1,
              std::max(0LL, static_cast<long long>(std::floor((s.P[a] - origin[a]) / mergeCell))));
          }
          const unsigned long long key =
            static_cast<unsigned long long>((k[2] * mdims[1] + k[1]) * mdims[0] + k[0]);
          if (key != lastKey) // (a triangle's points mostly share a cell)
          {
            auto it = index.emplace(key, out.size());
            if (it.second)
            {
              CellSum fresh;
              fresh.Key = key;
              for (int a = 0; a < 3; ++a)
              {
                fresh.Centre[a] = origin[a] + (static_cast<double>(k[a]) + 0.5) * mergeCell;
              }
              out.push_back(fresh);
            }
            last = &out[it.first->second];
            lastKey = key;
          }
          const glm::dvec3 d = s.P - last->Centre;
          last->M += s.M;
          last->First += s.M * d;
          last->Second += s.M * (covarianceOf(s) + glm::outerProduct(d, d));
          ++made;
        };
        const size_t t0 = static_cast<size_t>(blk * blockSize);
        const size_t t1 = std::min(tris.size(), t0 + static_cast<size_t>(blockSize));
        for (size_t ti = t0; ti < t1; ++ti)
        {
          quadrature(ti, sink);
        }
        blockPoints[blk] = made;
      }
    });
    quadratureDone = std::chrono::steady_clock::now();
    // the cells' sums in (cell, block) order; (key, block, position) is unique
    std::vector<std::array<unsigned long long, 3>> order;
    for (vtkIdType blk = 0; blk < blocks; ++blk)
    {
      pointCount += blockPoints[blk];
      for (size_t i = 0; i < perBlock[blk].size(); ++i)
      {
        order.push_back({ perBlock[blk][i].Key, static_cast<unsigned long long>(blk), i });
      }
    }
    vtkSMPTools::Sort(order.begin(), order.end());
    std::vector<size_t> runs;
    for (size_t i = 0; i < order.size(); ++i)
    {
      if (i == 0 || order[i][0] != order[i - 1][0])
      {
        runs.push_back(i);
      }
    }
    runs.push_back(order.size());
    blobs.resize(runs.size() - 1);
    vtkSMPTools::For(0, static_cast<vtkIdType>(blobs.size()), [&](vtkIdType r0, vtkIdType r1) {
      for (vtkIdType r = r0; r < r1; ++r)
      {
        double mass = 0.0;
        glm::dvec3 first(0.0);
        glm::dmat3 second(0.0);
        const CellSum* any = nullptr;
        for (size_t k = runs[r]; k < runs[r + 1]; ++k)
        {
          const CellSum& c = perBlock[order[k][1]][order[k][2]];
          mass += c.M;
          first += c.First;
          second += c.Second;
          any = &c;
        }
        const glm::dvec3 mean = first / mass;
        const glm::dmat3 cov = second / mass - glm::outerProduct(mean, mean);
        blobs[r] = blobOf(any->Centre + mean, mass, cov);
      }
    });
  }
  else
  {
    // in fixed blocks of triangles (each block keeps its own list, joined in
    // block order: the result does not depend on the thread count)
    std::vector<std::vector<Source>> perBlock(blocks);
    vtkSMPTools::For(0, blocks, [&](vtkIdType b0, vtkIdType b1) {
      for (vtkIdType blk = b0; blk < b1; ++blk)
      {
        std::vector<Source>& out = perBlock[blk];
        const size_t t0 = static_cast<size_t>(blk * blockSize);
        const size_t t1 = std::min(tris.size(), t0 + static_cast<size_t>(blockSize));
        for (size_t ti = t0; ti < t1; ++ti)
        {
          quadrature(ti, [&](const Source& s) { out.push_back(s); });
        }
      }
    });
    size_t total = 0;
    for (const auto& v : perBlock)
    {
      total += v.size();
    }
    sources.reserve(total);
    for (auto& v : perBlock)
    {
      sources.insert(sources.end(), v.begin(), v.end());
      std::vector<Source>().swap(v); // free as we go
    }
    pointCount = static_cast<vtkIdType>(sources.size());
    quadratureDone = std::chrono::steady_clock::now();
  }
  std::vector<std::array<vtkIdType, 3>>().swap(tris);
  this->PointCount = pointCount;
  this->QuadratureSeconds = std::chrono::duration<double>(quadratureDone - start).count();
  // without merging each point is made a Gaussian where it is splatted (no
  // second copy of the points)
  const bool merged = !blobs.empty() || sources.empty();
  const size_t count = merged ? blobs.size() : sources.size();
  auto gaussian = [&](size_t i) {
    return merged ? blobs[i] : blobOf(sources[i].P, sources[i].M, covarianceOf(sources[i]));
  };
  this->GaussianCount = static_cast<vtkIdType>(count);
  const auto mergeDone = std::chrono::steady_clock::now();
  this->MergeSeconds = std::chrono::duration<double>(mergeDone - quadratureDone).count();

  // the node box of a Gaussian: its ellipsoid's axis-aligned box,
  // half-width sqrt(2 Sigma_aa) Cutoff
  auto nodeBox = [&](const Blob& s, int lo[3], int hi[3]) {
    const double var[3] = { s.S[3], s.S[0], s.S[2] };
    for (int a = 0; a < 3; ++a)
    {
      const double r = std::sqrt(radius2 * std::max(var[a], 0.0));
      lo[a] = std::max(0, static_cast<int>(std::ceil((s.P[a] - r - origin[a]) / h)));
      hi[a] = std::min(dims[a] - 1, static_cast<int>(std::floor((s.P[a] + r - origin[a]) / h)));
    }
  };

  // ---- splat: z-slabs of 4 planes, each owned by one thread
  const int slab = 4;
  const int slabs = (dims[2] + slab - 1) / slab;
  std::vector<std::vector<unsigned int>> bins(slabs);
  for (size_t i = 0; i < count; ++i)
  {
    const Blob s = gaussian(i);
    int lo[3], hi[3];
    nodeBox(s, lo, hi);
    if (lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2] || !(s.Norm > 0.0))
    {
      continue;
    }
    for (int b = lo[2] / slab; b <= hi[2] / slab; ++b)
    {
      bins[b].push_back(static_cast<unsigned int>(i));
    }
  }
  const size_t nx = dims[0], ny = dims[1];
  // the output array is written in place (no second copy of the grid)
  vtkNew<vtkFloatArray> array;
  array->SetName("density");
  array->SetNumberOfValues(static_cast<vtkIdType>(nx * ny * dims[2]));
  float* rho = array->GetPointer(0);
  std::fill(rho, rho + nx * ny * dims[2], 0.0f);
  vtkSMPTools::For(0, slabs, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType b = b0; b < b1; ++b)
    {
      const int z0 = static_cast<int>(b) * slab, z1 = std::min(dims[2], z0 + slab) - 1;
      for (unsigned int i : bins[b])
      {
        const Blob s = gaussian(i);
        int sLo[3], sHi[3];
        nodeBox(s, sLo, sHi);
        // exponent Q = r^T A r; along a row Q(rx) = A rx^2 + B rx + C: only
        // the x range inside the ellipsoid Q <= limit is visited, and only
        // the y range of its (y, z) shadow. No exp per row or node: the
        // value G = Norm exp(-Q/2) at the current node and its factors to
        // the next node in x and in y (Fx, Fy) are exact at the first node
        // of each plane and move by multiplications (a step in x multiplies
        // Fx by exp(-Axx h^2) and Fy by exp(-Axy h^2), a step in y Fy by
        // exp(-Ayy h^2) and Fx by exp(-Axy h^2)); each row then sums four
        // interleaved geometric-quadratic sequences (short dependency
        // chains).
        const double A = s.A[0];
        const double limit = radius2;
        const double rxx = std::exp(-A * h * h), rxy = std::exp(-s.A[1] * h * h),
                     ryy = std::exp(-s.A[3] * h * h);
        const double irxx = 1.0 / rxx, irxy = 1.0 / rxy;
        const double rxx2 = rxx * rxx, rxx4 = rxx2 * rxx2, rxx6 = rxx4 * rxx2, rxx16 = rxx4 * rxx4 * rxx4 * rxx4;
        const double inv2A = 0.5 / A;
        // the (y, z) marginal: [ry rz] S_yz^-1 [ry rz]^T <= Cutoff^2
        const double detYZ = s.S[0] * s.S[2] - s.S[1] * s.S[1];
        for (int z = std::max(z0, sLo[2]); z <= std::min(z1, sHi[2]); ++z)
        {
          const double rz = origin.z + z * h - s.P.z;
          int y0 = sLo[1], y1 = sHi[1];
          if (detYZ > 0.0 && s.S[2] > 0.0)
          {
            // ry = (S_yz / S_zz) rz +- sqrt(detYZ / S_zz (Cutoff^2 - rz^2 / S_zz))
            const double rest = limit - rz * rz / s.S[2];
            if (!(rest > 0.0))
            {
              continue;
            }
            const double mid = s.S[1] / s.S[2] * rz + s.P.y - origin.y;
            const double half = std::sqrt(detYZ / s.S[2] * rest);
            y0 = std::max(y0, static_cast<int>(std::ceil((mid - half) / h)));
            y1 = std::min(y1, static_cast<int>(std::floor((mid + half) / h)));
          }
          bool started = false;
          int cx = 0, cy = 0;
          double G = 0.0, Fx = 0.0, Fy = 0.0;
          for (int y = y0; y <= y1; ++y)
          {
            const double ry = origin.y + y * h - s.P.y;
            const double B = 2.0 * (s.A[1] * ry + s.A[2] * rz);
            const double C = s.A[3] * ry * ry + 2.0 * s.A[4] * ry * rz + s.A[5] * rz * rz;
            const double disc = B * B - 4.0 * A * (C - limit);
            if (!(disc > 0.0))
            {
              continue;
            }
            const double root = std::sqrt(disc);
            const double xa = (-B - root) * inv2A + s.P.x - origin.x;
            const double xb = (-B + root) * inv2A + s.P.x - origin.x;
            const int x0 = std::max(sLo[0], static_cast<int>(std::ceil(xa / h)));
            const int x1 = std::min(sHi[0], static_cast<int>(std::floor(xb / h)));
            if (x0 > x1)
            {
              continue;
            }
            if (!started)
            {
              const double rx = origin.x + x0 * h - s.P.x;
              G = s.Norm * std::exp(-0.5 * ((A * rx + B) * rx + C));
              Fx = std::exp(-0.5 * (A * (2.0 * rx * h + h * h) + B * h));
              Fy = std::exp(-0.5 * (s.A[3] * (2.0 * ry * h + h * h) + 2.0 * h * (s.A[1] * rx + s.A[4] * rz)));
              cx = x0;
              cy = y;
              started = true;
            }
            for (; cy < y; ++cy)
            {
              G *= Fy;
              Fy *= ryy;
              Fx *= rxy;
            }
            for (; cx < x0; ++cx)
            {
              G *= Fx;
              Fx *= rxx;
              Fy *= rxy;
            }
            for (; cx > x0; --cx)
            {
              Fx *= irxx;
              G /= Fx;
              Fy *= irxy;
            }
            float* row = rho + (static_cast<size_t>(z) * ny + y) * nx;
            // nodes x0 + k + 4j: g_k advances by F_k = f_k f_k+1 f_k+2 f_k+3
            // = f_k^4 rxx^6, and F_k by rxx^16
            double g[4], F[4];
            {
              double f = Fx, v = G;
              for (int k = 0; k < 4; ++k)
              {
                g[k] = v;
                const double f2 = f * f;
                F[k] = f2 * f2 * rxx6;
                v *= f;
                f *= rxx;
              }
            }
            int x = x0;
            for (; x + 3 <= x1; x += 4)
            {
              for (int k = 0; k < 4; ++k)
              {
                row[x + k] += static_cast<float>(g[k]);
                g[k] *= F[k];
                F[k] *= rxx16;
              }
            }
            for (int k = 0; x <= x1; ++x, ++k)
            {
              row[x] += static_cast<float>(g[k]);
            }
          }
        }
      }
    }
  });
  this->SplatSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - mergeDone).count();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dims);
  image->SetOrigin(origin.x, origin.y, origin.z);
  image->SetSpacing(h, h, h);
  image->GetPointData()->SetScalars(array);
  this->Output = image;
  this->ComputeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

void vtkPlumeSheetDensityGrid::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SamplesPerSigma: " << this->SamplesPerSigma << "\n";
  os << indent << "MaximumNodes: " << this->MaximumNodes << "\n";
  os << indent << "SubTriangleSize: " << this->SubTriangleSize << "\n";
  os << indent << "SmallTriangleSize: " << this->SmallTriangleSize << "\n";
  os << indent << "SigmaFloor: " << this->SigmaFloor << "\n";
  os << indent << "PointCount: " << this->PointCount << "\n";
}
