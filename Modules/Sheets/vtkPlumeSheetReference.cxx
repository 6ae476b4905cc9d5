#include "vtkPlumeSheetReference.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkDataArray.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkPlumeSheetReference);

namespace
{
// GLM for the vector math (double precision; the shaders share nothing with this file)
using Vec = glm::dvec3;
const double Pi = 3.14159265358979323846;
const double Huge = 1e300;
// Triangles (and parts of them) farther than this many standard deviations
// from the ray are skipped (exp(-18) ~ 1.5e-8 of the peak)
const double Support = 6.0;

double ReferenceClean(double v)
{
  return std::isfinite(v) && v > 0.0 ? v : 0.0;
}

struct Triangle
{
  Vec P[3];
  Vec N;          // unit normal
  Vec D[3];       // RGB density at the corners
  double SB[3];   // sigma_b at the corners (after the pixel floor)
  double ST[3];   // sigma_t at the corners (0: surface layer)
  Vec Centre;     // bounding sphere of the triangle
  double Radius;
  double Reach;   // Support x the largest sigma
  double Area;
};

struct Ray
{
  Vec O;
  Vec V; // unit
  double T0, T1;
};

double RayDistance(const Ray& ray, const Vec& c)
{
  double t = glm::dot((c - ray.O), ray.V);
  t = std::min(std::max(t, ray.T0), ray.T1);
  return glm::length(((ray.O + (ray.V * t)) - c));
}

// Distance from the ray's infinite line to the triangle abc: the distance
// from the origin to the triangle projected along the ray's direction
// (closest point on a triangle, Ericson, Real-Time Collision Detection 5.1.5).
double LineTriangleDistance(const Ray& ray, const Vec& pa, const Vec& pb, const Vec& pc)
{
  auto project = [&](const Vec& p) {
    const Vec q = (p - ray.O);
    return (q - (ray.V * glm::dot(q, ray.V)));
  };
  const Vec a = project(pa), b = project(pb), c = project(pc);
  const Vec ab = (b - a), ac = (c - a), ap = (a * -1.0);
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0)
  {
    return glm::length(a);
  }
  const Vec bp = (b * -1.0);
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3)
  {
    return glm::length(b);
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    const double v = d1 / (d1 - d3);
    return glm::length((a + (ab * v)));
  }
  const Vec cp = (c * -1.0);
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6)
  {
    return glm::length(c);
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    const double w = d2 / (d2 - d6);
    return glm::length((a + (ac * w)));
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return glm::length((b + ((c - b) * w)));
  }
  const double denom = va + vb + vc;
  if (!(std::fabs(denom) > 0))
  {
    return 0.0; // degenerate projection (the triangle seen edge-on): do not cull
  }
  const double v = vb / denom, w = vc / denom;
  return glm::length((a + ((ab * v) + (ac * w))));
}

// Gauss-Kronrod 7/15 nodes and weights
const double XGK[8] = { 0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
  0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
  0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
  0.207784955007898467600689403773245, 0.0 };
const double WGK[8] = { 0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
  0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
  0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
  0.204432940075298892414161999234649, 0.209482141084727828012999174891714 };
const double WG[4] = { 0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
  0.381830050505118944950369775488975, 0.417959183673469387755102040816327 };

template <typename F>
double GaussKronrod(const F& f, double a, double b, double tolAbs, int depth)
{
  const double c = 0.5 * (a + b);
  const double h = 0.5 * (b - a);
  double k = WGK[7] * f(c);
  double g = WG[3] * f(c);
  for (int i = 0; i < 7; ++i)
  {
    const double s = f(c - h * XGK[i]) + f(c + h * XGK[i]);
    k += WGK[i] * s;
    if (i % 2 == 1)
    {
      g += WG[i / 2] * s;
    }
  }
  k *= h;
  g *= h;
  // |K15 - G7| overestimates the K15 error by orders of magnitude on smooth
  // integrands (K15 is then accurate to ~1e-9 relative)
  if (std::fabs(k - g) <= std::max(tolAbs, 1e-5 * std::fabs(k)) || depth > 40)
  {
    return k;
  }
  return GaussKronrod(f, a, c, 0.5 * tolAbs, depth + 1) +
    GaussKronrod(f, c, b, 0.5 * tolAbs, depth + 1);
}

