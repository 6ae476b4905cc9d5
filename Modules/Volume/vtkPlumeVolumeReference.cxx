#include "vtkPlumeVolumeReference.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkPlumeVolumeReference);

namespace
{
// GLM for the vector math (double precision; the shaders share nothing with this file)
using Vec3 = glm::dvec3;

/** A row-major 3x3 (VTK's layout) as a GLM matrix (column-major). */
glm::dmat3 RowMajor(const double m[9])
{
  return glm::transpose(glm::make_mat3(m));
}

// Everything one ray needs, prepared once per Compute().
struct Setup
{
  int Dims[3];
  std::vector<double> Values; // sanitised scalars, data units
  std::vector<unsigned char> Valid; // valid-point mask (1 inside the data); empty: all valid
  double Range[2];
  double BoxMin[3], BoxMax[3];
  double ClipToIndex[16];
  double Linear[9];  // index -> world, linear part
  double Normal[9];  // its inverse transpose
  double Inverse[9]; // its inverse
  // transfer functions tabulated finely over Range
  static constexpr int N = 65536;
  std::vector<double> Color; // 3 per entry
  std::vector<double> Opacity;
  double InvUnit;
  int Mode;
  double Iso;
  double Ambient, Diffuse, Specular, SpecularPower;
  std::vector<Vec3> LightDirs, LightColors;
  double Step, ShadowStep;
  bool Shade = false;   // composite with Phong-lit samples
  bool Nearest = false; // nearest-node instead of trilinear sampling
  int Width, Height;
  const std::vector<float>* Depth;

  // the scalar at p, interpolated over the valid nodes only; `weight` (if
  // given): their total trilinear weight (1 without a mask), which scales the
  // extinction so the data fades out over its last voxel
  double Field(const Vec3& p, double* weight = nullptr) const
  {
    const bool masked = !this->Valid.empty();
    if (this->Nearest)
    {
      size_t id = 0, stride = 1;
      for (int a = 0; a < 3; ++a)
      {
        const double x = std::min(std::max(p[a], 0.0), double(this->Dims[a] - 1));
        id += stride * static_cast<size_t>(std::floor(x + 0.5));
        stride *= this->Dims[a];
      }
      if (weight)
      {
        *weight = masked ? this->Valid[id] : 1.0;
      }
      return masked && !this->Valid[id] ? 0.0 : this->Values[id];
    }
    int i0[3];
    double f[3];
    for (int a = 0; a < 3; ++a)
    {
      const double x = std::min(std::max(p[a], 0.0), double(this->Dims[a] - 1));
      i0[a] = std::min(static_cast<int>(std::floor(x)), std::max(this->Dims[a] - 2, 0));
      f[a] = x - i0[a];
    }
    double v = 0, sum = 0;
    for (int c = 0; c < 8; ++c)
    {
      int ijk[3];
      double w = 1;
      for (int a = 0; a < 3; ++a)
      {
        const int bit = (c >> a) & 1;
        ijk[a] = std::min(i0[a] + bit, this->Dims[a] - 1);
        w *= bit ? f[a] : 1.0 - f[a];
      }
      const size_t id =
        ijk[0] + static_cast<size_t>(this->Dims[0]) * (ijk[1] + static_cast<size_t>(this->Dims[1]) * ijk[2]);
      if (w != 0 && (!masked || this->Valid[id]))
      {
        v += w * this->Values[id];
        sum += w;
      }
    }
    if (weight)
    {
      *weight = masked ? sum : 1.0;
    }
    return masked ? (sum > 0 ? v / sum : 0.0) : v;
  }

  // colour and opacity at scalar s
  void Transfer(double s, double rgb[3], double& alpha) const
  {
    const double span = this->Range[1] - this->Range[0];
    double x = span > 0 ? (s - this->Range[0]) / span * (N - 1) : 0.0;
    x = std::min(std::max(x, 0.0), double(N - 1));
    const int i = std::min(static_cast<int>(x), N - 2);
    const double f = x - i;
    for (int c = 0; c < 3; ++c)
    {
      rgb[c] = (1 - f) * this->Color[3 * i + c] + f * this->Color[3 * (i + 1) + c];
    }
    alpha = (1 - f) * this->Opacity[i] + f * this->Opacity[i + 1];
  }

