#include "vtkPlumeAirlightReference.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkPlumeAirlightPass.h"
#include "vtkPointData.h"
#include "vtkMapper.h"
#include "vtkCellArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkPlumeAirlightReference);

namespace
{
using RGB = std::array<double, 3>;

RGB operator+(const RGB& a, const RGB& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2] };
}
RGB operator-(const RGB& a, const RGB& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
RGB operator*(double s, const RGB& a)
{
  return { s * a[0], s * a[1], s * a[2] };
}
double MaxAbs(const RGB& a)
{
  return std::max({ std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2]) });
}

// Adaptive Simpson for an RGB-valued integrand (error: the largest channel's).
template <class F>
RGB ReferenceSimpson(const F& f, double a, const RGB& fa, double m, const RGB& fm, double b, const RGB& fb,
  const RGB& whole, double tol, int depth)
{
  const double lm = 0.5 * (a + m);
  const double rm = 0.5 * (m + b);
  const RGB flm = f(lm);
  const RGB frm = f(rm);
  const RGB left = ((m - a) / 6.0) * (fa + 4.0 * flm + fm);
  const RGB right = ((b - m) / 6.0) * (fm + 4.0 * frm + fb);
  const RGB delta = (left + right) - whole;
  // (A non-finite difference cannot shrink by subdividing: stop there too.)
  // The floor 1e-14 |left + right|: below it the difference is round-off and
  // halving the tolerance further would only multiply evaluations.
  const double floor = 1e-14 * MaxAbs(left + right);
  if (depth <= 0 || MaxAbs(delta) <= 15.0 * std::max(tol, floor) || !std::isfinite(MaxAbs(delta)))
  {
    return (left + right) + (1.0 / 15.0) * delta;
  }
  return ReferenceSimpson(f, a, fa, lm, flm, m, fm, left, 0.5 * tol, depth - 1) +
    ReferenceSimpson(f, m, fm, rm, frm, b, fb, right, 0.5 * tol, depth - 1);
}

template <class F>
RGB ReferenceIntegrate(const F& f, double a, double b, double tol)
{
  const double m = 0.5 * (a + b);
  const RGB fa = f(a), fm = f(m), fb = f(b);
  return ReferenceSimpson(f, a, fa, m, fm, b, fb, ((b - a) / 6.0) * (fa + 4.0 * fm + fb), tol, 50);
}
}

//------------------------------------------------------------------------------
vtkPlumeAirlightReference::vtkPlumeAirlightReference() = default;

//------------------------------------------------------------------------------
void vtkPlumeAirlightReference::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Lights: " << this->Lights.size() << "\n";
  os << indent << "RelativeTolerance: " << this->RelativeTolerance << "\n";
}

//------------------------------------------------------------------------------
// A binary bounding-volume hierarchy over the occluders' triangles (median
// split of the centroids on the longest axis, up to 4 triangles a leaf) and
// an exact segment-triangle test (Moller-Trumbore, double). VTK's locators
// test each candidate with vtkTriangle::IntersectWithLine and its tolerance
// checks against the three edges, which took most of the shadowed
// reference's time (TestAirlightPhase: 60 % of its CPU).
struct vtkPlumeAirlightReference::OccluderTree
{
  struct Node
  {
    glm::dvec3 Lo, Hi;
    int First = 0, Count = 0; // a leaf: triangles [First, First + Count)
    int Right = -1;           // an inner node: children at this + 1 and Right
  };
  std::vector<std::array<glm::dvec3, 3>> Triangles;
  std::vector<Node> Nodes;

  explicit OccluderTree(vtkPolyData* mesh)
  {
    vtkPoints* points = mesh->GetPoints();
    vtkCellArray* polys = mesh->GetPolys();
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
    {
      if (n != 3)
      {
        continue; // the triangle filter's output: only degenerate leftovers
      }
      std::array<glm::dvec3, 3> t;
      for (int k = 0; k < 3; ++k)
      {
        double p[3];
        points->GetPoint(ids[k], p);
        t[k] = glm::dvec3(p[0], p[1], p[2]);
      }
      this->Triangles.push_back(t);
    }
    if (!this->Triangles.empty())
    {
      this->Build(0, static_cast<int>(this->Triangles.size()));
    }
  }