// Integral over the ray of the unit-mass anisotropic Gaussian centred at p.
double LineIntegral(const Ray& ray, const Vec& p, const Vec& n, double sb, double st)
{
  if (!(sb > 0.0))
  {
    return 0.0;
  }
  const double vn = glm::dot(ray.V, n);
  if (!(st > 0.0))
  {
    // surface layer: a delta across the plane; the ray crosses it once
    if (!(std::fabs(vn) > 1e-300))
    {
      return 0.0;
    }
    const double t = glm::dot((p - ray.O), n) / vn;
    if (t < ray.T0 || t > ray.T1)
    {
      return 0.0;
    }
    const Vec r = ((ray.O + (ray.V * t)) - p);
    return std::exp(-0.5 * glm::dot(r, r) / (sb * sb)) / (2.0 * Pi * sb * sb * std::fabs(vn));
  }
  // Along the ray the integrand is a Gaussian in t; its centre and width
  // only place the quadrature panels (the value itself is integrated
  // numerically): panels at +-2.5 and +-8 widths, nothing beyond.
  const Vec r0 = (ray.O - p);
  const double z0 = glm::dot(r0, n);
  const Vec r0in = (r0 - (n * z0));
  const Vec vin = (ray.V - (n * vn));
  const double inv = glm::dot(vin, vin) / (sb * sb) + vn * vn / (st * st);
  const double width = 1.0 / std::sqrt(inv);
  const double centre = -(glm::dot(r0in, vin) / (sb * sb) + z0 * vn / (st * st)) / inv;
  const double a = std::max(ray.T0, centre - 8.0 * width);
  const double b = std::min(ray.T1, centre + 8.0 * width);
  if (!(a < b))
  {
    return 0.0;
  }
  const double norm = 1.0 / (std::pow(2.0 * Pi, 1.5) * sb * sb * st);
  auto f = [&](double t) {
    const Vec r = ((ray.O + (ray.V * t)) - p);
    const double z = glm::dot(r, n);
    const double in2 = std::max(0.0, glm::dot(r, r) - z * z);
    return norm * std::exp(-0.5 * (in2 / (sb * sb) + z * z / (st * st)));
  };
  const double cuts[4] = { centre - 8.0 * width, centre - 2.5 * width, centre + 2.5 * width,
    centre + 8.0 * width };
  const double tolAbs = 1e-13 * norm * width;
  double sum = 0.0;
  double prev = a;
  for (int i = 1; i < 4; ++i)
  {
    const double x = std::min(std::max(cuts[i], a), b);
    if (x > prev)
    {
      sum += GaussKronrod(f, prev, x, tolAbs, 0);
      prev = x;
    }
  }
  return sum;
}

// Integral over a (sub)triangle of d(p) times the line integral, RGB.
struct TriangleIntegrator
{
  const Triangle& T;
  const Ray& R;
  double Tolerance;

  Vec Point(const Vec& l) const
  {
    Vec p{ 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      p = (p + (this->T.P[k] * l[k]));
    }
    return p;
  }

  Vec Integrand(const Vec& l) const
  {
    const double sb = l[0] * T.SB[0] + l[1] * T.SB[1] + l[2] * T.SB[2];
    const double st = l[0] * T.ST[0] + l[1] * T.ST[1] + l[2] * T.ST[2];
    const double L = LineIntegral(this->R, this->Point(l), T.N, sb, st);
    Vec d{ 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      d = (d + (T.D[k] * l[k]));
    }
    return (d * L);
  }

  // degree-5 7-point rule (Radon) on the sub-triangle with barycentric corners a, b, c
  Vec Rule(const Vec& a, const Vec& b, const Vec& c, double area) const
  {
    static const double s15 = std::sqrt(15.0);
    static const double A1 = (6.0 - s15) / 21.0, B1 = (9.0 + 2.0 * s15) / 21.0;
    static const double A2 = (6.0 + s15) / 21.0, B2 = (9.0 - 2.0 * s15) / 21.0;
    static const double W0 = 9.0 / 40.0, W1 = (155.0 - s15) / 1200.0, W2 = (155.0 + s15) / 1200.0;
    auto at = [&](double x, double y, double z) {
      Vec l;
      for (int k = 0; k < 3; ++k)
      {
        l[k] = x * a[k] + y * b[k] + z * c[k];
      }
      return this->Integrand(l);
    };
    Vec s = (at(1.0 / 3, 1.0 / 3, 1.0 / 3) * W0);
    s = (s + (((at(A1, A1, B1) + at(A1, B1, A1)) + at(B1, A1, A1)) * W1));
    s = (s + (((at(A2, A2, B2) + at(A2, B2, A2)) + at(B2, A2, A2)) * W2));
    return (s * area);
  }

