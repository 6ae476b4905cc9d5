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

struct Triangle
{
  Corner C[3];
};

// one quadrature point: a Gaussian of mass M
struct Source
{
  glm::dvec3 P;
  glm::dvec3 N;
  double M, SB, ST;
  int Lo[3], Hi[3]; // node box within Cutoff (inclusive)
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

  // ---- triangles with the mapper's conventions
  std::vector<Triangle> tris;
  double sMin = 1e300, sMax = 0.0;
  glm::dvec3 lo(1e300), hi(-1e300);
  auto add = [&](vtkIdType i0, vtkIdType i1, vtkIdType i2) {
    Triangle t;
    const vtkIdType ids[3] = { i0, i1, i2 };
    bool any = false;
    for (int k = 0; k < 3; ++k)
    {
      double p[3];
      poly->GetPoint(ids[k], p);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      {
        return;
      }
      Corner& c = t.C[k];
      c.P = glm::dvec3(p[0], p[1], p[2]);
      c.D = std::min(Clean((dArr ? dArr->GetComponent(ids[k], 0) : this->Density) * scale), 1e30);
      c.SB = std::min(Clean(bArr ? bArr->GetComponent(ids[k], 0) : this->BlurRadius), MaximumSigma);
      c.ST = this->ThinSheet
        ? 0.0
        : std::min(Clean(tArr ? tArr->GetComponent(ids[k], 0) : this->Thickness), MaximumSigma);
      any = any || c.D > 0;
    }
    const double area = glm::length(glm::cross(t.C[1].P - t.C[0].P, t.C[2].P - t.C[0].P));
    if (!any || !(area > 0.0) || !std::isfinite(area))
    {
      return;
    }
    for (const Corner& c : t.C)
    {
      sMin = std::min(sMin, this->ThinSheet ? c.SB : std::min(c.SB, c.ST));
      sMax = std::max(sMax, std::max(c.SB, c.ST));
      lo = glm::min(lo, c.P);
      hi = glm::max(hi, c.P);
    }
    tris.push_back(t);
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

  // ---- the work this mesh asks for, bounded before any of it is done: the
  // bisection below makes about max(1, 2 area / target^2) pieces of each
  // triangle (at most 2^24), 3 quadrature points each, and every point
  // visits the nodes of its Cutoff box (an upper bound of the ellipsoid rows).
  {
    double points = 0.0, work = 0.0;
    for (const Triangle& t : tris)
    {
      double sb = 1e300, sMaxT = 0.0;
      for (const Corner& c : t.C)
      {
        sb = std::min(sb, std::max(c.SB, this->SigmaFloor));
        sMaxT = std::max({ sMaxT, std::max(c.SB, this->SigmaFloor), std::max(c.ST, this->SigmaFloor) });
      }
      const double target = this->SubTriangleSize * sb;
      const double area = 0.5 * glm::length(glm::cross(t.C[1].P - t.C[0].P, t.C[2].P - t.C[0].P));
      const double longest = std::max({ glm::length(t.C[1].P - t.C[0].P), glm::length(t.C[2].P - t.C[1].P),
        glm::length(t.C[0].P - t.C[2].P) });
      const double pieces = std::min(16777216.0, std::max({ 1.0, 2.0 * area / (target * target), longest / target }));
      const double side = std::min(double(std::max({ dims[0], dims[1], dims[2] })), 2.0 * this->Cutoff * sMaxT / h + 1.0);
      points += 3.0 * pieces;
      work += 3.0 * pieces * side * side * side;
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

  // ---- quadrature points: pieces no wider than SubTriangleSize x the smallest sigma_b,
  // each contributing its edge midpoints (degree 2)
  const double cutoff2 = this->Cutoff * this->Cutoff;
  std::vector<Source> sources;
  for (const Triangle& t : tris)
  {
    Corner c[3] = { t.C[0], t.C[1], t.C[2] };
    for (Corner& q : c)
    {
      q.SB = std::max(q.SB, this->SigmaFloor);
      q.ST = std::max(q.ST, this->SigmaFloor);
    }
    const glm::dvec3 e1 = c[1].P - c[0].P, e2 = c[2].P - c[0].P;
    const glm::dvec3 cr = glm::cross(e1, e2);
    const double area = 0.5 * glm::length(cr);
    const glm::dvec3 n = cr / (2.0 * area);
    const double sbMin = std::min({ c[0].SB, c[1].SB, c[2].SB });
    const double target = this->SubTriangleSize * sbMin;
    auto emit = [&](const glm::dvec3& l, double w) { // barycentric l, weight w (area)
      Source s;
      s.P = l.x * c[0].P + l.y * c[1].P + l.z * c[2].P;
      s.N = n;
      s.M = w * (l.x * c[0].D + l.y * c[1].D + l.z * c[2].D);
      s.SB = l.x * c[0].SB + l.y * c[1].SB + l.z * c[2].SB;
      s.ST = l.x * c[0].ST + l.y * c[1].ST + l.z * c[2].ST;
      if (!(s.M > 0.0))
      {
        return;
      }
      const double r = this->Cutoff * std::max(s.SB, s.ST);
      for (int a = 0; a < 3; ++a)
      {
        s.Lo[a] = std::max(0, static_cast<int>(std::ceil((s.P[a] - r - origin[a]) / h)));
        s.Hi[a] = std::min(dims[a] - 1, static_cast<int>(std::floor((s.P[a] + r - origin[a]) / h)));
      }
      sources.push_back(s);
    };
    // longest-edge bisection down to pieces no wider than `target` (a sliver
    // is cut along its length only: the number of pieces follows its area
    // over sigma^2, not its length^2), then each piece's edge midpoints
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
  this->PointCount = static_cast<vtkIdType>(sources.size());

  // ---- splat: z-slabs of 4 planes, each owned by one thread
  const int slab = 4;
  const int slabs = (dims[2] + slab - 1) / slab;
  std::vector<std::vector<int>> bins(slabs);
  for (size_t i = 0; i < sources.size(); ++i)
  {
    const Source& s = sources[i];
    if (s.Lo[0] > s.Hi[0] || s.Lo[1] > s.Hi[1] || s.Lo[2] > s.Hi[2])
    {
      continue;
    }
    for (int b = s.Lo[2] / slab; b <= s.Hi[2] / slab; ++b)
    {
      bins[b].push_back(static_cast<int>(i));
    }
  }
  const size_t nx = dims[0], ny = dims[1];
  std::vector<float> rho(nx * ny * dims[2], 0.0f);
  vtkSMPTools::For(0, slabs, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType b = b0; b < b1; ++b)
    {
      const int z0 = static_cast<int>(b) * slab, z1 = std::min(dims[2], z0 + slab) - 1;
      for (int i : bins[b])
      {
        const Source& s = sources[i];
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
        for (int z = std::max(z0, s.Lo[2]); z <= std::min(z1, s.Hi[2]); ++z)
        {
          const double rz = origin.z + z * h - s.P.z;
          for (int y = s.Lo[1]; y <= s.Hi[1]; ++y)
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
            const int x0 = std::max(s.Lo[0], static_cast<int>(std::ceil(xa / h)));
            const int x1 = std::min(s.Hi[0], static_cast<int>(std::floor(xb / h)));
            if (x0 > x1)
            {
              continue;
            }
            float* row = rho.data() + (static_cast<size_t>(z) * ny + y) * nx;
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
  vtkNew<vtkFloatArray> array;
  array->SetName("density");
  array->SetNumberOfValues(static_cast<vtkIdType>(rho.size()));
  std::copy(rho.begin(), rho.end(), array->GetPointer(0));
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
  os << indent << "SigmaFloor: " << this->SigmaFloor << "\n";
  os << indent << "PointCount: " << this->PointCount << "\n";
}