  double Sigma(double alpha) const { return -std::log(1.0 - std::min(alpha, 1.0 - 1e-6)) * this->InvUnit; }

  // [t0, t1] of p + t d inside the box, within [lo, hi]; false if empty
  bool Clip(const Vec3& p, const Vec3& d, double lo, double hi, double& t0, double& t1) const
  {
    t0 = lo;
    t1 = hi;
    for (int a = 0; a < 3; ++a)
    {
      if (d[a] == 0.0)
      {
        if (p[a] < this->BoxMin[a] || p[a] > this->BoxMax[a])
        {
          return false;
        }
        continue;
      }
      const double ta = (this->BoxMin[a] - p[a]) / d[a];
      const double tb = (this->BoxMax[a] - p[a]) / d[a];
      t0 = std::max(t0, std::min(ta, tb));
      t1 = std::min(t1, std::max(ta, tb));
    }
    return t1 > t0;
  }

  Vec3 Unproject(double x, double y, double z) const
  {
    const double in[4] = { x, y, z, 1.0 };
    double out[4];
    vtkMatrix4x4::MultiplyPoint(this->ClipToIndex, in, out);
    return { out[0] / out[3], out[1] / out[3], out[2] / out[3] };
  }

  double LightTransmittance(const Vec3& p, const Vec3& e, double worldPerIndex) const
  {
    double t0, t1;
    if (!this->Clip(p, e, 0.0, 1e300, t0, t1))
    {
      return 1.0;
    }
    const int n = std::max(1, static_cast<int>(std::ceil(t1 / this->ShadowStep)));
    const double h = t1 / n;
    double tau = 0;
    for (int k = 0; k < n; ++k)
    {
      double rgb[3], a, w;
      this->Transfer(this->Field((p + (e * ((k + 0.5) * h))), &w), rgb, a);
      tau += this->Sigma(a) * w * h * worldPerIndex;
    }
    return std::exp(-tau);
  }

  // Phong lighting of `base` at p: central-difference normal (one voxel) turned
  // towards the viewer (the view direction if the gradient vanishes)
  void Phong(const double base[3], const Vec3& p, const Vec3& viewDir, double col[3]) const
  {
    Vec3 g;
    for (int a = 0; a < 3; ++a)
    {
      Vec3 e = { 0, 0, 0 };
      e[a] = 1;
      g[a] = this->Field((p + e)) - this->Field((p - e));
    }
    Vec3 nrm = (RowMajor(this->Normal) * g);
    const double l = glm::length(nrm);
    nrm = l > 1e-20 ? (nrm * (1.0 / l)) : viewDir;
    if (glm::dot(nrm, viewDir) < 0)
    {
      nrm = (nrm * -1.0);
    }
    for (int c = 0; c < 3; ++c)
    {
      col[c] = this->Ambient * base[c];
    }
    for (size_t li = 0; li < this->LightDirs.size(); ++li)
    {
      const Vec3& L = this->LightDirs[li];
      const double nl = std::max(glm::dot(nrm, L), 0.0);
      const Vec3 H = (L + viewDir);
      const double hl = glm::length(H);
      const double nh = hl > 1e-6 ? std::max(glm::dot(nrm, (H * (1.0 / hl))), 0.0) : 0.0;
      const double spec = nh > 0 ? std::pow(nh, this->SpecularPower) : 0.0;
      for (int c = 0; c < 3; ++c)
      {
        col[c] += (this->Diffuse * nl * base[c] + this->Specular * spec) * this->LightColors[li][c];
      }
    }
  }