  // Both distances are lower bounds of the distance between the ray and the
  // (sub)triangle: from the ray segment to its bounding sphere, and from the
  // ray's infinite line to the triangle itself (exact for slivers, whose
  // bounding spheres are huge).
  bool Culled(const Vec& a, const Vec& b, const Vec& c) const
  {
    const Vec pa = this->Point(a), pb = this->Point(b), pc = this->Point(c);
    const Vec centre = (((pa + pb) + pc) * (1.0 / 3.0));
    const double r =
      std::max({ glm::length((pa - centre)), glm::length((pb - centre)), glm::length((pc - centre)) });
    if (RayDistance(this->R, centre) > r + T.Reach)
    {
      return true;
    }
    return LineTriangleDistance(this->R, pa, pb, pc) > T.Reach;
  }

  // Longest-edge bisection: a sliver (real stream sheets have triangles
  // metres long and millimetres wide) is cut along its length only, so the
  // pieces far from the ray are culled early; 4-way midpoint subdivision
  // kept slivers' aspect and multiplied the work by 4 per level.
  Vec Recurse(const Vec& a, const Vec& b, const Vec& c, const Vec& estimate, double area, int level) const
  {
    const Vec pa = this->Point(a), pb = this->Point(b), pc = this->Point(c);
    const double lab = glm::length((pa - pb)), lbc = glm::length((pb - pc)), lca = glm::length((pc - pa));
    const double diameter = std::max({ lab, lbc, lca });
    // (u, v) the longest edge, w the opposite corner
    const Vec& u = lab >= lbc && lab >= lca ? a : (lbc >= lca ? b : c);
    const Vec& v = lab >= lbc && lab >= lca ? b : (lbc >= lca ? c : a);
    const Vec& w = lab >= lbc && lab >= lca ? c : (lbc >= lca ? a : b);
    const Vec m = ((u + v) * 0.5);
    const Vec kids[2][3] = { { u, m, w }, { m, v, w } };
    const double q = 0.5 * area;
    Vec parts[2];
    bool culled[2];
    Vec sum{ 0, 0, 0 };
    for (int k = 0; k < 2; ++k)
    {
      culled[k] = this->Culled(kids[k][0], kids[k][1], kids[k][2]);
      parts[k] = culled[k] ? Vec{ 0, 0, 0 } : this->Rule(kids[k][0], kids[k][1], kids[k][2], q);
      sum = (sum + parts[k]);
    }
    // resolve sigma_b before trusting the error estimate
    const double sbMin = std::min({ a[0] * T.SB[0] + a[1] * T.SB[1] + a[2] * T.SB[2],
      b[0] * T.SB[0] + b[1] * T.SB[1] + b[2] * T.SB[2],
      c[0] * T.SB[0] + c[1] * T.SB[1] + c[2] * T.SB[2] });
    const double err = std::max({ std::fabs(sum[0] - estimate[0]), std::fabs(sum[1] - estimate[1]),
      std::fabs(sum[2] - estimate[2]) });
    // the error budget is shared by the part of the triangle the ray can see
    const double relevant = std::min(T.Area, Pi * T.Reach * T.Reach);
    const double tol = this->Tolerance * std::max(std::min(1.0, area / relevant), 1e-3);
    if (level >= 40 || (diameter <= 3.0 * sbMin && err <= tol))
    {
      return sum;
    }
    Vec total{ 0, 0, 0 };
    for (int k = 0; k < 2; ++k)
    {
      if (!culled[k])
      {
        total = (total + this->Recurse(kids[k][0], kids[k][1], kids[k][2], parts[k], q, level + 1));
      }
    }
    return total;
  }

  Vec Integrate() const
  {
    const Vec a{ 1, 0, 0 }, b{ 0, 1, 0 }, c{ 0, 0, 1 };
    if (this->Culled(a, b, c))
    {
      return { 0, 0, 0 };
    }
    return this->Recurse(a, b, c, this->Rule(a, b, c, T.Area), T.Area, 0);
  }
};