  int Build(int first, int count)
  {
    const int index = static_cast<int>(this->Nodes.size());
    this->Nodes.emplace_back();
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    glm::dvec3 clo = lo, chi = hi;
    for (int i = first; i < first + count; ++i)
    {
      const auto& t = this->Triangles[i];
      const glm::dvec3 c = (t[0] + t[1] + t[2]) / 3.0;
      clo = glm::min(clo, c);
      chi = glm::max(chi, c);
      for (const auto& p : t)
      {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
    }
    this->Nodes[index].Lo = lo;
    this->Nodes[index].Hi = hi;
    if (count <= 4)
    {
      this->Nodes[index].First = first;
      this->Nodes[index].Count = count;
      return index;
    }
    const glm::dvec3 extent = chi - clo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const int half = count / 2;
    auto begin = this->Triangles.begin() + first;
    std::nth_element(begin, begin + half, begin + count, [axis](const auto& a, const auto& b) {
      return a[0][axis] + a[1][axis] + a[2][axis] < b[0][axis] + b[1][axis] + b[2][axis];
    });
    this->Build(first, half);
    const int right = this->Build(first + half, count - half);
    this->Nodes[index].Right = right;
    return index;
  }

  // Whether the segment a + s d, 0 < s < 1, meets the box.
  static bool SegmentMeetsBox(const glm::dvec3& a, const glm::dvec3& d, const Node& node)
  {
    double s0 = 0.0, s1 = 1.0;
    for (int c = 0; c < 3; ++c)
    {
      if (d[c] == 0.0)
      {
        if (a[c] < node.Lo[c] || a[c] > node.Hi[c])
        {
          return false;
        }
        continue;
      }
      double u = (node.Lo[c] - a[c]) / d[c], v = (node.Hi[c] - a[c]) / d[c];
      if (u > v)
      {
        std::swap(u, v);
      }
      s0 = std::max(s0, u);
      s1 = std::min(s1, v);
      if (s0 > s1)
      {
        return false;
      }
    }
    return true;
  }

  // Whether the segment a + s d, 0 < s < 1, crosses the triangle (its edges included).
  static bool SegmentCrossesTriangle(const glm::dvec3& a, const glm::dvec3& d, const std::array<glm::dvec3, 3>& t)
  {
    const glm::dvec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0 || !std::isfinite(det))
    {
      return false; // the segment parallel to the plane: it grazes, it does not cross
    }
    const glm::dvec3 w = a - t[0];
    const double u = glm::dot(w, p) / det;
    if (u < 0.0 || u > 1.0)
    {
      return false;
    }
    const glm::dvec3 q = glm::cross(w, e1);
    const double v = glm::dot(d, q) / det;
    if (v < 0.0 || u + v > 1.0)
    {
      return false;
    }
    const double s = glm::dot(e2, q) / det;
    return s > 0.0 && s < 1.0;
  }

  bool Crosses(const glm::dvec3& a, const glm::dvec3& b) const
  {
    if (this->Nodes.empty())
    {
      return false;
    }
    const glm::dvec3 d = b - a;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0)
    {
      const Node& node = this->Nodes[stack[--top]];
      if (!SegmentMeetsBox(a, d, node))
      {
        continue;
      }
      if (node.Right < 0)
      {
        for (int i = node.First; i < node.First + node.Count; ++i)
        {
          if (SegmentCrossesTriangle(a, d, this->Triangles[i]))
          {
            return true;
          }
        }
        continue;
      }
      const int left = static_cast<int>(&node - this->Nodes.data()) + 1;
      stack[top++] = left;
      stack[top++] = node.Right;
    }
    return false;
  }
};

//------------------------------------------------------------------------------
void vtkPlumeAirlightReference::SetOccluders(vtkRenderer* renderer)
{
  vtkNew<vtkAppendPolyData> append;
  int count = 0;
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    vtkPolyData* input =
      actor->GetMapper() ? vtkPolyData::SafeDownCast(actor->GetMapper()->GetInput()) : nullptr;
    if (!actor->GetVisibility() || !input || actor->GetProperty()->GetOpacity() < 1.0)
    {
      continue;
    }
    vtkNew<vtkTransform> transform;
    transform->SetMatrix(actor->GetMatrix());
    vtkNew<vtkTransformPolyDataFilter> world;
    world->SetInputData(input);
    world->SetTransform(transform);
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(world->GetOutputPort());
    triangles->Update();
    vtkNew<vtkPolyData> copy;
    copy->DeepCopy(triangles->GetOutput());
    append->AddInputData(copy);
    ++count;
  }
  this->Tree = nullptr;
  if (count == 0)
  {
    return;
  }
  append->Update();
  this->Tree = std::make_shared<const OccluderTree>(append->GetOutput());
}