  void Pixel(int x, int y, float out[4]) const
  {
    out[0] = out[1] = out[2] = out[3] = 0.0f;
    const double nx = 2.0 * (x + 0.5) / this->Width - 1.0;
    const double ny = 2.0 * (y + 0.5) / this->Height - 1.0;
    const Vec3 p0 = this->Unproject(nx, ny, -1.0);
    const Vec3 d = (this->Unproject(nx, ny, 1.0) - p0);
    double tEnd = 1.0;
    if (this->Depth && !this->Depth->empty())
    {
      const double z = (*this->Depth)[static_cast<size_t>(y) * this->Width + x];
      if (z < 1.0)
      {
        tEnd = glm::dot((this->Unproject(nx, ny, 2.0 * z - 1.0) - p0), d) / glm::dot(d, d);
      }
    }
    double t0, t1;
    if (!this->Clip(p0, d, 0.0, tEnd, t0, t1))
    {
      return;
    }
    const double dlen = glm::length(d);
    const double worldPerT = glm::length((RowMajor(this->Linear) * d));
    const int n = std::max(1, static_cast<int>(std::ceil((t1 - t0) * dlen / this->Step)));
    const double h = (t1 - t0) / n;
    const Vec3 viewDir = ((RowMajor(this->Linear) * d) * (-1.0 / worldPerT));

    if (this->Mode == vtkPlumeVolumeReference::MAXIMUM_INTENSITY)
    {
      double best = -std::numeric_limits<double>::infinity();
      for (int k = 0; k <= n; ++k)
      {
        double w;
        const double v = this->Field((p0 + (d * (t0 + k * h))), &w);
        if (w > 0.0) // samples with no valid node around do not count
        {
          best = std::max(best, v);
        }
      }
      if (!std::isfinite(best))
      {
        return;
      }
      double rgb[3], a;
      this->Transfer(best, rgb, a);
      for (int c = 0; c < 3; ++c)
      {
        out[c] = static_cast<float>(rgb[c] * a);
      }
      out[3] = static_cast<float>(a);
      return;
    }
    if (this->Mode == vtkPlumeVolumeReference::ISOSURFACE)
    {
      double tPrev = t0, w;
      double fPrev = this->Field((p0 + (d * t0)), &w) - this->Iso;
      bool prevInside = w > 0.0;
      for (int k = 1; k <= n; ++k)
      {
        const double t = t0 + k * h;
        const double f = this->Field((p0 + (d * t)), &w) - this->Iso;
        const bool inside = w > 0.0; // a crossing needs two samples with valid nodes around
        if (inside && prevInside && (fPrev < 0) != (f < 0))
        {
          double ta = tPrev, tb = t;
          for (int it = 0; it < 40; ++it)
          {
            const double tc = 0.5 * (ta + tb);
            const double fc = this->Field((p0 + (d * tc))) - this->Iso;
            ((fc < 0) == (fPrev < 0) ? ta : tb) = tc;
          }
          const Vec3 ph = (p0 + (d * (0.5 * (ta + tb))));
          double base[3], a, col[3];
          this->Transfer(this->Iso, base, a);
          this->Phong(base, ph, viewDir, col);
          for (int c = 0; c < 3; ++c)
          {
            out[c] = static_cast<float>(col[c]);
          }
          out[3] = 1.0f;
          return;
        }
        if (inside)
        {
          tPrev = t;
          fPrev = f;
        }
        prevInside = inside;
      }
      return;
    }

    // composite and smoke: emission–absorption, midpoint rule
    std::vector<Vec3> lightIndexDirs;
    std::vector<double> lightWorldPerIndex;
    if (this->Mode == vtkPlumeVolumeReference::SMOKE)
    {
      for (const Vec3& L : this->LightDirs)
      {
        Vec3 e = (RowMajor(this->Inverse) * L);
        e = (e * (1.0 / glm::length(e)));
        lightIndexDirs.push_back(e);
        lightWorldPerIndex.push_back(glm::length((RowMajor(this->Linear) * e)));
      }
    }
    double T = 1.0;
    double C[3] = { 0, 0, 0 };
    const double segment = h * worldPerT;
    for (int k = 0; k < n; ++k)
    {
      const Vec3 p = (p0 + (d * (t0 + (k + 0.5) * h)));
      double rgb[3], a, w;
      this->Transfer(this->Field(p, &w), rgb, a);
      const double sigma = this->Sigma(a) * w;
      if (sigma <= 0)
      {
        continue;
      }
      const double alpha = 1.0 - std::exp(-sigma * segment);
      if (this->Shade)
      {
        double lit[3];
        this->Phong(rgb, p, viewDir, lit);
        std::copy(lit, lit + 3, rgb);
      }
      double light[3] = { 1, 1, 1 };
      if (this->Mode == vtkPlumeVolumeReference::SMOKE)
      {
        light[0] = light[1] = light[2] = this->Ambient;
        for (size_t li = 0; li < this->LightDirs.size(); ++li)
        {
          const double tl = this->LightTransmittance(p, lightIndexDirs[li], lightWorldPerIndex[li]);
          for (int c = 0; c < 3; ++c)
          {
            light[c] += this->Diffuse * this->LightColors[li][c] * tl;
          }
        }
      }
      for (int c = 0; c < 3; ++c)
      {
        C[c] += T * alpha * rgb[c] * light[c];
      }
      T *= 1.0 - alpha;
    }
    for (int c = 0; c < 3; ++c)
    {
      out[c] = static_cast<float>(C[c]);
    }
    out[3] = static_cast<float>(1.0 - T);
  }
};
}