void Apply(const double m[16], const Vec& p, double out[4])
{
  for (int r = 0; r < 4; ++r)
  {
    out[r] = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3];
  }
}

Vec Unproject(const double inv[16], double x, double y, double z)
{
  double in[4] = { x, y, z, 1.0 };
  double out[4];
  for (int r = 0; r < 4; ++r)
  {
    out[r] = inv[4 * r] * in[0] + inv[4 * r + 1] * in[1] + inv[4 * r + 2] * in[2] + inv[4 * r + 3];
  }
  return { out[0] / out[3], out[1] / out[3], out[2] / out[3] };
}

vtkDataArray* ReferenceArray(vtkPolyData* poly, const std::string& name, int comps)
{
  if (name.empty())
  {
    return nullptr;
  }
  vtkDataArray* a = poly->GetPointData()->GetArray(name.c_str());
  return a && a->GetNumberOfTuples() == poly->GetNumberOfPoints() && a->GetNumberOfComponents() >= comps
    ? a
    : nullptr;
}
} // namespace

vtkPlumeSheetReference::vtkPlumeSheetReference() = default;
vtkPlumeSheetReference::~vtkPlumeSheetReference() = default;

void vtkPlumeSheetReference::SetModelMatrix(vtkMatrix4x4* matrix)
{
  if (matrix)
  {
    std::copy(matrix->GetData(), matrix->GetData() + 16, this->ModelMatrix);
  }
  else
  {
    vtkMatrix4x4::Identity(this->ModelMatrix);
  }
  this->Modified();
}

void vtkPlumeSheetReference::SetInputData(vtkPolyData* mesh)
{
  this->Mesh = mesh;
  this->Modified();
}