//------------------------------------------------------------------------------
bool vtkPlumeAirlightReference::Visible(const double light[3], const double point[3]) const
{
  // The segment stops 1e-9 of its length short of both ends: a point on a
  // surface (or a light on one) does not shadow itself.
  const glm::dvec3 l(light[0], light[1], light[2]), p(point[0], point[1], point[2]);
  const glm::dvec3 d = p - l;
  return !this->Tree->Crosses(l + 1e-9 * d, p - 1e-9 * d);
}

//------------------------------------------------------------------------------
void vtkPlumeAirlightReference::SetLights(vtkRenderer* renderer)
{
  this->Lights.clear();
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch() || !light->GetPositional())
    {
      continue;
    }
    Light l;
    double focal[3], color[3], att[3];
    light->GetTransformedPosition(l.Position);
    light->GetTransformedFocalPoint(focal);
    light->GetDiffuseColor(color);
    light->GetAttenuationValues(att);
    double scale = light->GetIntensity() * this->IntensityScale;
    if (att[0] == 0.0 && att[1] == 0.0 && att[2] > 0.0)
    {
      scale /= att[2];
    }
    glm::dvec3 axis(focal[0] - l.Position[0], focal[1] - l.Position[1], focal[2] - l.Position[2]);
    const double len = glm::length(axis);
    axis = len > 0 ? axis / len : glm::dvec3(0, 0, -1);
    for (int c = 0; c < 3; ++c)
    {
      l.Axis[c] = axis[c];
      l.I0[c] = scale * color[c];
    }
    l.Spot = light->GetConeAngle() < 90.0;
    l.CosCone = std::cos(vtkMath::RadiansFromDegrees(light->GetConeAngle()));
    l.Exponent = light->GetExponent();
    l.Shadowed = this->Tree != nullptr; // spot and point lights alike
    // A spot light's projected image (the pass's documented rules).
    vtkImageData* image = l.Spot ? vtkPlumeAirlightPass::GetLightTexture(light) : nullptr;
    vtkDataArray* values = nullptr;
    int dims[3] = { 0, 0, 0 };
    if (image)
    {
      image->GetDimensions(dims);
      values = image->GetPointData()->GetScalars();
      if (!values && image->GetPointData()->GetNumberOfArrays() > 0)
      {
        values = image->GetPointData()->GetArray(0);
      }
    }
    if (values && dims[0] >= 1 && dims[1] >= 1 && dims[2] == 1 &&
      values->GetNumberOfTuples() == static_cast<vtkIdType>(dims[0]) * dims[1])
    {
      const int type = values->GetDataType();
      const double norm = type == VTK_UNSIGNED_CHAR ? 255.0 : (type == VTK_UNSIGNED_SHORT ? 65535.0 : 1.0);
      const int nc = values->GetNumberOfComponents();
      l.TextureWidth = dims[0];
      l.TextureHeight = dims[1];
      l.Texels.resize(3 * static_cast<size_t>(dims[0]) * dims[1]);
      for (vtkIdType id = 0; id < values->GetNumberOfTuples(); ++id)
      {
        for (int c = 0; c < 3; ++c)
        {
          const double x = values->GetComponent(id, nc < 3 ? 0 : c) / norm;
          l.Texels[3 * id + c] = (x > 0.0 && x < 1e30) ? x : 0.0; // NaN, negative, huge: 0
        }
      }
      glm::dvec3 hint(0.0, 1.0, 0.0);
      vtkInformation* info = light->GetInformation();
      if (info && info->Has(vtkPlumeAirlightPass::LIGHT_TEXTURE_UP()) &&
        info->Length(vtkPlumeAirlightPass::LIGHT_TEXTURE_UP()) == 3)
      {
        const double* u = info->Get(vtkPlumeAirlightPass::LIGHT_TEXTURE_UP());
        hint = glm::dvec3(u[0], u[1], u[2]);
      }
      glm::dvec3 right = glm::cross(axis, hint);
      if (!(glm::length(right) > 1e-9 * glm::length(hint)))
      {
        right = glm::cross(axis, glm::dvec3(0.0, 0.0, 1.0));
      }
      right = glm::normalize(right);
      const glm::dvec3 up = glm::cross(right, axis);
      const double tanCone = std::tan(vtkMath::RadiansFromDegrees(light->GetConeAngle()));
      for (int c = 0; c < 3; ++c)
      {
        l.TextureRight[c] = right[c] / tanCone;
        l.TextureUp[c] = up[c] / tanCone;
      }
    }
    this->Lights.push_back(l);
  }
}

