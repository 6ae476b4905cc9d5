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
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkPlumeSheetDensityGrid);

namespace
{
const double MaximumSigma = 1e15; // as vtkPlumeSheetMapper::MaximumSigma

double Clean(double v)
{
  return std::isfinite(v) && v > 0.0 ? v : 0.0;
}

vtkDataArray* Named(vtkPolyData* poly, const std::string& name)
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
  vtkDataArray* dArr = Named(poly, this->DensityArrayName);
  vtkDataArray* bArr = Named(poly, this->BlurArrayName);
  vtkDataArray* tArr = Named(poly, this->ThicknessArrayName);
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
      c[k].D = std::min(Clean((dArr ? dArr->GetComponent(ids[k], 0) : this->Density) * scale), 1e30);
      c[k].SB = std::min(Clean(bArr ? bArr->GetComponent(ids[k], 0) : this->BlurRadius), MaximumSigma);
      c[k].ST = this->ThinSheet
        ? 0.0
        : std::min(Clean(tArr ? tArr->GetComponent(ids[k], 0) : this->Thickness), MaximumSigma);
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
  // quadrature points each, and every point visits the nodes of its Cutoff
  // box (an upper bound of the ellipsoid rows).
  {
    double points = 0.0, work = 0.0;
    for (const auto& ids : tris)
    {
      Corner c[3];
      corners(ids.data(), c);
      double sb = 1e300, sMaxT = 0.0;
      for (const Corner& q : c)
      {
        sb = std::min(sb, std::max(q.SB, this->SigmaFloor));
        sMaxT = std::max({ sMaxT, std::max(q.SB, this->SigmaFloor), std::max(q.ST, this->SigmaFloor) });
      }
      const double target = this->SubTriangleSize * sb;
      const double area = 0.5 * glm::length(glm::cross(c[1].P - c[0].P, c[2].P - c[0].P));
      const double longest =
        std::max({ glm::length(c[1].P - c[0].P), glm::length(c[2].P - c[1].P), glm::length(c[0].P - c[2].P) });
      const double n = longest <= this->SmallTriangleSize * sb
        ? 1.0
        : 3.0 * std::min(16777216.0, std::max({ 1.0, 2.0 * area / (target * target), longest / target }));
      const double side =
        std::min(double(std::max({ dims[0], dims[1], dims[2] })), 2.0 * this->Cutoff * sMaxT / h + 1.0);
      points += n;
      work += n * side * side * side;
    }
    std::ostringstream what;
    what << "the sheet grid of " << tris.size() << " triangles (about " << points << " quadrature points on "
         << dims[0] << "x" << dims[1] << "x" << dims[2] << " nodes)";
    std::string tooMuch = vtkPlumeInputValidation::CheckMemory(points * sizeof(Source), what.str());
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
  const double cutoff2 = this->Cutoff * this->Cutoff;
  const vtkIdType blockSize = 4096;
  const vtkIdType blocks = (static_cast<vtkIdType>(tris.size()) + blockSize - 1) / blockSize;
  std::vector<std::vector<Source>> perBlock(blocks);
  const double floorSigma = this->SigmaFloor;
  const double subSize = this->SubTriangleSize;
  const double smallSize = this->SmallTriangleSize;
  vtkSMPTools::For(0, blocks, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType blk = b0; blk < b1; ++blk)
    {
      std::vector<Source>& out = perBlock[blk];
      const size_t t0 = static_cast<size_t>(blk * blockSize);
      const size_t t1 = std::min(tris.size(), t0 + static_cast<size_t>(blockSize));
      for (size_t ti = t0; ti < t1; ++ti)
      {
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
            continue;
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
          out.push_back(s);
          continue;
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
            out.push_back(s);
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
      }
    }
  });
  std::vector<Source> sources;
  {
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
  }
  std::vector<std::array<vtkIdType, 3>>().swap(tris);
  // the node box of a source within Cutoff (inclusive)
  auto nodeBox = [&](const Source& s, int lo[3], int hi[3]) {
    const double r = this->Cutoff * std::max(s.SB, s.ST);
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::max(0, static_cast<int>(std::ceil((s.P[a] - r - origin[a]) / h)));
      hi[a] = std::min(dims[a] - 1, static_cast<int>(std::floor((s.P[a] + r - origin[a]) / h)));
    }
  };
  this->PointCount = static_cast<vtkIdType>(sources.size());

  // ---- splat: z-slabs of 4 planes, each owned by one thread
  const int slab = 4;
  const int slabs = (dims[2] + slab - 1) / slab;
  std::vector<std::vector<int>> bins(slabs);
  for (size_t i = 0; i < sources.size(); ++i)
  {
    int lo[3], hi[3];
    nodeBox(sources[i], lo, hi);
    if (lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2])
    {
      continue;
    }
    for (int b = lo[2] / slab; b <= hi[2] / slab; ++b)
    {
      bins[b].push_back(static_cast<int>(i));
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
      for (int i : bins[b])
      {
        const Source& s = sources[i];
        int sLo[3], sHi[3];
        nodeBox(s, sLo, sHi);
        // exponent r^T A r with A = I / sb^2 + (1/st^2 - 1/sb^2) n n^T
        const double ib = 1.0 / (s.SB * s.SB), it = 1.0 / (s.ST * s.ST);
        const double norm = s.M / (std::pow(2.0 * 3.14159265358979323846, 1.5) * s.SB * s.SB * s.ST);
        // q(rx) = A rx^2 + B rx + C along each row: only the x range inside
        // the Cutoff ellipsoid is visited (a thin sheet's Gaussian fills a
        // small part of its bounding cube), and exp(-q/2) advances by two
        // multiplications per node
        const double dq = it - ib;
        const double A = ib + dq * s.N.x * s.N.x;
        const double limit = 2.0 * cutoff2;
        for (int z = std::max(z0, sLo[2]); z <= std::min(z1, sHi[2]); ++z)
        {
          const double rz = origin.z + z * h - s.P.z;
          for (int y = sLo[1]; y <= sHi[1]; ++y)
          {
            const double ry = origin.y + y * h - s.P.y;
            const double cn = s.N.y * ry + s.N.z * rz;
            const double B = 2.0 * dq * s.N.x * cn;
            const double C = ib * (ry * ry + rz * rz) + dq * cn * cn;
            const double disc = B * B - 4.0 * A * (C - limit);
            if (!(disc > 0.0))
            {
              continue;
            }
            const double root = std::sqrt(disc);
            const double xa = (-B - root) / (2.0 * A) + s.P.x - origin.x;
            const double xb = (-B + root) / (2.0 * A) + s.P.x - origin.x;
            const int x0 = std::max(sLo[0], static_cast<int>(std::ceil(xa / h)));
            const int x1 = std::min(sHi[0], static_cast<int>(std::floor(xb / h)));
            if (x0 > x1)
            {
              continue;
            }
            float* row = rho + (static_cast<size_t>(z) * ny + y) * nx;
            const double rx = origin.x + x0 * h - s.P.x;
            double g = norm * std::exp(-0.5 * ((A * rx + B) * rx + C));
            double f = std::exp(-0.5 * (A * (2.0 * rx * h + h * h) + B * h));
            const double r = std::exp(-A * h * h);
            for (int x = x0; x <= x1; ++x)
            {
              row[x] += static_cast<float>(g);
              g *= f;
              f *= r;
            }
          }
        }
      }
    }
  });

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