vtkPlumeVolumeReference::vtkPlumeVolumeReference()
  : IsoValue(std::numeric_limits<double>::quiet_NaN())
{
}

vtkPlumeVolumeReference::~vtkPlumeVolumeReference() = default;

void vtkPlumeVolumeReference::SetInputData(vtkImageData* image)
{
  this->Input = image;
}
void vtkPlumeVolumeReference::SetVolume(vtkVolume* volume)
{
  this->Volume = volume;
}
void vtkPlumeVolumeReference::SetRenderer(vtkRenderer* renderer)
{
  this->Renderer = renderer;
}

bool vtkPlumeVolumeReference::Compute(int width, int height)
{
  this->LastError.clear();
  this->Image.assign(4 * static_cast<size_t>(std::max(width, 0)) * std::max(height, 0), 0.0f);
  if (!this->Input || !this->Volume || !this->Renderer || width <= 0 || height <= 0)
  {
    this->LastError = "input, volume, renderer and a positive size are required";
    return false;
  }
  vtkImageData* image = this->Input;
  vtkDataArray* array = this->ArrayName.empty()
    ? image->GetPointData()->GetScalars()
    : image->GetPointData()->GetArray(this->ArrayName.c_str());
  if (!array)
  {
    this->LastError = "no point scalars named '" + this->ArrayName + "'";
    return false;
  }
  Setup s;
  image->GetDimensions(s.Dims);
  const vtkIdType n = image->GetNumberOfPoints();
  const int comps = array->GetNumberOfComponents();
  if (this->ScalarComponent >= comps)
  {
    this->LastError = "component out of range";
    return false;
  }
  s.Values.resize(n);
  std::vector<double> tuple(comps);
  for (vtkIdType i = 0; i < n; ++i)
  {
    array->GetTuple(i, tuple.data());
    double v;
    if (this->ScalarComponent >= 0)
    {
      v = tuple[this->ScalarComponent];
    }
    else if (comps == 1)
    {
      v = tuple[0];
    }
    else
    {
      v = 0;
      for (double c : tuple)
      {
        v += c * c;
      }
      v = std::sqrt(v);
    }
    s.Values[i] = v;
  }
  // valid-point mask: nodes outside the data are left out of everything
  vtkDataArray* mask = this->ValidMaskArrayName.empty()
    ? nullptr
    : image->GetPointData()->GetArray(this->ValidMaskArrayName.c_str());
  if (mask && mask->GetNumberOfComponents() == 1 && mask->GetNumberOfTuples() == n)
  {
    s.Valid.resize(n);
    bool any = false;
    for (vtkIdType i = 0; i < n; ++i)
    {
      s.Valid[i] = mask->GetComponent(i, 0) != 0.0 ? 1 : 0;
      any = any || !s.Valid[i];
    }
    if (!any)
    {
      s.Valid.clear();
    }
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = s.Values[i];
    if (!s.Valid.empty() && !s.Valid[i])
    {
      continue;
    }
    if (std::isfinite(v))
    {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (lo > hi)
  {
    lo = hi = 0;
  }
  for (double& v : s.Values)
  {
    if (std::isnan(v))
    {
      v = lo;
    }
    else if (std::isinf(v))
    {
      v = v > 0 ? hi : lo;
    }
  }
  s.Range[0] = lo;
  s.Range[1] = hi;

  // geometry: index -> data -> world -> clip
  int extent[6];
  image->GetExtent(extent);
  double origin[3], spacing[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  vtkMatrix3x3* direction = image->GetDirectionMatrix();
  double indexToData[16] = { 0 };
  for (int r = 0; r < 3; ++r)
  {
    double t = origin[r];
    for (int c = 0; c < 3; ++c)
    {
      indexToData[4 * r + c] = direction->GetElement(r, c) * spacing[c];
      t += direction->GetElement(r, c) * spacing[c] * extent[2 * c];
    }
    indexToData[4 * r + 3] = t;
  }
  indexToData[15] = 1;
  vtkNew<vtkMatrix4x4> volumeMatrix;
  this->Volume->GetMatrix(volumeMatrix);
  double indexToWorld[16];
  vtkMatrix4x4::Multiply4x4(volumeMatrix->GetData(), indexToData, indexToWorld);
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  vtkMatrix4x4* worldToClip =
    camera->GetCompositeProjectionTransformMatrix(double(width) / height, -1, 1);
  double indexToClip[16];
  vtkMatrix4x4::Multiply4x4(worldToClip->GetData(), indexToWorld, indexToClip);
  vtkMatrix4x4::Invert(indexToClip, s.ClipToIndex);
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      s.Linear[3 * r + c] = indexToWorld[4 * r + c];
    }
  }
  vtkMatrix3x3::Invert(s.Linear, s.Inverse);
  vtkMatrix3x3::Transpose(s.Inverse, s.Normal);
  for (int a = 0; a < 3; ++a)
  {
    s.BoxMin[a] = s.Dims[a] > 1 ? 0.0 : -0.5;
    s.BoxMax[a] = s.Dims[a] > 1 ? s.Dims[a] - 1.0 : 0.5;
  }

  // transfer functions
  vtkVolumeProperty* property = this->Volume->GetProperty();
  vtkColorTransferFunction* color = property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* gray =
    property->GetColorChannels(0) == 1 ? property->GetGrayTransferFunction(0) : nullptr;
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  s.Color.resize(3 * Setup::N);
  s.Opacity.resize(Setup::N);
  for (int i = 0; i < Setup::N; ++i)
  {
    const double v = lo + (hi - lo) * i / (Setup::N - 1.0);
    double rgb[3];
    if (gray)
    {
      rgb[0] = rgb[1] = rgb[2] = gray->GetValue(v);
    }
    else
    {
      color->GetColor(v, rgb);
    }
    std::copy(rgb, rgb + 3, &s.Color[3 * i]);
    s.Opacity[i] = std::min(1.0, std::max(0.0, opacity->GetValue(v)));
  }
  // the property's unit distance; at 0 (automatic) one voxel, the mean |spacing|
  double unit = property->GetScalarOpacityUnitDistance(0);
  if (!(unit > 0) || !std::isfinite(unit))
  {
    unit = (std::fabs(spacing[0]) + std::fabs(spacing[1]) + std::fabs(spacing[2])) / 3.0;
  }
  s.InvUnit = unit > 0 ? 1.0 / unit : 1.0;
  s.Mode = this->Mode;
  double iso = this->IsoValue;
  if (!std::isfinite(iso) && property->GetIsoSurfaceValues()->GetNumberOfContours() > 0)
  {
    iso = property->GetIsoSurfaceValues()->GetValue(0);
  }
  s.Iso = std::isfinite(iso) ? iso : lo + 0.5 * (hi - lo);
  s.Ambient = property->GetAmbient(0);
  s.Diffuse = property->GetDiffuse(0);
  s.Specular = property->GetSpecular(0);
  s.SpecularPower = property->GetSpecularPower(0);
  s.Shade = this->Mode == COMPOSITE && property->GetShade(0) != 0;
  s.Nearest = property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION;

  // lights: switched-on lights (at most 4) as directions towards them
  vtkLightCollection* lights = this->Renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch() || s.LightDirs.size() >= 4)
    {
      continue;
    }
    double p[3], f[3], rgb[3];
    light->GetTransformedPosition(p);
    light->GetTransformedFocalPoint(f);
    Vec3 l = { p[0] - f[0], p[1] - f[1], p[2] - f[2] };
    const double len = glm::length(l);
    if (!(len > 0) || !std::isfinite(len))
    {
      continue;
    }
    light->GetDiffuseColor(rgb);
    const double k = light->GetIntensity();
    s.LightDirs.push_back((l * (1.0 / len)));
    s.LightColors.push_back({ rgb[0] * k, rgb[1] * k, rgb[2] * k });
  }
  if (s.LightDirs.empty())
  {
    double p[3], f[3];
    camera->GetPosition(p);
    camera->GetFocalPoint(f);
    Vec3 l = { p[0] - f[0], p[1] - f[1], p[2] - f[2] };
    s.LightDirs.push_back((l * (1.0 / glm::length(l))));
    s.LightColors.push_back({ 1, 1, 1 });
  }
  s.Step = this->Step > 0 ? this->Step : 0.125;
  s.ShadowStep = this->ShadowStep > 0 ? this->ShadowStep : 0.25;
  s.Width = width;
  s.Height = height;
  if (!this->OpaqueDepth.empty() && this->OpaqueDepth.size() != static_cast<size_t>(width) * height)
  {
    this->LastError = "the opaque depth image does not match the size";
    return false;
  }
  s.Depth = &this->OpaqueDepth;

  float* out = this->Image.data();
  const int stride = this->PixelStride;
  vtkSMPTools::For(0, height, [&](vtkIdType y0, vtkIdType y1) {
    for (vtkIdType y = y0; y < y1; ++y)
    {
      if (y % stride != 0)
      {
        continue;
      }
      for (int x = 0; x < width; x += stride)
      {
        s.Pixel(x, static_cast<int>(y), out + 4 * (static_cast<size_t>(y) * width + x));
      }
    }
  });
  return true;
}

std::vector<float> vtkPlumeVolumeReference::CompositeOver(const std::vector<float>& background) const
{
  std::vector<float> result(this->Image.size());
  for (size_t p = 0; p + 3 < this->Image.size() && p + 3 < background.size(); p += 4)
  {
    const double a = this->Image[p + 3];
    for (int c = 0; c < 3; ++c)
    {
      result[p + c] = static_cast<float>(this->Image[p + c] + (1.0 - a) * background[p + c]);
    }
    result[p + 3] = static_cast<float>(1.0 - (1.0 - a) * (1.0 - background[p + 3]));
  }
  return result;
}

void vtkPlumeVolumeReference::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->Mode << "\n";
  os << indent << "Step: " << this->Step << "\n";
  os << indent << "ShadowStep: " << this->ShadowStep << "\n";
  os << indent << "PixelStride: " << this->PixelStride << "\n";
}