//------------------------------------------------------------------------------
void vtkPlumeAirlightReference::ComputeLightTexture(int index, const double direction[3], double rgb[3]) const
{
  rgb[0] = rgb[1] = rgb[2] = 1.0;
  if (index >= 0 && index < static_cast<int>(this->Lights.size()) && this->Lights[index].TextureWidth > 0)
  {
    TextureAt(this->Lights[index], direction, rgb);
  }
}

//------------------------------------------------------------------------------
void vtkPlumeAirlightReference::TextureAt(const Light& light, const double v[3], double rgb[3])
{
  const double z = v[0] * light.Axis[0] + v[1] * light.Axis[1] + v[2] * light.Axis[2];
  double st[2];
  const double* axes[2] = { light.TextureRight, light.TextureUp };
  const int size[2] = { light.TextureWidth, light.TextureHeight };
  int lo[2], hi[2];
  double frac[2];
  for (int k = 0; k < 2; ++k)
  {
    const double q = v[0] * axes[k][0] + v[1] * axes[k][1] + v[2] * axes[k][2];
    // image coordinate in [0, 1] (z > 0 inside the cone), then texel units from the first centre
    const double u = z > 0.0 ? std::min(1.0, std::max(0.0, 0.5 + 0.5 * q / z)) : 0.5;
    st[k] = u * size[k] - 0.5;
    const double f = std::floor(st[k]);
    frac[k] = st[k] - f;
    lo[k] = std::min(std::max(static_cast<int>(f), 0), size[k] - 1);
    hi[k] = std::min(std::max(static_cast<int>(f) + 1, 0), size[k] - 1);
  }
  auto texel = [&](int i, int j, int c) { return light.Texels[3 * (static_cast<size_t>(j) * size[0] + i) + c]; };
  for (int c = 0; c < 3; ++c)
  {
    const double bottom = (1.0 - frac[0]) * texel(lo[0], lo[1], c) + frac[0] * texel(hi[0], lo[1], c);
    const double top = (1.0 - frac[0]) * texel(lo[0], hi[1], c) + frac[0] * texel(hi[0], hi[1], c);
    rgb[c] = (1.0 - frac[1]) * bottom + frac[1] * top;
  }
}

//------------------------------------------------------------------------------
void vtkPlumeAirlightReference::AddSmokeBox(const double bounds[6], double extinction, const double colour[3])
{
  SmokeBox b;
  std::copy(bounds, bounds + 6, b.Bounds);
  b.Extinction = extinction;
  std::copy(colour, colour + 3, b.Colour);
  this->Smoke.push_back(b);
}

std::vector<std::array<double, 2>> vtkPlumeAirlightReference::SmokeChords(const double o[3], const double r[3]) const
{
  std::vector<std::array<double, 2>> chords;
  for (const SmokeBox& b : this->Smoke)
  {
    double enter = -HUGE_VAL, leave = HUGE_VAL;
    for (int k = 0; k < 3; ++k)
    {
      if (r[k] == 0.0)
      {
        if (o[k] < b.Bounds[2 * k] || o[k] > b.Bounds[2 * k + 1])
        {
          enter = HUGE_VAL; // parallel to the slab and outside it
          leave = -HUGE_VAL;
        }
        continue;
      }
      double t0 = (b.Bounds[2 * k] - o[k]) / r[k];
      double t1 = (b.Bounds[2 * k + 1] - o[k]) / r[k];
      if (t0 > t1)
      {
        std::swap(t0, t1);
      }
      enter = std::max(enter, t0);
      leave = std::min(leave, t1);
    }
    chords.push_back({ std::max(enter, 0.0), leave });
  }
  return chords;
}