bool vtkPlumeSheetReference::Compute(vtkRenderer* renderer, const float* depth)
{
  vtkPolyData* poly = this->Mesh;
  if (!poly || !renderer || !renderer->GetActiveCamera())
  {
    vtkErrorMacro(<< "a mesh and a renderer with a camera are required");
    return false;
  }
  int w = 0, h = 0, x0 = 0, y0 = 0;
  renderer->GetTiledSizeAndOrigin(&w, &h, &x0, &y0);
  if (w < 1 || h < 1)
  {
    vtkErrorMacro(<< "the renderer has an empty viewport");
    return false;
  }
  this->Width = w;
  this->Height = h;
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkMatrix4x4* composite = camera->GetCompositeProjectionTransformMatrix(double(w) / h, -1, 1);
  double M[16], Minv[16];
  std::copy(composite->GetData(), composite->GetData() + 16, M);
  vtkMatrix4x4::Invert(M, Minv);

  // ---- triangles with the model's conventions
  vtkDataArray* dArr = ReferenceArray(poly, this->DensityArrayName, 1);
  vtkDataArray* bArr = ReferenceArray(poly, this->BlurArrayName, 1);
  vtkDataArray* tArr = ReferenceArray(poly, this->ThicknessArrayName, 1);
  vtkDataArray* aArr = ReferenceArray(poly, this->AbsorptionArrayName, 3);
  // model -> world: positions by the matrix, sigmas by its length scale
  const double* MM = this->ModelMatrix;
  const double lengthScale = std::cbrt(std::fabs(MM[0] * (MM[5] * MM[10] - MM[6] * MM[9]) -
    MM[1] * (MM[4] * MM[10] - MM[6] * MM[8]) + MM[2] * (MM[4] * MM[9] - MM[5] * MM[8])));
  auto pixelSize = [&](const Vec& p) {
    double c[4];
    Apply(M, p, c);
    if (!(c[3] > 0.0))
    {
      return 0.0;
    }
    const Vec q1 = Unproject(Minv, c[0] / c[3], c[1] / c[3], c[2] / c[3]);
    const Vec q2 = Unproject(Minv, c[0] / c[3], c[1] / c[3] + 2.0 / h, c[2] / c[3]);
    return glm::length((q2 - q1));
  };
  std::vector<Triangle> tris;
  auto add = [&](vtkIdType i0, vtkIdType i1, vtkIdType i2) {
    Triangle t;
    const vtkIdType ids[3] = { i0, i1, i2 };
    bool any = false;
    for (int k = 0; k < 3; ++k)
    {
      double m[3];
      poly->GetPoint(ids[k], m);
      double p[4];
      Apply(MM, { m[0], m[1], m[2] }, p);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) || !(p[3] != 0.0))
      {
        return;
      }
      t.P[k] = { p[0] / p[3], p[1] / p[3], p[2] / p[3] };
      const double d =
        ReferenceClean((dArr ? dArr->GetComponent(ids[k], 0) : this->Density) * this->DensityScale);
      for (int c = 0; c < 3; ++c)
      {
        t.D[k][c] = d * (aArr ? ReferenceClean(aArr->GetComponent(ids[k], c)) : 1.0);
        any = any || t.D[k][c] > 0;
      }
      const double floorSigma = this->MinimumSigmaPixels * pixelSize(t.P[k]);
      t.SB[k] = std::max(
        ReferenceClean(bArr ? bArr->GetComponent(ids[k], 0) : this->BlurRadius) * lengthScale, floorSigma);
      t.ST[k] = this->ThinSheet
        ? 0.0
        : std::max(
            ReferenceClean(tArr ? tArr->GetComponent(ids[k], 0) : this->Thickness) * lengthScale, floorSigma);
    }
    const Vec n = glm::cross((t.P[1] - t.P[0]), (t.P[2] - t.P[0]));
    const double nl = glm::length(n);
    if (!any || !(nl > 0.0) || !std::isfinite(nl))
    {
      return;
    }
    t.N = (n * (1.0 / nl));
    t.Area = 0.5 * nl;
    t.Centre = (((t.P[0] + t.P[1]) + t.P[2]) * (1.0 / 3.0));
    t.Radius = std::max(
      { glm::length((t.P[0] - t.Centre)), glm::length((t.P[1] - t.Centre)), glm::length((t.P[2] - t.Centre)) });
    t.Reach = Support * std::max({ t.SB[0], t.SB[1], t.SB[2], t.ST[0], t.ST[1], t.ST[2] });
    tris.push_back(t);
  };
  // Ghost cells (another piece owns them, or hidden) are not part of this
  // sheet. Cell ids count verts and lines first, then polys, then strips.
  vtkDataArray* ghostType = poly->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName());
  const vtkIdType polyBase = poly->GetNumberOfVerts() + poly->GetNumberOfLines();
  const vtkIdType stripBase = polyBase + poly->GetNumberOfPolys();
  auto isGhost = [&](vtkIdType cellId) {
    if (!ghostType || cellId >= ghostType->GetNumberOfTuples())
    {
      return false;
    }
    const int flags = static_cast<int>(ghostType->GetComponent(cellId, 0));
    return (flags & (vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL)) != 0;
  };
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  vtkCellArray* polys = poly->GetPolys();
  for (vtkIdType i = 0; i < polys->GetNumberOfCells(); ++i)
  {
    polys->GetCellAtId(i, npts, pts);
    if (isGhost(polyBase + i))
    {
      continue;
    }
    for (vtkIdType k = 1; k + 1 < npts; ++k)
    {
      add(pts[0], pts[k], pts[k + 1]);
    }
  }
  vtkCellArray* strips = poly->GetStrips();
  for (vtkIdType i = 0; i < strips->GetNumberOfCells(); ++i)
  {
    strips->GetCellAtId(i, npts, pts);
    if (isGhost(stripBase + i))
    {
      continue;
    }
    for (vtkIdType k = 0; k + 2 < npts; ++k)
    {
      add(pts[k], pts[k + 1], pts[k + 2]);
    }
  }

  // ---- screen tiles: which triangles' supports can reach which pixels
  const int tile = 16;
  const int tx = (w + tile - 1) / tile, ty = (h + tile - 1) / tile;
  std::vector<std::vector<int>> bins(static_cast<size_t>(tx) * ty);
  for (size_t i = 0; i < tris.size(); ++i)
  {
    const Triangle& t = tris[i];
    const double r = t.Radius + t.Reach;
    double lo[2] = { Huge, Huge }, hi[2] = { -Huge, -Huge };
    bool full = false;
    for (int c = 0; c < 8 && !full; ++c)
    {
      const Vec p = { t.Centre[0] + ((c & 1) ? r : -r), t.Centre[1] + ((c & 2) ? r : -r),
        t.Centre[2] + ((c & 4) ? r : -r) };
      double q[4];
      Apply(M, p, q);
      if (!(q[3] > 0.0))
      {
        full = true;
        break;
      }
      for (int a = 0; a < 2; ++a)
      {
        lo[a] = std::min(lo[a], q[a] / q[3]);
        hi[a] = std::max(hi[a], q[a] / q[3]);
      }
    }
    int b0[2] = { 0, 0 }, b1[2] = { tx - 1, ty - 1 };
    if (!full)
    {
      const int size[2] = { w, h };
      const int nt[2] = { tx, ty };
      bool off = false;
      for (int a = 0; a < 2; ++a)
      {
        const double p0 = (lo[a] + 1.0) * 0.5 * size[a] - 1.0;
        const double p1 = (hi[a] + 1.0) * 0.5 * size[a] + 1.0;
        if (p1 < 0 || p0 > size[a])
        {
          off = true;
        }
        b0[a] = std::max(0, std::min(nt[a] - 1, static_cast<int>(std::floor(std::max(p0, 0.0) / tile))));
        b1[a] = std::max(0, std::min(nt[a] - 1, static_cast<int>(std::floor(std::min(p1, double(size[a])) / tile))));
      }
      if (off)
      {
        continue;
      }
    }
    for (int by = b0[1]; by <= b1[1]; ++by)
    {
      for (int bx = b0[0]; bx <= b1[0]; ++bx)
      {
        bins[static_cast<size_t>(by) * tx + bx].push_back(static_cast<int>(i));
      }
    }
  }

  // ---- every pixel: its exact ray, the optical depth, the transmittance
  this->Transmittance.assign(static_cast<size_t>(w) * h * 3, std::numeric_limits<double>::quiet_NaN());
  const int stride = this->PixelStride;
  const int offset = this->PixelOffset % stride;
  const int rows = (h - offset + stride - 1) / stride;
  const bool bounded = this->BoundedByDepth;
  const double tol = this->Tolerance;
  std::vector<double>& out = this->Transmittance;
  vtkSMPTools::For(0, rows, [&](vtkIdType rb, vtkIdType re) {
    for (vtkIdType row = rb; row < re; ++row)
    {
      const int y = static_cast<int>(row) * stride + offset;
      for (int x = offset; x < w; x += stride)
      {
        const double nx = (x + 0.5) / w * 2.0 - 1.0;
        const double ny = (y + 0.5) / h * 2.0 - 1.0;
        Ray ray;
        ray.O = Unproject(Minv, nx, ny, -1.0);
        const Vec far = Unproject(Minv, nx, ny, 1.0);
        const Vec dir = (far - ray.O);
        ray.V = (dir * (1.0 / glm::length(dir)));
        ray.T0 = bounded ? 0.0 : -Huge;
        ray.T1 = Huge;
        if (bounded && depth)
        {
          const double dz = depth[static_cast<size_t>(y) * w + x];
          if (dz < 1.0)
          {
            ray.T1 = std::max(0.0, glm::dot((Unproject(Minv, nx, ny, 2.0 * dz - 1.0) - ray.O), ray.V));
          }
        }
        Vec tau{ 0, 0, 0 };
        for (int i : bins[static_cast<size_t>(y / tile) * tx + x / tile])
        {
          const Triangle& t = tris[i];
          if (RayDistance(ray, t.Centre) > t.Radius + t.Reach)
          {
            continue;
          }
          TriangleIntegrator integrator{ t, ray, tol };
          tau = (tau + integrator.Integrate());
        }
        for (int c = 0; c < 3; ++c)
        {
          out[3 * (static_cast<size_t>(y) * w + x) + c] = std::exp(-tau[c]);
        }
      }
    }
  });
  return true;
}

void vtkPlumeSheetReference::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DensityArrayName: " << this->DensityArrayName << "\n";
  os << indent << "Density: " << this->Density << "\n";
  os << indent << "BlurRadius: " << this->BlurRadius << "\n";
  os << indent << "Thickness: " << this->Thickness << "\n";
  os << indent << "ThinSheet: " << this->ThinSheet << "\n";
  os << indent << "BoundedByDepth: " << this->BoundedByDepth << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "PixelStride: " << this->PixelStride << "\n";
  os << indent << "PixelOffset: " << this->PixelOffset << "\n";
}