double vtkPlumeAirlightReference::SmokeDepth(const std::vector<std::array<double, 2>>& chords, double x) const
{
  double depth = 0.0;
  for (size_t k = 0; k < chords.size(); ++k)
  {
    const double len = std::min(x, chords[k][1]) - chords[k][0];
    if (len > 0.0)
    {
      depth += this->Smoke[k].Extinction * len;
    }
  }
  return depth;
}

void vtkPlumeAirlightReference::ComputeSmoke(const double origin[3], const double direction[3], double distance,
  double emission[3], double* transmittance) const
{
  const glm::dvec3 rn = glm::normalize(glm::dvec3(direction[0], direction[1], direction[2]));
  const double r[3] = { rn.x, rn.y, rn.z };
  const auto chords = this->SmokeChords(origin, r);
  double kt[3];
  for (int c = 0; c < 3; ++c)
  {
    kt[c] = this->Scattering[c] + this->Absorption[c];
    emission[c] = 0.0;
  }
  if (transmittance)
  {
    *transmittance = std::exp(-this->SmokeDepth(chords, distance));
  }
  for (size_t k = 0; k < chords.size(); ++k)
  {
    const double a = chords[k][0], b = std::min(chords[k][1], distance);
    if (!(b > a))
    {
      continue;
    }
    const SmokeBox& box = this->Smoke[k];
    auto f = [&](double x) -> RGB {
      const double T = std::exp(-this->SmokeDepth(chords, x));
      RGB v;
      for (int c = 0; c < 3; ++c)
      {
        v[c] = box.Colour[c] * box.Extinction * T * std::exp(-kt[c] * x);
      }
      return v;
    };
    // split at the other boxes' ends inside this chord (the integrand's kinks)
    std::vector<double> cuts = { a, b };
    for (const auto& c : chords)
    {
      for (double x : { c[0], c[1] })
      {
        if (x > a && x < b)
        {
          cuts.push_back(x);
        }
      }
    }
    std::sort(cuts.begin(), cuts.end());
    for (size_t p = 0; p + 1 < cuts.size(); ++p)
    {
      const RGB fa = f(cuts[p]), fb = f(cuts[p + 1]);
      const double scale = std::max(MaxAbs(fa), MaxAbs(fb)) * (cuts[p + 1] - cuts[p]);
      const RGB v = ReferenceIntegrate(f, cuts[p], cuts[p + 1], this->RelativeTolerance * scale + 1e-300);
      for (int c = 0; c < 3; ++c)
      {
        emission[c] += v[c];
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkPlumeAirlightReference::ComputeRay(
  const double origin[3], const double direction[3], double distance, double airlight[3]) const
{
  const glm::dvec3 o(origin[0], origin[1], origin[2]);
  const glm::dvec3 r = glm::normalize(glm::dvec3(direction[0], direction[1], direction[2]));
  double ks[3], kt[3];
  for (int c = 0; c < 3; ++c)
  {
    ks[c] = this->Scattering[c];
    kt[c] = this->Scattering[c] + this->Absorption[c];
    airlight[c] = 0.0;
  }
  const bool infinite = std::isinf(distance);
  const double hg = this->ScatteringAnisotropy;
  const double rArray[3] = { r.x, r.y, r.z };
  const auto chords = this->SmokeChords(origin, rArray);
  for (const Light& light : this->Lights)
  {
    const glm::dvec3 L(light.Position[0], light.Position[1], light.Position[2]);
    const glm::dvec3 axis(light.Axis[0], light.Axis[1], light.Axis[2]);
    RGB coef;
    for (int c = 0; c < 3; ++c)
    {
      coef[c] = ks[c] * light.I0[c] / (4.0 * vtkMath::Pi());
    }
    auto inside = [&](double x) {
      if (light.Spot)
      {
        const glm::dvec3 v = o + x * r - L;
        const double len = glm::length(v);
        if (!(len > 0.0 && glm::dot(v, axis) >= light.CosCone * len))
        {
          return false;
        }
      }
      if (light.Shadowed)
      {
        const glm::dvec3 q = o + x * r;
        const double point[3] = { q.x, q.y, q.z };
        return this->Visible(light.Position, point);
      }
      return true;
    };
    auto f = [&](double x) -> RGB {
      const glm::dvec3 v = o + x * r - L;
      const double d2 = glm::dot(v, v);
      const double d = std::sqrt(d2);
      double w = 1.0;
      if (light.Spot)
      {
        const double cosAngle = d > 0.0 ? glm::dot(v, axis) / d : 1.0;
        w = cosAngle >= light.CosCone ? std::pow(std::max(cosAngle, 0.0), light.Exponent) : 0.0;
      }
      if (hg != 0.0 && d > 0.0)
      {
        // Henyey-Greenstein relative to the isotropic 1/(4 pi) already in coef:
        // the light travels along v / d, the eye receives along -r.
        const double cosScatter = -glm::dot(v, r) / d;
        w *= (1.0 - hg * hg) / std::pow(1.0 + hg * hg - 2.0 * hg * cosScatter, 1.5);
      }
      // the smoke's optical depth between the eye and the scattering point
      const double smoke = chords.empty() ? 0.0 : this->SmokeDepth(chords, x);
      double tint[3] = { 1.0, 1.0, 1.0 };
      if (light.TextureWidth > 0 && w > 0.0)
      {
        const double vv[3] = { v.x, v.y, v.z };
        TextureAt(light, vv, tint);
      }
      RGB value;
      for (int c = 0; c < 3; ++c)
      {
        // exp of the sum: 1/d^2 and the extinction never meet as inf * 0.
        value[c] = (d2 > 0.0 && w * tint[c] > 0.0)
          ? coef[c] * w * tint[c] * std::exp(-kt[c] * (x + d) - std::log(d2) - smoke)
          : 0.0;
      }
      return value;
    };
    // Infinite tail [X, inf): x = X + s / (1 - s).
    auto mapped = [&](double X) {
      return [&, X](double s) -> RGB {
        if (s >= 1.0)
        {
          return { 0.0, 0.0, 0.0 };
        }
        const double w = 1.0 - s;
        return (1.0 / (w * w)) * f(X + s / w);
      };
    };

    // Breakpoints: the peak around the foot point, then the cone's boundaries.
    const double tc = glm::dot(L - o, r);
    const double h = glm::length(L - o - tc * r);
    std::vector<double> breaks = { 0.0 };
    for (double k : { -16.0, -4.0, -1.0, 0.0, 1.0, 4.0, 16.0 })
    {
      const double x = tc + k * h;
      if (x > 0.0 && (infinite || x < distance))
      {
        breaks.push_back(x);
      }
    }
    // the smoke boxes' ends: kinks of the transmittance
    for (const auto& c : chords)
    {
      for (double x : { c[0], c[1] })
      {
        if (c[0] < c[1] && x > 0.0 && std::isfinite(x) && (infinite || x < distance))
        {
          breaks.push_back(x);
        }
      }
    }
    std::sort(breaks.begin(), breaks.end());
    const double lastFinite = infinite ? breaks.back() : distance;
    if (!infinite)
    {
      breaks.push_back(distance);
    }
    if (light.Spot || light.Shadowed)
    {
      // Sample the inside test (cone and shadow) on every piece (the infinite one in s) and bisect changes.
      std::vector<double> extra;
      auto xOf = [&](size_t piece, double u) {
        if (piece + 1 < breaks.size())
        {
          return breaks[piece] + u * (breaks[piece + 1] - breaks[piece]);
        }
        return lastFinite + u / (1.0 - u); // the infinite tail, u < 1
      };
      const size_t pieces = infinite ? breaks.size() : breaks.size() - 1;
      const int samples = 256;
      for (size_t p = 0; p < pieces; ++p)
      {
        const double uMax = (p + 1 < breaks.size()) ? 1.0 : 1.0 - 1e-9;
        double u0 = 0.0;
        bool in0 = inside(xOf(p, u0));
        for (int k = 1; k <= samples; ++k)
        {
          const double u1 = uMax * k / samples;
          const bool in1 = inside(xOf(p, u1));
          if (in1 != in0)
          {
            double a = u0, b = u1;
            for (int it = 0; it < 80; ++it)
            {
              const double mid = 0.5 * (a + b);
              (inside(xOf(p, mid)) == in0 ? a : b) = mid;
            }
            extra.push_back(xOf(p, 0.5 * (a + b)));
          }
          u0 = u1;
          in0 = in1;
        }
      }
      breaks.insert(breaks.end(), extra.begin(), extra.end());
      std::sort(breaks.begin(), breaks.end());
    }

    // Tolerance from a coarse first estimate, then the adaptive pass.
    auto piecewise = [&](double tol, bool coarse) {
      RGB sum = { 0, 0, 0 };
      for (size_t p = 0; p + 1 < breaks.size(); ++p)
      {
        const double a = breaks[p], b = breaks[p + 1];
        // A shadowed light: pieces between the found lit/shadow changes are
        // classified by the exact ray cast at their middle.
        if (b > a && (!light.Shadowed || inside(0.5 * (a + b))))
        {
          sum = sum + (coarse ? ((b - a) / 6.0) * (f(a) + 4.0 * f(0.5 * (a + b)) + f(b))
                              : ReferenceIntegrate(f, a, b, tol));
        }
      }
      if (infinite && (!light.Shadowed || inside(breaks.back() + 1.0)))
      {
        auto g = mapped(breaks.back());
        sum = sum + (coarse ? (1.0 / 6.0) * (g(0.0) + 4.0 * g(0.5) + g(1.0)) : ReferenceIntegrate(g, 0.0, 1.0, tol));
      }
      return sum;
    };
    const RGB estimate = piecewise(0.0, true);
    const double tol = this->RelativeTolerance * MaxAbs(estimate) + 1e-300;
    const RGB value = piecewise(tol, false);
    for (int c = 0; c < 3; ++c)
    {
      airlight[c] += value[c];
    }
  }
}

//------------------------------------------------------------------------------
void vtkPlumeAirlightReference::ComputeImage(vtkRenderer* renderer, int w, int h, const float* rgba,
  const float* depth, std::vector<float>& out, int stride, std::vector<float>* airlight) const
{
  out.assign(4 * static_cast<size_t>(w) * h, std::numeric_limits<float>::quiet_NaN());
  if (airlight)
  {
    airlight->assign(out.size(), std::numeric_limits<float>::quiet_NaN());
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkNew<vtkMatrix4x4> inverse;
  inverse->DeepCopy(
    camera->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1.0, 1.0));
  inverse->Invert();
  auto unproject = [&](double nx, double ny, double nz) {
    double in[4] = { nx, ny, nz, 1.0 };
    double p[4];
    inverse->MultiplyPoint(in, p);
    return glm::dvec3(p[0] / p[3], p[1] / p[3], p[2] / p[3]);
  };
  double eye[3];
  camera->GetPosition(eye);
  const bool perspective = !camera->GetParallelProjection();
  double kt[3];
  for (int c = 0; c < 3; ++c)
  {
    kt[c] = this->Scattering[c] + this->Absorption[c];
  }
  stride = std::max(stride, 1);
  for (int j = 0; j < h; j += stride)
  {
    for (int i = 0; i < w; i += stride)
    {
      const size_t p = static_cast<size_t>(j) * w + i;
      const double nx = (i + 0.5) / w * 2.0 - 1.0;
      const double ny = (j + 0.5) / h * 2.0 - 1.0;
      const glm::dvec3 nearPoint = unproject(nx, ny, -1.0);
      const glm::dvec3 farPoint = unproject(nx, ny, 1.0);
      const glm::dvec3 o = perspective ? glm::dvec3(eye[0], eye[1], eye[2]) : nearPoint;
      const glm::dvec3 dir = farPoint - o;
      double distance = std::numeric_limits<double>::infinity();
      if (depth[p] < 1.0f)
      {
        distance = glm::length(unproject(nx, ny, 2.0 * depth[p] - 1.0) - o);
      }
      double air[3];
      const double origin[3] = { o.x, o.y, o.z };
      const double direction[3] = { dir.x, dir.y, dir.z };
      this->ComputeRay(origin, direction, distance, air);
      double emission[3] = { 0, 0, 0 }, smokeT = 1.0;
      if (!this->Smoke.empty())
      {
        this->ComputeSmoke(origin, direction, distance, emission, &smokeT);
      }
      for (int c = 0; c < 3; ++c)
      {
        const double T = kt[c] == 0.0 ? 1.0 : std::exp(-kt[c] * distance);
        out[4 * p + c] = static_cast<float>(rgba[4 * p + c] * T * smokeT + emission[c] + air[c]);
        if (airlight)
        {
          (*airlight)[4 * p + c] = static_cast<float>(air[c]);
        }
      }
      out[4 * p + 3] = 1.0f;
      if (airlight)
      {
        (*airlight)[4 * p + 3] = 1.0f;
      }
    }
  }
}
