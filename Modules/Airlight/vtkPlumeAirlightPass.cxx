#include "vtkPlumeAirlightPass.h"

#include "vtkPlumeAirlightFS.h"
#include "vtkPlumeLightTexture.h"
#include "vtkPlumeCompositingPass.h"
#include "vtkPlumeGLMatrix.h"
#include "vtkPlumeLatticeCellsDraw.h"
#include "vtkPlumeLatticeCellsVS.h"
#include "vtkPlumeOpaqueDepthTexture.h"
#include "vtkPlumeParameterTable.h"
#include "vtkPlumeShaderFeatures.h"
#include "vtkPlumeShaderProgramCache.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkPointData.h"
#include "vtkOpaquePass.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPixelBufferObject.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"
#include "vtk_glew.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <string>

vtkStandardNewMacro(vtkPlumeAirlightPass);
vtkInformationKeyMacro(vtkPlumeAirlightPass, LIGHT_TEXTURE, ObjectBase);
vtkInformationKeyMacro(vtkPlumeAirlightPass, LIGHT_TEXTURE_UP, DoubleVector);

namespace
{
// The light's information, made if it has none yet.
vtkInformation* LightInformation(vtkLight* light)
{
  if (!light->GetInformation())
  {
    vtkNew<vtkInformation> info;
    light->SetInformation(info);
  }
  return light->GetInformation();
}

// The array holding an image's texels: its scalars, else its first point array.
vtkDataArray* TexelValues(vtkImageData* image)
{
  vtkDataArray* values = image->GetPointData()->GetScalars();
  if (!values && image->GetPointData()->GetNumberOfArrays() > 0)
  {
    values = image->GetPointData()->GetArray(0);
  }
  return values;
}
}

//------------------------------------------------------------------------------
void vtkPlumeAirlightPass::SetLightTexture(vtkLight* light, vtkImageData* image)
{
  if (!light)
  {
    return;
  }
  if (image)
  {
    LightInformation(light)->Set(LIGHT_TEXTURE(), image);
  }
  else
  {
    LightInformation(light)->Remove(LIGHT_TEXTURE());
  }
  light->Modified();
}

vtkImageData* vtkPlumeAirlightPass::GetLightTexture(vtkLight* light)
{
  vtkInformation* info = light ? light->GetInformation() : nullptr;
  return info ? vtkImageData::SafeDownCast(info->Get(LIGHT_TEXTURE())) : nullptr;
}

void vtkPlumeAirlightPass::SetLightTextureUp(vtkLight* light, double x, double y, double z)
{
  if (!light)
  {
    return;
  }
  const double up[3] = { x, y, z };
  LightInformation(light)->Set(LIGHT_TEXTURE_UP(), up, 3);
  light->Modified();
}

namespace
{
// The light's image if it projects one this frame: a spot light with a 2D
// image (x-y plane) that has point values.
vtkImageData* ProjectedTexture(vtkLight* light)
{
  vtkImageData* image = vtkPlumeAirlightPass::GetLightTexture(light);
  if (!image || !(light->GetConeAngle() < 90.0))
  {
    return nullptr;
  }
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* values = TexelValues(image);
  if (dims[0] < 1 || dims[1] < 1 || dims[2] != 1 || !values ||
    values->GetNumberOfTuples() != static_cast<vtkIdType>(dims[0]) * dims[1])
  {
    return nullptr;
  }
  return image;
}

// The image's RGB (see SetLightTexture's rules) appended as RGBA floats, row by row.
void AppendTexels(vtkImageData* image, std::vector<float>& atlas, int atlasWidth)
{
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* values = TexelValues(image);
  const int nc = values->GetNumberOfComponents();
  double scale = 1.0;
  if (values->GetDataType() == VTK_UNSIGNED_CHAR)
  {
    scale = 1.0 / 255.0;
  }
  else if (values->GetDataType() == VTK_UNSIGNED_SHORT)
  {
    scale = 1.0 / 65535.0;
  }
  const size_t row0 = atlas.size();
  atlas.resize(row0 + 4 * size_t(atlasWidth) * dims[1], 0.0f);
  for (int j = 0; j < dims[1]; ++j)
  {
    for (int i = 0; i < dims[0]; ++i)
    {
      const vtkIdType id = i + static_cast<vtkIdType>(j) * dims[0];
      float* out = &atlas[row0 + 4 * (size_t(j) * atlasWidth + i)];
      for (int c = 0; c < 3; ++c)
      {
        const double v = values->GetComponent(id, nc >= 3 ? c : 0) * scale;
        out[c] = (v > 0.0 && v < 1e30) ? static_cast<float>(v) : 0.0f;
      }
      out[3] = 1.0f;
    }
  }
}
}

// One spot light's shadow map: the light's camera, a depth (+ unused colour)
// target and the key it was baked for.
struct vtkPlumeAirlightPass::ShadowMap
{
  vtkNew<vtkCamera> Camera;
  vtkOpenGLFramebufferObject* FrameBuffer = nullptr;
  vtkTextureObject* Depth = nullptr;
  vtkTextureObject* Color = nullptr;
  // What the shader reads: RG32F with a full mip chain, level 0 the depth
  // (twice), level L the (min, max) of the texels it covers at level L - 1.
  vtkTextureObject* MinMax = nullptr;
  int Top = 0;  // MinMax's highest level (0: no pyramid)
  int Size = 0; // the map's (a face's) size when baked
  std::vector<double> Key;
  double Near = 0, Far = 1;
  // 1 for a spot light (the whole texture); 6 for a point light: the faces
  // +x, -x, +y, -y, +z, -z (world axes) as tiles (f % 3, f / 3) of a 3 x 2 atlas.
  int Faces = 1;
  double WorldToClip[6][16]; // per face, row-major, with the renderer's aspect ratio

  void Release()
  {
    for (vtkTextureObject** t : { &this->Depth, &this->Color, &this->MinMax })
    {
      if (*t)
      {
        (*t)->Delete();
        *t = nullptr;
      }
    }
    if (this->FrameBuffer)
    {
      this->FrameBuffer->Delete();
      this->FrameBuffer = nullptr;
    }
    this->Key.clear();
  }
};

namespace
{
constexpr int MaximumLights = 8;
// The airlight lattice: a pixel whose eye depth differs by more than this
// (relative) from the plane through its cell's corners lies on another
// surface (a silhouette, an object smaller than a cell) and its cell is
// refined. Window depth is stored as float: on a plane the mismatch is
// rounding; on the benchmark's sphere, bilinear depth over 8 pixels is
// within about 3e-4.
constexpr double LatticeDepthTolerance = 1e-3;
// Spots narrower than this (cone half-angle, degrees) can make a shaft
// thinner than a lattice cell: the cells along their axis are refined.
constexpr double NarrowSpotAngle = 10.0;

// The airlight lattice's levels for downsampling D, at most `wanted` of them,
// on a w x h viewport (w, h >= 2): each level's node spacing (D, then halved
// while it is even and its half at least 2) and cells per row and column;
// returns how many levels.
int LatticeGeometry(int D, int wanted, int w, int h, int spacing[], int count[][2])
{
  int levels = 0;
  for (int s = D; levels < wanted; s /= 2)
  {
    spacing[levels] = s;
    count[levels][0] = (w - 2) / s + 1;
    count[levels][1] = (h - 2) / s + 1;
    ++levels;
    if (s % 2 != 0 || s / 2 < 2)
    {
      break;
    }
  }
  return levels;
}

// The size of lattice level l's nodes texture along `axis`: level 0 its
// nodes in order (cells + 1); level 1 those it evaluates, 64 a row (at most
// all of its nodes).
int LatticeNodesSize(const int count[][2], int l, int axis)
{
  return l == 0 ? count[0][axis] + 1 : axis == 0 ? 64 : ((count[l][0] + 1) * (count[l][1] + 1) + 63) / 64;
}

// The airlight's fragment shader with the textured lights' shared GLSL in it
// (one string for the process: the program cache knows templates by address).
const char* AirlightSource()
{
  static const std::string source = [] {
    std::string fs = vtkPlumeAirlightFS;
    vtkShaderProgram::Substitute(fs, "//PLUME::LightTexture", vtkPlumeLightTexture, false);
    return fs;
  }();
  return source.c_str();
}

// Adaptive Simpson on [a, b] to absolute tolerance `tol` (the table's
// integrands are smooth and bounded; the depth limit only guards round-off).
template <class F>
double Simpson(const F& f, double a, double fa, double m, double fm, double b, double fb,
  double whole, double tol, int depth)
{
  const double lm = 0.5 * (a + m);
  const double rm = 0.5 * (m + b);
  const double flm = f(lm);
  const double frm = f(rm);
  const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
  const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  const double delta = left + right - whole;
  if (depth <= 0 || std::fabs(delta) <= 15.0 * tol)
  {
    return left + right + delta / 15.0;
  }
  return Simpson(f, a, fa, lm, flm, m, fm, left, 0.5 * tol, depth - 1) +
    Simpson(f, m, fm, rm, frm, b, fb, right, 0.5 * tol, depth - 1);
}

template <class F>
double Integrate(const F& f, double a, double b, double tol)
{
  // Start from 8 panels so that a narrow boundary layer is not missed.
  double sum = 0.0;
  const int panels = 8;
  for (int k = 0; k < panels; ++k)
  {
    const double x0 = a + (b - a) * k / panels;
    const double x1 = a + (b - a) * (k + 1) / panels;
    const double xm = 0.5 * (x0 + x1);
    const double f0 = f(x0), fm = f(xm), f1 = f(x1);
    sum += Simpson(f, x0, f0, xm, fm, x1, f1, (x1 - x0) / 6.0 * (f0 + 4.0 * fm + f1),
      tol / panels, 48);
  }
  return sum;
}

// The table coordinates' stretch for the Henyey-Greenstein peak (see
// GetScatteringTable): 0 for g = 0, large as |g| -> 1.
double PhaseStretch(double g)
{
  return 2.0 * std::fabs(g) / (1.0 - std::fabs(g));
}

// The peaked function's rows (see GetScatteringTable; both 0 for k = 0).
// The warp r = sqrt(1 + k) - 1 spreads the rows evenly between the peak
// (width 1/(1+k)) and tau = 1: the row spacing in tau grows (1+r)^2 = 1 + k
// times from tau = 0 to 1 (with r = k, 19^2 times at g = 0.9: four rows held
// tau in [0.4, 1]). The weight slope w grows as k^3, as the peak's height
// over the phase at 90 degrees ((1+g^2)^1.5 / (1-g)^3, 2435 at g = 0.9,
// 11 at 0.5) that the rows' values cancel to (w = 91 at 0.9, 0.12 at 0.5).
double RowWarp(double k)
{
  return std::sqrt(1.0 + k) - 1.0;
}
double RowWeight(double k)
{
  return k * k * k / 64.0;
}
}

//------------------------------------------------------------------------------
void vtkPlumeAirlightPass::GetTableCoordinates(double g, double coordinates[6])
{
  const double kH = g > 0.0 ? PhaseStretch(g) : 0.0;
  const double kG = g < 0.0 ? PhaseStretch(g) : 0.0;
  const double values[6] = { kH, kG, RowWarp(kH), RowWarp(kG), RowWeight(kH), RowWeight(kG) };
  std::copy(values, values + 6, coordinates);
}

namespace
{
std::vector<double> ComputeTable(int n, double g)
{
  std::vector<double> table(2 * static_cast<size_t>(n) * n);
  const double tol = 1e-11;
  // The head function H carries the forward peak (g > 0), the tail G the
  // backward one (g < 0): each gets the stretch of the peak it has.
  double k[6];
  vtkPlumeAirlightPass::GetTableCoordinates(g, k);
  const double kH = k[0], kG = k[1], rH = k[2], rG = k[3], wH = k[4], wG = k[5];
  const double a = (1.0 + g) * (1.0 + g);
  const double b = (1.0 - g) * (1.0 - g);
  const double c = 1.0 - g * g;
  // Rows are independent: vtkSMPTools (threads with the STDThread backend).
  vtkSMPTools::For(0, n, [&](int rowBegin, int rowEnd) {
  for (int j = rowBegin; j < rowEnd; ++j)
  {
    // Row j: u = j/(n-1); tau (or eps) = u / (1 + r (1 - u)) inverts u = tau (1+r) / (1 + r tau).
    const double u = static_cast<double>(j) / (n - 1);
    const double tau = u / (1.0 + rH * (1.0 - u));
    const double eps = u / (1.0 + rG * (1.0 - u));
    const double t2 = tau * tau;
    const double e2 = eps * eps;
    // m's scale, row by row. H: a forward peak (width 1/(1+kH) in tau) puts
    // its m-dependence at m ~ 1 + kH tau (the decay over the peak, whose
    // integral the row's value is made of beyond tau ~ 1/kH): m = m' (1 + kH tau).
    // G: a backward peak puts it at m ~ 1/(1 + kG eps): m = m' / (1 + kG eps).
    // Beyond the peak both scales make m' ~ kt h (a ray's constant), so the
    // two ends of a ray's segment read the table at nearly the same column.
    const double sH = 1.0 + kH * tau;
    const double sG = 1.0 + kG * eps;
    // The row weights 1 + w tau (1 + w eps): beyond the peak the head function
    // is its integral over tau, H ~ A / tau, and a segment that misses the
    // peak is a small difference of two such values; stored as H (1 + w tau),
    // nearly constant there, the interpolation keeps that difference.
    const double fH = 1.0 + wH * tau;
    const double fG = 1.0 + wG * eps;
    for (int i = 0; i < n; ++i)
    {
      double* out = &table[2 * (static_cast<size_t>(j) * n + i)];
      if (i == n - 1)
      {
        // p = 1, m = infinity: m times the integrals tend to the integrands at 0.
        out[0] = fH * (1.0 + g) / ((1.0 - g) * (1.0 - g)) / sH;
        out[1] = fG * sG * c * std::sqrt(e2 + 1.0) / std::pow(a + b * e2, 1.5);
        continue;
      }
      // m' = p^2 / (1 - p^2): G has a k log k term at m = 0 that a uniform grid in
      // m / (1 + m) would only resolve to first order.
      const double p = static_cast<double>(i) / (n - 1);
      const double mp = p * p / (1.0 - p * p);
      const double mH = mp * sH;
      const double mG = mp / sG;
      // H: the phase 4 pi p_HG times 1 / (1 + s^2), s = tau q (g = 0: 1 / (1 + s^2)).
      auto h = [mH, t2, a, b, c](double q) {
        const double s2 = t2 * q * q;
        return std::exp(-mH * q) * c * std::sqrt(1.0 + s2) / std::pow(a * s2 + b, 1.5);
      };
      // G: y = z / (1 - z) maps [0, inf) to [0, 1); the integrand stays bounded.
      auto gg = [mG, e2, a, b, c](double z) {
        if (z >= 1.0)
        {
          return mG > 0.0 ? 0.0 : c / (a * std::sqrt(a));
        }
        const double w = 1.0 - z; // 1 + y = 1 / w
        return std::exp(-mG * z / w) * c * std::sqrt(e2 * w * w + 1.0) / std::pow(a + b * e2 * w * w, 1.5);
      };
      out[0] = fH * (1.0 + mp) * Integrate(h, 0.0, 1.0, tol / (1.0 + mp));
      out[1] = fG * (1.0 + mp) * Integrate(gg, 0.0, 1.0, tol / (1.0 + mp));
    }
  }
  });
  return table;
}
}

//------------------------------------------------------------------------------
const std::vector<double>& vtkPlumeAirlightPass::GetScatteringTable(int n, double g)
{
  static std::mutex mutex;
  static std::map<std::pair<int, double>, std::unique_ptr<std::vector<double>>> tables;
  std::lock_guard<std::mutex> lock(mutex);
  auto& slot = tables[{ n, g }];
  if (!slot)
  {
    slot.reset(new std::vector<double>(ComputeTable(n, g)));
  }
  return *slot;
}

//------------------------------------------------------------------------------
const vtkPlumeParameterTable& vtkPlumeAirlightPass::GetParameterTable()
{
  static const vtkPlumeParameterTable table = [] {
    using T = vtkPlumeAirlightPass;
    using SetV = void (T::*)(const double*);
    vtkPlumeParameterTable t("vtkPlumeAirlightPass", "medium");
    t.Vector3("scattering", "Scattering", { 0.0, 0.0, 0.0 })
      .Between(0.0, 1e30)
      .Units("1/model units")
      .Panel("Medium")
      .Doc("Scattering coefficient ks per RGB channel: the fraction of light scattered per unit length.")
      .Bind(static_cast<SetV>(&T::SetScattering), &T::GetScattering);
    t.Vector3("absorption", "Absorption", { 0.0, 0.0, 0.0 })
      .Between(0.0, 1e30)
      .Units("1/model units")
      .Panel("Medium")
      .Doc("Absorption coefficient ka per RGB channel; light is extinguished by ks + ka.")
      .Bind(static_cast<SetV>(&T::SetAbsorption), &T::GetAbsorption);
    t.Real("intensity_scale", "IntensityScale", 1.0)
      .Between(0.0, 1e30)
      .Panel("Medium")
      .Doc("Multiplies every positional light's intensity for the airlight only (inverse-square falloff).")
      .Bind(&T::SetIntensityScale, &T::GetIntensityScale);
    t.Real("anisotropy", "ScatteringAnisotropy", 0.0)
      .Between(-0.95, 0.95)
      .Panel("Medium")
      .Doc("Henyey-Greenstein phase asymmetry g: > 0 forward scattering (glow around lights seen through the medium), < 0 backward, 0 isotropic. Exact (one scattering table per g, built once on the CPU).")
      .Bind(&T::SetScatteringAnisotropy, &T::GetScatteringAnisotropy);
    t.Integer("spot_steps", "SpotSteps", 8)
      .Between(1, 256)
      .Panel("Medium")
      .Advanced()
      .Doc("Sub-intervals per spot light cone for its exponent weight, per unit of sqrt(exponent/2) (one when the exponent is 0).")
      .Bind(&T::SetSpotSteps, &T::GetSpotSteps);
    t.Integer("downsampling", "Downsampling", 8)
      .Between(1, 8)
      .Panel("Medium")
      .Advanced()
      .Doc("Airlight lattice: evaluated every D pixels, interpolated in cells whose estimated error is within upsampling_tolerance and which hold no surface edge, light or translucent medium, every pixel of the other cells evaluated; 1: every pixel.")
      .Bind(&T::SetDownsampling, &T::GetDownsampling);
    t.Integer("lattice_levels", "LatticeLevels", 1)
      .Between(1, 2)
      .Panel("Medium")
      .Advanced()
      .Doc("With downsampling: levels of the airlight lattice; level 2 halves the spacing (8 to 4) inside the cells level 1 refined, and only the last level's refined cells are evaluated at every pixel.")
      .Bind(&T::SetLatticeLevels, &T::GetLatticeLevels);
    t.Real("upsampling_tolerance", "UpsamplingTolerance", 0.005)
      .Between(0.0, 1.0)
      .Panel("Medium")
      .Advanced()
      .Doc("With downsampling: the largest estimated interpolation error of a lattice cell, as a fraction of the frame's airlight range (0: every pixel evaluated).")
      .Bind(&T::SetUpsamplingTolerance, &T::GetUpsamplingTolerance);
    t.Integer("table_resolution", "TableResolution", 64)
      .Between(8, 2048)
      .Panel("Medium")
      .Advanced()
      .Doc("Resolution N of the N x N scattering table (computed once in double precision).")
      .Bind(&T::SetTableResolution, &T::GetTableResolution);
    t.Integer("march_steps", "MarchSteps", 0)
      .Between(0, 65536)
      .Panel("Medium")
      .Advanced()
      .Doc("0: the closed form; N > 0: brute-force ray marching with N samples (for comparisons).")
      .Bind(&T::SetMarchSteps, &T::GetMarchSteps);
    t.Boolean("shadows", "Shadows", true)
      .Panel("Medium")
      .Doc("Volumetric shadows of opaque geometry: a shadow map per spot light whose cone holds a prop, a cube map (six faces) per point light with any opaque prop; every light shadowed (one sampler each; more than 8 lights take further passes).")
      .Bind(&T::SetShadows, &T::GetShadows);
    t.Integer("shadow_steps", "ShadowSteps", 64)
      .Between(1, 1024)
      .Panel("Medium")
      .Advanced()
      .Doc("March steps along each view ray for a shadowed light (uniform in the angle seen from the light, jittered).")
      .Bind(&T::SetShadowSteps, &T::GetShadowSteps);
    t.Integer("shadow_map_size", "ShadowMapSize", 1024)
      .Between(16, 8192)
      .Units("texels")
      .Panel("Medium")
      .Advanced()
      .Doc("Width and height of each spot light's shadow map and of each face of a point light's cube map.")
      .Bind(&T::SetShadowMapSize, &T::GetShadowMapSize);
    t.Boolean("shadow_min_max", "ShadowMinMax", true)
      .Panel("Medium")
      .Advanced()
      .Doc("Min-max mipmaps of the shadow maps: runs of 8 march steps that are wholly lit or wholly shadowed are evaluated at once (same result, faster).")
      .Bind(&T::SetShadowMinMax, &T::GetShadowMinMax);
    return t;
  }();
  return table;
}

//------------------------------------------------------------------------------
vtkPlumeAirlightPass::vtkPlumeAirlightPass()
{
  for (int c = 0; c < 3; ++c)
  {
    this->Scattering[c] = this->Absorption[c] = 0.0;
  }
  GetParameterTable().ApplyDefaults(this);
}

//------------------------------------------------------------------------------
vtkPlumeAirlightPass::~vtkPlumeAirlightPass()
{
  // GL objects are released by the renderer (ReleaseGraphicsResources); the
  // helpers hold no context of their own.
  for (ShadowMap* m : this->ShadowMaps)
  {
    m->Release();
    delete m;
  }
}

//------------------------------------------------------------------------------
void vtkPlumeAirlightPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scattering: " << this->Scattering[0] << " " << this->Scattering[1] << " "
     << this->Scattering[2] << "\n";
  os << indent << "Absorption: " << this->Absorption[0] << " " << this->Absorption[1] << " "
     << this->Absorption[2] << "\n";
  os << indent << "IntensityScale: " << this->IntensityScale << "\n";
  os << indent << "ScatteringAnisotropy: " << this->ScatteringAnisotropy << "\n";
  os << indent << "SpotSteps: " << this->SpotSteps << "\n";
  os << indent << "Downsampling: " << this->Downsampling << "\n";
  os << indent << "LatticeLevels: " << this->LatticeLevels << "\n";
  os << indent << "UpsamplingTolerance: " << this->UpsamplingTolerance << "\n";
  os << indent << "TableResolution: " << this->TableResolution << "\n";
  os << indent << "MarchSteps: " << this->MarchSteps << "\n";
  os << indent << "Shadows: " << this->Shadows << "\n";
  os << indent << "ShadowSteps: " << this->ShadowSteps << "\n";
  os << indent << "ShadowMapSize: " << this->ShadowMapSize << "\n";
  os << indent << "ShadowMinMax: " << this->ShadowMinMax << "\n";
}

//------------------------------------------------------------------------------
namespace
{
bool SetCoefficients(double target[3], double r, double g, double b)
{
  const double in[3] = { r, g, b };
  bool changed = false;
  for (int c = 0; c < 3; ++c)
  {
    const double v = std::isnan(in[c]) ? 0.0 : std::min(std::max(in[c], 0.0), 1e30);
    changed = changed || v != target[c];
    target[c] = v;
  }
  return changed;
}
}

void vtkPlumeAirlightPass::SetScattering(double r, double g, double b)
{
  if (SetCoefficients(this->Scattering, r, g, b))
  {
    this->Modified();
  }
}

void vtkPlumeAirlightPass::SetAbsorption(double r, double g, double b)
{
  if (SetCoefficients(this->Absorption, r, g, b))
  {
    this->Modified();
  }
}

void vtkPlumeAirlightPass::SetScatteringAnisotropy(double g)
{
  const double v = std::isnan(g) ? 0.0 : std::min(std::max(g, -0.95), 0.95);
  if (v != this->ScatteringAnisotropy)
  {
    this->ScatteringAnisotropy = v;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkPlumeAirlightPass::HasMedium() const
{
  for (int c = 0; c < 3; ++c)
  {
    if (this->Scattering[c] > 0.0 || this->Absorption[c] > 0.0)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkPlumeAirlightPass::UpdateResources(vtkOpenGLRenderWindow* renWin, int w, int h)
{
  if (!this->ColorTexture)
  {
    this->ColorTexture = vtkTextureObject::New();
    this->ColorTexture->SetContext(renWin);
    this->ColorTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->ColorTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->ColorTexture->Allocate2D(w, h, 4, VTK_FLOAT);
  }
  this->ColorTexture->Resize(w, h);
  if (!this->DepthTexture)
  {
    this->DepthTexture = vtkTextureObject::New();
    this->DepthTexture->SetContext(renWin);
    this->DepthTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->DepthTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->DepthTexture->AllocateDepth(w, h, vtkTextureObject::Float32);
  }
  this->DepthTexture->Resize(w, h);
  if (!this->FrameBuffer)
  {
    this->FrameBuffer = vtkOpenGLFramebufferObject::New();
    this->FrameBuffer->SetContext(renWin);
  }
  if (this->Downsampling > 1 && w >= 2 && h >= 2)
  {
    // each lattice level: (cells + 1)^2 nodes' airlight (bilinear filtering:
    // the interpolated cells' one fetch), one refinement flag per cell
    int spacing[MaximumLatticeLevels], count[MaximumLatticeLevels][2];
    const int levels = LatticeGeometry(this->Downsampling, this->LatticeLevels, w, h, spacing, count);
    for (int l = 0; l < levels; ++l)
    {
      for (vtkTextureObject** t : { &this->LatticeNodes[l], &this->LatticeCells[l] })
      {
        const bool nodes = t == &this->LatticeNodes[l];
        const int tw = nodes ? LatticeNodesSize(count, l, 0) : count[l][0];
        const int th = nodes ? LatticeNodesSize(count, l, 1) : count[l][1];
        if (!*t)
        {
          *t = vtkTextureObject::New();
          (*t)->SetContext(renWin);
          (*t)->SetMinificationFilter(nodes ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
          (*t)->SetMagnificationFilter(nodes ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
          (*t)->SetWrapS(vtkTextureObject::ClampToEdge);
          (*t)->SetWrapT(vtkTextureObject::ClampToEdge);
          (*t)->Allocate2D(tw, th, nodes ? 4 : 1, VTK_FLOAT);
        }
        (*t)->Resize(tw, th);
      }
    }
    // level 0's nodes (and cells, one fewer a side) folded: see the header
    const int fold[2] = { 2 * LatticeNodesSize(count, 0, 0), (LatticeNodesSize(count, 0, 1) + 1) / 2 };
    if (!this->LatticeFolded)
    {
      this->LatticeFolded = vtkTextureObject::New();
      this->LatticeFolded->SetContext(renWin);
      this->LatticeFolded->SetMinificationFilter(vtkTextureObject::Nearest);
      this->LatticeFolded->SetMagnificationFilter(vtkTextureObject::Nearest);
      this->LatticeFolded->Allocate2D(fold[0], fold[1], 4, VTK_FLOAT);
    }
    this->LatticeFolded->Resize(fold[0], fold[1]);
    for (vtkTextureObject** t : { &this->LatticeNodeMap, &this->LatticeNodeList })
    {
      if (levels > 1 && !*t)
      {
        *t = vtkTextureObject::New();
        (*t)->SetContext(renWin);
        (*t)->SetMinificationFilter(vtkTextureObject::Nearest);
        (*t)->SetMagnificationFilter(vtkTextureObject::Nearest);
        (*t)->SetWrapS(vtkTextureObject::ClampToEdge);
        (*t)->SetWrapT(vtkTextureObject::ClampToEdge);
      }
    }
    if (!this->LowFrameBuffer)
    {
      this->LowFrameBuffer = vtkOpenGLFramebufferObject::New();
      this->LowFrameBuffer->SetContext(renWin);
    }
  }
  if (!this->TableTexture || this->UploadedTableResolution != this->TableResolution ||
    this->UploadedTableAnisotropy != this->ScatteringAnisotropy)
  {
    const int n = this->TableResolution;
    const std::vector<double>& table = GetScatteringTable(n, this->ScatteringAnisotropy);
    std::vector<float> data(table.begin(), table.end());
    if (!this->TableTexture)
    {
      this->TableTexture = vtkTextureObject::New();
      this->TableTexture->SetContext(renWin);
    }
    this->TableTexture->SetMinificationFilter(vtkTextureObject::Linear);
    this->TableTexture->SetMagnificationFilter(vtkTextureObject::Linear);
    this->TableTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    this->TableTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    if (!this->TableTexture->Create2DFromRaw(n, n, 2, VTK_FLOAT, data.data()))
    {
      vtkErrorMacro("Could not upload the " << n << "x" << n << " scattering table.");
      return false;
    }
    this->UploadedTableResolution = n;
    this->UploadedTableAnisotropy = this->ScatteringAnisotropy;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkPlumeAirlightPass::BuildMinMax(ShadowMap* m, vtkOpenGLRenderWindow* renWin, int w, int h)
{
  // The depth map read back once per bake (maps are rebuilt only on change)
  // and reduced on the CPU: level L's texel j covers texels 2j, 2j + 1 of
  // level L - 1, and the last one of an odd row also the leftover, so a texel
  // always covers at least its 2^L x 2^L block of the map (the shader's
  // footprint test is conservative).
  // One RG32F texture of one level: the map at (0, 0), level L > 0 right of
  // it at (w, h - (h >> (L - 1))) (the levels' heights h/2, h/4, ... stack
  // into h when h is a power of two; otherwise no pyramid, Top 0). (A real mip
  // chain read with texelFetch(..., level) returned stale levels on llvmpipe
  // after the pass's textures had been released and made again.)
  // Each level is reduced straight from the previous one inside the atlas,
  // and the buffers are not value-initialized: a point light's atlas at the
  // default size is 75 MB, so zero-filling and copying it dominated a bake.
  int top = 0;
  if ((h & (h - 1)) == 0)
  {
    while ((h >> top) > 1)
    {
      ++top;
    }
  }
  const int atlasW = top > 0 ? w + std::max(w >> 1, 1) : w;
  const size_t count = static_cast<size_t>(w) * h;
  std::unique_ptr<float[]> depth(new float[count]);
  // Raw binds on the current unit, restored after: no texture unit of VTK's
  // manager is taken, so none is left pointing at these textures.
  GLint previous = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
  glBindTexture(GL_TEXTURE_2D, m->Depth->GetHandle());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth.get());
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
  std::unique_ptr<float[]> atlas(new float[2 * static_cast<size_t>(atlasW) * h]);
  float* const a = atlas.get();
  vtkSMPTools::For(0, h, [&](vtkIdType y0, vtkIdType y1) {
    for (vtkIdType y = y0; y < y1; ++y)
    {
      float* row = a + 2 * static_cast<size_t>(y) * atlasW;
      const float* d = depth.get() + static_cast<size_t>(y) * w;
      for (int x = 0; x < w; ++x)
      {
        row[2 * x] = row[2 * x + 1] = d[x];
      }
      std::fill(row + 2 * static_cast<size_t>(w), row + 2 * static_cast<size_t>(atlasW), 1.0f);
    }
  });
  depth.reset();
  // level l's first texel in the atlas (its rows atlasW texels apart)
  auto origin = [&](int l) {
    const int x0 = l == 0 ? 0 : w;
    const int y0 = l == 0 ? 0 : h - (h >> (l - 1));
    return a + 2 * (static_cast<size_t>(y0) * atlasW + x0);
  };
  int pw = w, ph = h;
  for (int l = 1; l <= top; ++l)
  {
    const int lw = std::max(pw / 2, 1), lh = std::max(ph / 2, 1);
    const float* prev = origin(l - 1);
    float* next = origin(l);
    vtkSMPTools::For(0, lh, [&](vtkIdType y0, vtkIdType y1) {
      for (vtkIdType y = y0; y < y1; ++y)
      {
        const int sy0 = std::min(static_cast<int>(2 * y), ph - 1);
        const int sy1 = (y == lh - 1) ? ph - 1 : std::min(static_cast<int>(2 * y + 1), ph - 1);
        for (int x = 0; x < lw; ++x)
        {
          const int sx0 = std::min(2 * x, pw - 1);
          const int sx1 = (x == lw - 1) ? pw - 1 : std::min(2 * x + 1, pw - 1);
          float lo = std::numeric_limits<float>::max(), hi = -lo;
          for (int sy = sy0; sy <= sy1; ++sy)
          {
            for (int sx = sx0; sx <= sx1; ++sx)
            {
              const size_t i = 2 * (static_cast<size_t>(sy) * atlasW + sx);
              lo = std::min(lo, prev[i]);
              hi = std::max(hi, prev[i + 1]);
            }
          }
          const size_t o = 2 * (static_cast<size_t>(y) * atlasW + x);
          next[o] = lo;
          next[o + 1] = hi;
        }
      }
    });
    pw = lw;
    ph = lh;
  }
  if (!m->MinMax)
  {
    m->MinMax = vtkTextureObject::New();
    m->MinMax->SetContext(renWin);
    m->MinMax->SetWrapS(vtkTextureObject::ClampToEdge);
    m->MinMax->SetWrapT(vtkTextureObject::ClampToEdge);
    m->MinMax->SetMinificationFilter(vtkTextureObject::Nearest);
    m->MinMax->SetMagnificationFilter(vtkTextureObject::Nearest);
  }
  if (m->MinMax->GetHandle() != 0 && static_cast<int>(m->MinMax->GetWidth()) == atlasW &&
    static_cast<int>(m->MinMax->GetHeight()) == h && m->MinMax->GetComponents() == 2)
  {
    // same size as the last bake: update in place (a new texture of this
    // size would be allocated and cleared by the driver each bake)
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
    glBindTexture(GL_TEXTURE_2D, m->MinMax->GetHandle());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, atlasW, h, GL_RG, GL_FLOAT, a);
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
  }
  else
  {
    m->MinMax->Create2DFromRaw(atlasW, h, 2, VTK_FLOAT, a);
  }
  m->Top = top;
}

//------------------------------------------------------------------------------
bool vtkPlumeAirlightPass::BakeShadowMap(const vtkRenderState* s, int index,
  const std::vector<double>& key, const double position[3], const double focal[3],
  double coneAngle, const double bounds[6], bool point)
{
  while (static_cast<int>(this->ShadowMaps.size()) <= index)
  {
    this->ShadowMaps.push_back(new ShadowMap);
  }
  ShadowMap* m = this->ShadowMaps[index];
  if (m->Depth && m->Key == key)
  {
    return true; // light, props and size unchanged
  }
  vtkRenderer* r = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(r->GetRenderWindow());
  const int size = this->ShadowMapSize;
  const int faces = point ? 6 : 1;
  const int mapW = point ? 3 * size : size;
  const int mapH = point ? 2 * size : size;
  if (!m->Depth)
  {
    m->Depth = vtkTextureObject::New();
    m->Depth->SetContext(renWin);
    m->Depth->SetMinificationFilter(vtkTextureObject::Nearest);
    m->Depth->SetMagnificationFilter(vtkTextureObject::Nearest);
    m->Depth->SetWrapS(vtkTextureObject::ClampToEdge);
    m->Depth->SetWrapT(vtkTextureObject::ClampToEdge);
    m->Depth->AllocateDepth(mapW, mapH, vtkTextureObject::Float32);
    m->Color = vtkTextureObject::New();
    m->Color->SetContext(renWin);
    m->Color->Allocate2D(mapW, mapH, 4, VTK_UNSIGNED_CHAR);
    m->FrameBuffer = vtkOpenGLFramebufferObject::New();
    m->FrameBuffer->SetContext(renWin);
  }
  m->Depth->Resize(mapW, mapH);
  m->Color->Resize(mapW, mapH);
  m->Faces = faces;

  // The light's camera: its frustum holds the cone, or for a point light
  // each face's 90 degree square (VTK's projection uses the renderer's aspect
  // ratio; the vertical angle is widened when it is < 1).
  vtkCamera* cam = m->Camera;
  const glm::dvec3 p(position[0], position[1], position[2]);
  const double aspect = r->GetTiledAspectRatio();
  double farthest = 0;
  for (int c = 0; c < 8; ++c)
  {
    const glm::dvec3 corner(bounds[c & 1], bounds[2 + ((c >> 1) & 1)], bounds[4 + ((c >> 2) & 1)]);
    farthest = std::max(farthest, glm::length(corner - p));
  }
  m->Far = std::max(farthest * 1.01, 1e-6);
  m->Near = m->Far * 1e-3;
  cam->SetPosition(position);
  cam->SetClippingRange(m->Near, m->Far);
  auto aim = [&](const glm::dvec3& axis, double halfAngle) {
    const glm::dvec3 up = std::fabs(axis.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    cam->SetFocalPoint(p.x + axis.x, p.y + axis.y, p.z + axis.z);
    cam->SetViewUp(up.x, up.y, up.z);
    const double tanHalf = std::tan(halfAngle) / std::min(aspect, 1.0);
    cam->SetViewAngle(std::min(vtkMath::DegreesFromRadians(2.0 * std::atan(tanHalf)), 179.0));
    cam->SetClippingRange(m->Near, m->Far);
  };
  static const double faceAxes[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 },
    { 0, 0, 1 }, { 0, 0, -1 } };

  // Depth of the opaque props from the light, with the renderer's camera
  // swapped for the light's (as vtkShadowMapBakerPass does).
  vtkOpenGLState* ostate = renWin->GetState();
  ostate->PushFramebufferBindings();
  m->FrameBuffer->Bind();
  m->FrameBuffer->AddColorAttachment(0, m->Color);
  m->FrameBuffer->ActivateDrawBuffers(1);
  m->FrameBuffer->AddDepthAttachment(m->Depth);
  m->FrameBuffer->StartNonOrtho(mapW, mapH);
  vtkCamera* saved = r->GetActiveCamera();
  saved->Register(this);
  r->SetActiveCamera(cam);
  // No vtkCameraPass: vtkOpenGLCamera::Render would set the renderer's own
  // viewport; the mappers take the light camera's matrices (with the
  // renderer's aspect ratio, as ShadowMatrix does) and draw into the whole map.
  vtkNew<vtkOpaquePass> opaque;
  // Every visible prop, not the state's array: that one is culled to the
  // eye's frustum, and an occluder outside the view still casts its shadow.
  std::vector<vtkProp*> props;
  vtkPropCollection* all = r->GetViewProps();
  vtkCollectionSimpleIterator pit;
  all->InitTraversal(pit);
  while (vtkProp* prop = all->GetNextProp(pit))
  {
    if (prop->GetVisibility())
    {
      props.push_back(prop);
    }
  }
  vtkRenderState inner(r);
  inner.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
  inner.SetFrameBuffer(m->FrameBuffer);
  ostate->vtkglViewport(0, 0, mapW, mapH);
  ostate->vtkglScissor(0, 0, mapW, mapH);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
  for (int f = 0; f < faces; ++f)
  {
    if (point)
    {
      // A margin of 2 % keeps the faces' frusta overlapping at their seams.
      aim(glm::dvec3(faceAxes[f][0], faceAxes[f][1], faceAxes[f][2]), std::atan(1.02));
    }
    else
    {
      glm::dvec3 axis = glm::dvec3(focal[0], focal[1], focal[2]) - p;
      axis = glm::length(axis) > 0 ? glm::normalize(axis) : glm::dvec3(0, 0, -1);
      aim(axis, vtkMath::RadiansFromDegrees(std::min(coneAngle * 1.02 + 0.5, 89.0)));
    }
    vtkMatrix4x4* toClip = cam->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0);
    std::copy(toClip->GetData(), toClip->GetData() + 16, m->WorldToClip[f]);
    const int tx = (f % 3) * size, ty = (f / 3) * size;
    ostate->vtkglViewport(tx, ty, size, size);
    ostate->vtkglScissor(tx, ty, size, size);
    opaque->Render(&inner);
  }
  r->SetActiveCamera(saved);
  saved->UnRegister(this);
  m->FrameBuffer->RemoveColorAttachments(1);
  m->FrameBuffer->RemoveDepthAttachment();
  ostate->PopFramebufferBindings();
  m->Size = size;
  this->BuildMinMax(m, renWin, mapW, mapH);
  m->Key = key;
  ++this->NumberOfShadowMapBakes;
  return true;
}

//------------------------------------------------------------------------------
bool vtkPlumeAirlightPass::UpdateLightTextures(vtkRenderer* r, vtkOpenGLRenderWindow* renWin)
{
  // Camera lights are placed as the delegate's lights pass will place them.
  if (r->GetLightFollowCamera())
  {
    r->UpdateLightsGeometryToFollowCamera();
  }
  vtkMatrix4x4* view = r->GetActiveCamera()->GetViewTransformMatrix();
  auto toEye = [view](const glm::dvec3& p, double w4) {
    double in[4] = { p.x, p.y, p.z, w4 };
    double out[4];
    view->MultiplyPoint(in, out);
    return glm::dvec3(out[0], out[1], out[2]);
  };
  std::vector<std::pair<vtkImageData*, vtkMTimeType>> atlasKey;
  std::vector<int> indices;
  this->LightTextures.clear();
  int atlasWidth = 1, atlasHeight = 0;
  int index = 0; // among the switched-on lights, as VTK's polydata shaders count them
  vtkCollectionSimpleIterator it;
  vtkLightCollection* lights = r->GetLights();
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch())
    {
      continue;
    }
    vtkImageData* image = light->GetPositional() ? ProjectedTexture(light) : nullptr;
    if (image)
    {
      int dims[3];
      image->GetDimensions(dims);
      atlasKey.emplace_back(image, image->GetMTime());
      indices.push_back(index);
      LightTexture t;
      t.Light = light;
      t.Index = index;
      t.Rect[0] = 0.0f;
      t.Rect[1] = static_cast<float>(atlasHeight);
      t.Rect[2] = static_cast<float>(dims[0]);
      t.Rect[3] = static_cast<float>(dims[1]);
      atlasHeight += dims[1];
      atlasWidth = std::max(atlasWidth, dims[0]);
      // The image's axes (see SetLightTexture), scaled by 1/tan(cone) so that
      // the shaders divide by v.a only; to eye coordinates (VTK's view
      // transform is rigid: directions take its rotation only).
      double position[3], focal[3];
      light->GetTransformedPosition(position);
      light->GetTransformedFocalPoint(focal);
      const glm::dvec3 wp(position[0], position[1], position[2]);
      glm::dvec3 wa = glm::dvec3(focal[0], focal[1], focal[2]) - wp;
      wa = glm::length(wa) > 0 ? glm::normalize(wa) : glm::dvec3(0, 0, -1);
      glm::dvec3 hint(0.0, 1.0, 0.0);
      vtkInformation* li = light->GetInformation();
      if (li && li->Has(LIGHT_TEXTURE_UP()) && li->Length(LIGHT_TEXTURE_UP()) == 3)
      {
        const double* u = li->Get(LIGHT_TEXTURE_UP());
        hint = glm::dvec3(u[0], u[1], u[2]);
      }
      if (!(glm::length(glm::cross(wa, hint)) > 1e-9 * glm::length(hint)))
      {
        hint = glm::dvec3(0.0, 0.0, 1.0);
      }
      const glm::dvec3 wr = glm::normalize(glm::cross(wa, hint));
      const glm::dvec3 wu = glm::cross(wr, wa);
      const double scaleTan =
        1.0 / std::max(std::tan(vtkMath::RadiansFromDegrees(light->GetConeAngle())), 1e-9);
      const glm::dvec3 pe = toEye(wp, 1.0);
      glm::dvec3 axis = toEye(glm::dvec3(focal[0], focal[1], focal[2]), 1.0) - pe;
      axis = glm::length(axis) > 0.0 ? axis / glm::length(axis) : glm::dvec3(0.0, 0.0, -1.0);
      const glm::dvec3 frame[4] = { pe, axis, toEye(wr * scaleTan, 0.0), toEye(wu * scaleTan, 0.0) };
      for (int k = 0; k < 4; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          t.Frame[k][c] = static_cast<float>(frame[k][c]);
        }
      }
      this->LightTextures.push_back(t);
    }
    ++index;
  }
  if (indices != this->LightTextureIndices)
  {
    this->LightTextureIndices = indices;
    this->LightTextureShaderTime.Modified(); // the surface shaders' code changes
  }
  if (atlasKey.empty())
  {
    return false;
  }
  if (!this->TextureAtlas || atlasKey != this->TextureAtlasKey)
  {
    std::vector<float> texels;
    for (const auto& k : atlasKey)
    {
      AppendTexels(k.first, texels, atlasWidth);
    }
    if (!this->TextureAtlas)
    {
      this->TextureAtlas = vtkTextureObject::New();
      this->TextureAtlas->SetContext(renWin);
    }
    // read with texelFetch (bilinear in the shader, within each image)
    this->TextureAtlas->SetMinificationFilter(vtkTextureObject::Nearest);
    this->TextureAtlas->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->TextureAtlas->Create2DFromRaw(atlasWidth, atlasHeight, 4, VTK_FLOAT, texels.data());
    this->TextureAtlasKey = atlasKey;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkPlumeAirlightPass::RenderDelegate(const vtkRenderState* s, bool textured)
{
  if (textured)
  {
    // The props' shaders multiply the textured spots' light by their images
    // (PreReplaceShaderValues ... SetShaderParameters below).
    this->TextureAtlas->Activate();
    this->PreRender(s);
  }
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  if (textured)
  {
    this->PostRender(s);
    this->TextureAtlas->Deactivate();
  }
}

//------------------------------------------------------------------------------
namespace
{
// The diffuse and specular lines of light N in VTK 9.1's polydata shaders (the
// ones vtkShadowMapPass rewrites too), and the PBR one.
std::string DiffuseLine(int i)
{
  return "diffuse += (df * lightColor" + std::to_string(i) + ");";
}
std::string SpecularLine(int i)
{
  return "specular += (sf * lightColor" + std::to_string(i) + ");";
}
std::string RadianceLine(int i)
{
  return "radiance = lightColor" + std::to_string(i) + " * attenuation;";
}
}

bool vtkPlumeAirlightPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*)
{
  if (this->LightTextures.empty() || !vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    return true;
  }
  std::string dec = "//VTK::Light::Dec\n"
                    "uniform sampler2D plumeLightTextures;\n";
  for (const LightTexture& t : this->LightTextures)
  {
    const std::string n = std::to_string(t.Index);
    dec += "uniform vec4 plumeLightTextureRect" + n + ";\n" + "uniform vec3 plumeLightTextureFrame" + n +
      "[4];\n";
  }
  dec += vtkPlumeLightTexture;
  dec += "// light `frame` (position, axis, right, up)'s image at the eye-space point p\n"
         "vec3 plumeSurfaceLightTexture(vec3 p, vec3 frame[4], vec4 rect)\n"
         "{\n"
         "  return plumeLightTexel(plumeLightTextures, rect,\n"
         "    plumeLightTextureCoordinates(p - frame[0], frame[1], frame[2], frame[3]));\n"
         "}\n";
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Dec", dec, false);
  return true;
}

bool vtkPlumeAirlightPass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*)
{
  if (this->LightTextures.empty() || !vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    return true;
  }
  // The light code is expanded by now: multiply each textured light's lines.
  for (const LightTexture& t : this->LightTextures)
  {
    const std::string n = std::to_string(t.Index);
    const std::string texel =
      "plumeSurfaceLightTexture(vertexVC.xyz, plumeLightTextureFrame" + n + ", plumeLightTextureRect" + n + ")";
    vtkShaderProgram::Substitute(fragmentShader, DiffuseLine(t.Index),
      "diffuse += (df * " + texel + " * lightColor" + n + ");", false);
    vtkShaderProgram::Substitute(fragmentShader, SpecularLine(t.Index),
      "specular += (sf * " + texel + " * lightColor" + n + ");", false);
    vtkShaderProgram::Substitute(fragmentShader, RadianceLine(t.Index),
      "radiance = " + texel + " * lightColor" + n + " * attenuation;", false);
  }
  return true;
}

bool vtkPlumeAirlightPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  if (this->LightTextures.empty() || !program->IsUniformUsed("plumeLightTextures"))
  {
    return true;
  }
  program->SetUniformi("plumeLightTextures", this->TextureAtlas->GetTextureUnit());
  for (const LightTexture& t : this->LightTextures)
  {
    const std::string n = std::to_string(t.Index);
    program->SetUniform4f(("plumeLightTextureRect" + n).c_str(), t.Rect);
    program->SetUniform3fv(("plumeLightTextureFrame" + n).c_str(), 4, t.Frame);
  }
  return true;
}

vtkMTimeType vtkPlumeAirlightPass::GetShaderStageMTime()
{
  return this->LightTextureShaderTime.GetMTime();
}

//------------------------------------------------------------------------------
void vtkPlumeAirlightPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro("no delegate in vtkPlumeAirlightPass.");
    return;
  }
  vtkRenderer* r = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(r->GetRenderWindow());
  // Textured spot lights project their images onto the surfaces, medium or not.
  const bool anyTexture = this->UpdateLightTextures(r, renWin);
  // Nothing to scatter or absorb: the scene as it is, no framebuffer, no pass.
  if (!this->HasMedium())
  {
    this->NumberOfTexturedLights = static_cast<int>(this->LightTextures.size());
    this->RenderDelegate(s, anyTexture);
    return;
  }

  vtkOpenGLState* ostate = renWin->GetState();
  int x, y, w, h;
  r->GetTiledSizeAndOrigin(&w, &h, &x, &y);
  if (!this->UpdateResources(renWin, w, h))
  {
    this->RenderDelegate(s, anyTexture);
    return;
  }

  // Translucent media (volumes, smoke sheets): a compositing pass in the
  // delegate draws them into a layer of their own (MEDIA_LAYER), so that the
  // haze in front of them is added and the haze behind them dimmed by them.
  std::vector<float> mediaBoxes; // world bounds, min then max, at most MaximumMediaBoxes
  std::vector<int> mediaCentred; // per box: 1 for a medium at the middle of its bounds (not a volume)
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    const double* b = vtkPlumeCompositingPass::IsMedium(prop) ? prop->GetBounds() : nullptr;
    if (!b || !(b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5]) || !std::isfinite(b[0] + b[1] + b[2] + b[3] + b[4] + b[5]))
    {
      continue;
    }
    const float box[6] = { float(b[0]), float(b[2]), float(b[4]), float(b[1]), float(b[3]), float(b[5]) };
    // Volumes: extinction taken as uniform along the chord; other media
    // (smoke sheets: a surface widened by its blur) sit at its middle.
    const int centred = vtkVolume::SafeDownCast(prop) ? 0 : 1;
    if (mediaBoxes.size() < 6 * MaximumMediaBoxes)
    {
      mediaBoxes.insert(mediaBoxes.end(), box, box + 6);
      mediaCentred.push_back(centred);
    }
    else
    {
      // more media than the shader's slots: the last slot holds the union of the rest
      float* last = &mediaBoxes[mediaBoxes.size() - 6];
      for (int k = 0; k < 3; ++k)
      {
        last[k] = std::min(last[k], box[k]);
        last[3 + k] = std::max(last[3 + k], box[3 + k]);
      }
      mediaCentred.back() = mediaCentred.back() && centred;
    }
  }
  vtkInformation* info = r->GetInformation();
  if (!mediaBoxes.empty())
  {
    if (!this->MediaTexture)
    {
      this->MediaTexture = vtkTextureObject::New();
      this->MediaTexture->SetContext(renWin);
      this->MediaTexture->SetMinificationFilter(vtkTextureObject::Nearest);
      this->MediaTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
      this->MediaTexture->Allocate2D(w, h, 4, VTK_FLOAT);
    }
    this->MediaTexture->Resize(w, h);
    info->Set(vtkPlumeCompositingPass::MEDIA_LAYER(), this->MediaTexture);
    if (!this->MediaTransmittanceTexture)
    {
      this->MediaTransmittanceTexture = vtkTextureObject::New();
      this->MediaTransmittanceTexture->SetContext(renWin);
      this->MediaTransmittanceTexture->SetMinificationFilter(vtkTextureObject::Nearest);
      this->MediaTransmittanceTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
      this->MediaTransmittanceTexture->Allocate2D(w, h, 4, VTK_FLOAT);
    }
    this->MediaTransmittanceTexture->Resize(w, h);
    info->Set(vtkPlumeCompositingPass::MEDIA_TRANSMITTANCE(), this->MediaTransmittanceTexture);
  }

  // 1. The scene into our float colour + depth targets.
  this->Profiler.SetEnabled(this->ProfilePasses);
  this->Profiler.Start();
  ostate->PushFramebufferBindings();
  this->FrameBuffer->Bind();
  this->FrameBuffer->AddColorAttachment(0, this->ColorTexture);
  this->FrameBuffer->ActivateDrawBuffers(1);
  this->FrameBuffer->AddDepthAttachment(this->DepthTexture);
  this->FrameBuffer->StartNonOrtho(w, h);
  // A state naming our framebuffer: the camera pass then draws the viewport
  // at (0, 0) of the w x h target, whatever the renderer's place in the window.
  vtkRenderState inner(r);
  inner.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  inner.SetFrameBuffer(this->FrameBuffer);
  this->RenderDelegate(&inner, anyTexture);
  this->Profiler.Mark("scene");
  this->FrameBuffer->RemoveColorAttachments(1);
  this->FrameBuffer->RemoveDepthAttachment();
  ostate->PopFramebufferBindings();
  this->NumberOfMediaInLayer = info->Has(vtkPlumeCompositingPass::MEDIA_LAYER_DRAWN())
    ? info->Get(vtkPlumeCompositingPass::MEDIA_LAYER_DRAWN())
    : 0;
  auto* mediaDepth =
    vtkPlumeOpaqueDepthTexture::SafeDownCast(info->Get(vtkPlumeCompositingPass::MEDIA_LAYER_DEPTH()));
  vtkTextureObject* mediaDepthTexture = mediaDepth ? mediaDepth->GetTextureObject() : nullptr;
  const bool mediaTransmittance = info->Has(vtkPlumeCompositingPass::MEDIA_TRANSMITTANCE_DRAWN()) &&
    info->Get(vtkPlumeCompositingPass::MEDIA_TRANSMITTANCE_DRAWN()) == 1;
  info->Remove(vtkPlumeCompositingPass::MEDIA_TRANSMITTANCE());
  info->Remove(vtkPlumeCompositingPass::MEDIA_TRANSMITTANCE_DRAWN());
  info->Remove(vtkPlumeCompositingPass::MEDIA_LAYER());
  info->Remove(vtkPlumeCompositingPass::MEDIA_LAYER_DRAWN());
  info->Remove(vtkPlumeCompositingPass::MEDIA_LAYER_DEPTH());
  const bool media = this->NumberOfMediaInLayer > 0;

  // 2. The lights, in eye coordinates (the delegate has updated their geometry),
  // split into groups of at most MaximumLights (one shader pass each).
  vtkCamera* camera = r->GetActiveCamera();
  vtkMatrix4x4* view = camera->GetViewTransformMatrix();
  auto toEye = [view](const double p[3], double w4) {
    double in[4] = { p[0], p[1], p[2], w4 };
    double out[4];
    view->MultiplyPoint(in, out);
    return glm::dvec3(out[0], out[1], out[2]);
  };
  std::vector<float> positions, intensities, axes, cosCones, exponents;
  std::vector<int> shadowIndex;       // per light: its shadow map's index in ShadowMaps, or -1
  std::vector<double> shadowMatrices; // row-major, eye coordinates -> light clip coordinates
  std::vector<float> shadowRanges;    // near, far per shadow map
  std::vector<int> shadowFaces;       // 1 (spot) or 6 (point) per shadow map
  std::vector<float> shadowLights;    // the light's eye position per shadow map
  int unshadowed = 0;                 // lights that needed a map but got none (no texture unit at all)
  // A group: lights [First, First + Count) and shadow maps [FirstShadow, FirstShadow + Shadows).
  struct Group
  {
    int First = 0, Count = 0, FirstShadow = 0, Shadows = 0;
    bool AnySpot = false;
    bool AnyTexture = false;
  };
  std::vector<Group> groups(1);
  // The opaque props that can cast shadows: their bounds and their latest change.
  struct Occluder
  {
    double Bounds[6];
  };
  std::vector<Occluder> occluders;
  double sceneBounds[6] = { HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL };
  vtkMTimeType propsTime = 0;
  if (this->Shadows)
  {
    vtkPropCollection* all = r->GetViewProps(); // not the eye-culled array of the state
    vtkCollectionSimpleIterator pit;
    all->InitTraversal(pit);
    while (vtkProp* prop = all->GetNextProp(pit))
    {
      const double* b = prop->GetVisibility() ? prop->GetBounds() : nullptr;
      if (!b || !(b[0] <= b[1]) || !std::isfinite(b[0]) || !std::isfinite(b[1]) ||
        prop->HasTranslucentPolygonalGeometry())
      {
        continue;
      }
      Occluder o;
      std::copy(b, b + 6, o.Bounds);
      occluders.push_back(o);
      for (int k = 0; k < 3; ++k)
      {
        sceneBounds[2 * k] = std::min(sceneBounds[2 * k], b[2 * k]);
        sceneBounds[2 * k + 1] = std::max(sceneBounds[2 * k + 1], b[2 * k + 1]);
      }
      propsTime = std::max({ propsTime, prop->GetMTime(), prop->GetRedrawMTime() });
    }
  }
  vtkNew<vtkMatrix4x4> inverseView;
  vtkMatrix4x4::Invert(view, inverseView);
  int shadowCount = 0;
  // One sampler per shadowed light of a group beside the pass's own 5
  // (colour, depth, table, the lattice's nodes and cells).
  GLint textureUnits = 16;
  glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &textureUnits);
  vtkLightCollection* lights = r->GetLights();
  vtkCollectionSimpleIterator it;
  // Textured spot lights: their images are in one atlas (one more sampler).
  const int shadowLimit = std::max(
    0, std::min<int>(MaximumShadowedLights, textureUnits - (media ? 8 : 5) - (anyTexture ? 1 : 0)));
  std::vector<float> textureRects, textureRights, textureUps; // per light (rect width 0: untextured)
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch() || !light->GetPositional())
    {
      continue;
    }
    if (groups.back().Count >= MaximumLights)
    {
      Group next;
      next.First = static_cast<int>(cosCones.size());
      next.FirstShadow = shadowCount;
      groups.push_back(next);
    }
    double position[3], focal[3], color[3], attenuation[3];
    light->GetTransformedPosition(position);
    light->GetTransformedFocalPoint(focal);
    light->GetDiffuseColor(color);
    light->GetAttenuationValues(attenuation);
    double scale = light->GetIntensity() * this->IntensityScale;
    if (attenuation[0] == 0.0 && attenuation[1] == 0.0 && attenuation[2] > 0.0)
    {
      scale /= attenuation[2];
    }
    const glm::dvec3 pe = toEye(position, 1.0);
    const glm::dvec3 fe = toEye(focal, 1.0);
    glm::dvec3 axis = fe - pe;
    const double axisLength = glm::length(axis);
    axis = axisLength > 0.0 ? axis / axisLength : glm::dvec3(0.0, 0.0, -1.0);
    const bool spot = light->GetConeAngle() < 90.0;
    for (int c = 0; c < 3; ++c)
    {
      positions.push_back(static_cast<float>(pe[c]));
      intensities.push_back(static_cast<float>(scale * color[c]));
      axes.push_back(static_cast<float>(axis[c]));
    }
    cosCones.push_back(
      spot ? static_cast<float>(std::cos(vtkMath::RadiansFromDegrees(light->GetConeAngle()))) : -2.0f);
    // its image, as UpdateLightTextures collected it (rect width 0: none)
    const auto image = std::find_if(this->LightTextures.begin(), this->LightTextures.end(),
      [light](const LightTexture& t) { return t.Light == light; });
    const bool textured = image != this->LightTextures.end();
    const float none[4] = { 0, 0, 0, 0 };
    const float* rect = textured ? image->Rect : none;
    const float* right = textured ? image->Frame[2] : none;
    const float* up = textured ? image->Frame[3] : none;
    textureRects.insert(textureRects.end(), rect, rect + 4);
    textureRights.insert(textureRights.end(), right, right + 3);
    textureUps.insert(textureUps.end(), up, up + 3);
    // A shadow map for a spot light whose cone holds some opaque prop's
    // bounding sphere, or for a point light with any opaque prop (a cube map).
    int shadow = -1;
    if (this->Shadows)
    {
      const glm::dvec3 lp(position[0], position[1], position[2]);
      glm::dvec3 la = glm::dvec3(focal[0], focal[1], focal[2]) - lp;
      la = glm::length(la) > 0 ? glm::normalize(la) : glm::dvec3(0, 0, -1);
      const double cone = vtkMath::RadiansFromDegrees(light->GetConeAngle());
      bool occluded = false;
      for (const Occluder& o : occluders)
      {
        const glm::dvec3 c(0.5 * (o.Bounds[0] + o.Bounds[1]), 0.5 * (o.Bounds[2] + o.Bounds[3]),
          0.5 * (o.Bounds[4] + o.Bounds[5]));
        const double radius = 0.5 *
          glm::length(glm::dvec3(o.Bounds[1] - o.Bounds[0], o.Bounds[3] - o.Bounds[2], o.Bounds[5] - o.Bounds[4]));
        const glm::dvec3 v = c - lp;
        const double dist = glm::length(v);
        if (!spot || dist <= radius ||
          std::acos(std::min(1.0, std::max(-1.0, glm::dot(v, la) / dist))) - std::asin(radius / dist) <= cone)
        {
          occluded = true;
          break;
        }
      }
      const std::vector<double> key = { position[0], position[1], position[2], focal[0], focal[1],
        focal[2], spot ? light->GetConeAngle() : 180.0, static_cast<double>(this->ShadowMapSize),
        static_cast<double>(propsTime), static_cast<double>(occluders.size()), r->GetTiledAspectRatio() };
      if (occluded && shadowLimit > 0 && groups.back().Shadows >= shadowLimit)
      {
        // The group's samplers are used up (only on a driver with fewer than
        // 12 units): this light opens the next group.
        Group next;
        next.First = static_cast<int>(cosCones.size()) - 1;
        next.FirstShadow = shadowCount;
        groups.push_back(next);
      }
      if (occluded && shadowLimit == 0)
      {
        ++unshadowed; // reported below
      }
      else if (occluded &&
        this->BakeShadowMap(s, shadowCount, key, position, focal, light->GetConeAngle(), sceneBounds, !spot))
      {
        ShadowMap* m = this->ShadowMaps[shadowCount];
        for (int f = 0; f < 6; ++f)
        {
          vtkNew<vtkMatrix4x4> worldToClip, toLight;
          worldToClip->DeepCopy(m->WorldToClip[std::min(f, m->Faces - 1)]);
          vtkMatrix4x4::Multiply4x4(worldToClip, inverseView, toLight);
          shadowMatrices.insert(shadowMatrices.end(), toLight->GetData(), toLight->GetData() + 16);
        }
        shadowRanges.push_back(static_cast<float>(m->Near));
        shadowRanges.push_back(static_cast<float>(m->Far));
        shadowFaces.push_back(m->Faces);
        shadowLights.insert(shadowLights.end(), { static_cast<float>(pe.x), static_cast<float>(pe.y),
          static_cast<float>(pe.z) });
        shadow = shadowCount++;
        ++groups.back().Shadows;
      }
    }
    Group& group = groups.back();
    ++group.Count;
    group.AnySpot = group.AnySpot || spot;
    group.AnyTexture = group.AnyTexture || textured;
    shadowIndex.push_back(shadow);
    exponents.push_back(static_cast<float>(light->GetExponent()));
  }
  this->NumberOfShadowedLights = shadowCount;
  this->NumberOfTexturedLights = static_cast<int>(this->LightTextures.size());
  this->NumberOfUnshadowedLights = unshadowed;
  this->NumberOfLightGroups = static_cast<int>(groups.size());
  if (unshadowed > 0 && unshadowed != this->ReportedUnshadowed)
  {
    vtkWarningMacro("vtkPlumeAirlightPass: " << unshadowed
      << " lights need a shadow map but the driver has " << textureUnits
      << " fragment texture units, all used by the pass's 5 others; they are rendered unshadowed.");
  }
  this->ReportedUnshadowed = unshadowed;

  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  ostate->vtkglDepthMask(GL_TRUE);
  this->ColorTexture->Activate();
  this->DepthTexture->Activate();
  this->TableTexture->Activate();
  if (anyTexture)
  {
    this->TextureAtlas->Activate();
  }
  if (media)
  {
    this->MediaTexture->Activate();
    if (mediaTransmittance)
    {
      this->MediaTransmittanceTexture->Activate();
    }
    if (mediaDepthTexture)
    {
      mediaDepthTexture->Activate();
    }
  }
  // stays 0 unless a group uses the lattice
  this->LastRefinedCellFraction = 0.0;
  this->LastRefinedPixelFraction = 0.0;
  this->LatticeFlagsPending = false;
  for (size_t gi = 0; gi < groups.size(); ++gi)
  {
    const Group& group = groups[gi];
    // 3. The program for this group's variant (lights count, spot lights, shadows).
    vtkPlumeShaderFeatures features;
    features.Define("NUMBER_OF_LIGHTS", std::max(group.Count, 1));
    // A medium and no positional light (haze for depth cues): the frame is
    // the attenuated surface alone. Without this variant the light code,
    // inlined twice, cost about half the pass on llvmpipe even at 0 trips.
    features.Enable("NO_LIGHTS", group.Count == 0);
    // the shadowed march uses the spot path's running integral
    features.Enable("SPOT", group.AnySpot || group.Shadows > 0);
    features.Enable("TEXTURE", group.AnyTexture); // only spot lights project one
    if (group.Shadows > 0)
    {
      features.Enable("SHADOW").Define("NUMBER_OF_SHADOWS", group.Shadows);
    }
    features.Enable("MEDIA", media);
    if (this->MarchSteps > 0)
    {
      features.Enable("MARCH").Define("MARCH_STEPS", this->MarchSteps);
    }
    const double kt0 = this->Scattering[0] + this->Absorption[0];
    // one table look-up for the three channels
    features.Enable("GREY",
      kt0 == this->Scattering[1] + this->Absorption[1] && kt0 == this->Scattering[2] + this->Absorption[2]);
    // The airlight lattice (Downsampling > 1): for a group with lights, two
    // cells in each direction at least; the run statistics are per pixel.
    // Not for shadowed or textured lights: a shadow or a slat's shaft
    // narrower than a cell can fall between the nodes, and nothing in the
    // classification would see it.
    const int cells[2] = { w >= 2 ? (w - 2) / this->Downsampling + 1 : 0,
      h >= 2 ? (h - 2) / this->Downsampling + 1 : 0 };
    const bool lattice = this->Downsampling > 1 && group.Count > 0 && group.Shadows == 0 &&
      !group.AnyTexture && this->MarchSteps == 0 && !this->ShadowRunStatistics && cells[0] >= 2 &&
      cells[1] >= 2;
    // 4. Uniforms (the same for every program of the group) and the passes.
    auto setUniforms = [&](vtkShaderProgram* program) {
      program->SetUniformi("SceneColor", this->ColorTexture->GetTextureUnit());
      program->SetUniformi("SceneDepth", this->DepthTexture->GetTextureUnit());
      program->SetUniformi("Table", this->TableTexture->GetTextureUnit());
      program->SetUniformi("TableSize", this->UploadedTableResolution);
      if (media)
      {
        program->SetUniformi("MediaLayer", this->MediaTexture->GetTextureUnit());
        // (without the depth before the media, the sampler still needs a valid unit)
        program->SetUniformi("MediaDepth",
          (mediaDepthTexture ? mediaDepthTexture : this->MediaTexture)->GetTextureUnit());
        program->SetUniformi("HasMediaDepth", mediaDepthTexture ? 1 : 0);
        program->SetUniformi("MediaTransmittance",
          (mediaTransmittance ? this->MediaTransmittanceTexture : this->MediaTexture)->GetTextureUnit());
        program->SetUniformi("HasMediaTransmittance", mediaTransmittance ? 1 : 0);
        const int boxes = static_cast<int>(mediaBoxes.size() / 6);
        std::vector<float> lo, hi;
        for (int k = 0; k < boxes; ++k)
        {
          lo.insert(lo.end(), &mediaBoxes[6 * k], &mediaBoxes[6 * k + 3]);
          hi.insert(hi.end(), &mediaBoxes[6 * k + 3], &mediaBoxes[6 * k + 6]);
        }
        program->SetUniformi("NumberOfMediaBoxes", boxes);
        program->SetUniform1iv("MediaBoxCentred", boxes, mediaCentred.data());
        program->SetUniform3fv("MediaBoxMin", boxes, reinterpret_cast<const float(*)[3]>(lo.data()));
        program->SetUniform3fv("MediaBoxMax", boxes, reinterpret_cast<const float(*)[3]>(hi.data()));
        plume::SetUniformMatrix4x4(program, "EyeToWorldPoint", inverseView->GetData());
      }
      {
        const double g = this->UploadedTableAnisotropy;
        double k[6];
        GetTableCoordinates(g, k);
        const float stretch[2] = { static_cast<float>(k[0]), static_cast<float>(k[1]) };
        const float rows[4] = { static_cast<float>(k[2]), static_cast<float>(k[3]), static_cast<float>(k[4]),
          static_cast<float>(k[5]) };
        program->SetUniform2f("PhaseStretch", stretch);
        program->SetUniform4f("PhaseRows", rows);
        if (this->MarchSteps > 0)
        {
          program->SetUniformf("Anisotropy", static_cast<float>(g));
        }
      }
      const float origin[2] = { static_cast<float>(x), static_cast<float>(y) };
      program->SetUniform2f("ViewportOrigin", origin);
      vtkNew<vtkMatrix4x4> inverse;
      inverse->DeepCopy(camera->GetProjectionTransformMatrix(r->GetTiledAspectRatio(), -1.0, 1.0));
      inverse->Invert();
      plume::SetUniformMatrix4x4(program, "InverseProjection", inverse->GetData());
      program->SetUniformi("Perspective", camera->GetParallelProjection() ? 0 : 1);
      const float viewportSize[2] = { static_cast<float>(w), static_cast<float>(h) };
      program->SetUniform2f("ViewportSize", viewportSize);
      // The first group composites the attenuated surface; the others add airlight only.
      program->SetUniformi("AirlightOnly", gi == 0 ? 0 : 1);
      float ks[3], kt[3];
      for (int c = 0; c < 3; ++c)
      {
        ks[c] = static_cast<float>(this->Scattering[c]);
        kt[c] = static_cast<float>(this->Scattering[c] + this->Absorption[c]);
      }
      program->SetUniform3f("KappaS", ks);
      program->SetUniform3f("KappaT", kt);
      const int n = group.Count;
      const int l0 = group.First;
      program->SetUniformi("NumberOfLights", n);
      if (this->MarchSteps > 0)
      {
        double ktMin = HUGE_VAL;
        for (int c = 0; c < 3; ++c)
        {
          if (kt[c] > 0)
          {
            ktMin = std::min(ktMin, static_cast<double>(kt[c]));
          }
        }
        program->SetUniformf("MarchFar", static_cast<float>(std::log(1e6) / ktMin));
      }
      if (n > 0)
      {
        program->SetUniform3fv("LightPosition", n, reinterpret_cast<const float(*)[3]>(&positions[3 * l0]));
        program->SetUniform3fv("LightI0", n, reinterpret_cast<const float(*)[3]>(&intensities[3 * l0]));
        if (group.AnySpot || group.Shadows > 0)
        {
          program->SetUniform3fv("LightAxis", n, reinterpret_cast<const float(*)[3]>(&axes[3 * l0]));
          program->SetUniform1fv("LightCosCone", n, &cosCones[l0]);
          program->SetUniform1fv("LightExponent", n, &exponents[l0]);
          program->SetUniformi("SpotSteps", this->SpotSteps);
        }
        if (group.AnyTexture)
        {
          program->SetUniformi("LightTextures", this->TextureAtlas->GetTextureUnit());
          program->SetUniform4fv("LightTextureRect", n, reinterpret_cast<const float(*)[4]>(&textureRects[4 * l0]));
          program->SetUniform3fv(
            "LightTextureRight", n, reinterpret_cast<const float(*)[3]>(&textureRights[3 * l0]));
          program->SetUniform3fv("LightTextureUp", n, reinterpret_cast<const float(*)[3]>(&textureUps[3 * l0]));
        }
        if (group.Shadows > 0)
        {
          // The shader's sampler slots count from the group's first map.
          std::vector<int> local(n);
          for (int k = 0; k < n; ++k)
          {
            local[k] = shadowIndex[l0 + k] >= 0 ? shadowIndex[l0 + k] - group.FirstShadow : -1;
          }
          program->SetUniform1iv("LightShadow", n, local.data());
          program->SetUniformi("ShadowSteps", this->ShadowSteps);
          program->SetUniformi("ShadowMinMax", this->ShadowMinMax ? 1 : 0);
          program->SetUniformi("ShadowRunStatistics", this->ShadowRunStatistics ? 1 : 0);
          // Cube faces are world-axis aligned: the shader picks one by the world direction.
          double eyeToWorld[9];
          for (int i = 0; i < 3; ++i)
          {
            for (int j = 0; j < 3; ++j)
            {
              eyeToWorld[3 * i + j] = inverseView->GetElement(i, j);
            }
          }
          plume::SetUniformMatrix3x3(program, "EyeToWorld", eyeToWorld);
          for (int k = 0; k < group.Shadows; ++k)
          {
            const int m = group.FirstShadow + k;
            const std::string ks2 = std::to_string(k);
            this->ShadowMaps[m]->MinMax->Activate();
            program->SetUniformi(("ShadowMap" + ks2).c_str(), this->ShadowMaps[m]->MinMax->GetTextureUnit());
            for (int f = 0; f < 6; ++f)
            {
              plume::SetUniformMatrix4x4(program, ("ShadowMatrix" + ks2 + "[" + std::to_string(f) + "]").c_str(),
                &shadowMatrices[16 * (6 * m + f)]);
            }
            program->SetUniform2f(("ShadowRange" + ks2).c_str(), &shadowRanges[2 * m]);
            program->SetUniformi(("ShadowFaces" + ks2).c_str(), shadowFaces[m]);
            program->SetUniform3f(("ShadowLight" + ks2).c_str(), &shadowLights[3 * m]);
            const ShadowMap* sm = this->ShadowMaps[m];
            const int mapSize[2] = { sm->Faces == 6 ? 3 * sm->Size : sm->Size, sm->Faces == 6 ? 2 * sm->Size : sm->Size };
            program->SetUniform2i(("ShadowSize" + ks2).c_str(), mapSize);
            program->SetUniformi(("ShadowTop" + ks2).c_str(), sm->Top);
          }
        }
      }
    };
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_ALWAYS);
    auto blendGroup = [&]() {
      if (gi == 0)
      {
        ostate->vtkglDisable(GL_BLEND);
      }
      else
      {
        // The single-scattering airlight is a sum over lights: later groups add
        // theirs to the colour and keep the alpha.
        ostate->vtkglEnable(GL_BLEND);
        ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
      }
    };
    if (!lattice)
    {
      vtkOpenGLQuadHelper* quad = this->Programs->ReadyQuad(renWin, AirlightSource(), features);
      if (!quad)
      {
        vtkErrorMacro("Could not build the airlight shader program.");
        break;
      }
      setUniforms(quad->Program);
      blendGroup();
      ostate->vtkglViewport(x, y, w, h);
      ostate->vtkglScissor(x, y, w, h);
      quad->Render();
      this->Profiler.Mark("pixels");
    }
    else if (!this->RenderLattice(renWin, features, setUniforms, blendGroup, x, y, w, h,
               camera->GetProjectionTransformMatrix(r->GetTiledAspectRatio(), -1.0, 1.0),
               &positions[3 * group.First], &axes[3 * group.First], &cosCones[group.First], group.Count))
    {
      vtkErrorMacro("Could not build the airlight lattice's shader programs.");
      break;
    }
    for (int k = 0; k < group.Shadows; ++k)
    {
      this->ShadowMaps[group.FirstShadow + k]->MinMax->Deactivate();
    }
  }
  this->ColorTexture->Deactivate();
  this->DepthTexture->Deactivate();
  this->TableTexture->Deactivate();
  if (anyTexture)
  {
    this->TextureAtlas->Deactivate();
  }
  if (media)
  {
    this->MediaTexture->Deactivate();
    if (mediaTransmittance)
    {
      this->MediaTransmittanceTexture->Deactivate();
    }
    if (mediaDepthTexture)
    {
      mediaDepthTexture->Deactivate();
    }
  }
  vtkOpenGLCheckErrorMacro("failed after vtkPlumeAirlightPass::Render");
}

//------------------------------------------------------------------------------
bool vtkPlumeAirlightPass::RenderLattice(vtkOpenGLRenderWindow* renWin, const vtkPlumeShaderFeatures& base,
  const std::function<void(vtkShaderProgram*)>& setUniforms, const std::function<void()>& blendGroup,
  int x, int y, int w, int h, vtkMatrix4x4* projection, const float* lights,
  const float* axes, const float* cosCones, int count)
{
  vtkOpenGLState* ostate = renWin->GetState();
  int spacing[MaximumLatticeLevels], cells[MaximumLatticeLevels][2];
  const int levels = LatticeGeometry(this->Downsampling, this->LatticeLevels, w, h, spacing, cells);
  const int viewport[2] = { w, h };
  // level l's spacing, cells and textures, for the fragment shader
  auto levelUniforms = [&](vtkShaderProgram* program, int l) {
    setUniforms(program);
    program->SetUniformi("Lattice", spacing[l]);
    program->SetUniform2i("LatticeCellCount", cells[l]);
    program->SetUniformi("LatticeNodes", this->LatticeNodes[l]->GetTextureUnit());
    program->SetUniformi("LatticeCells", this->LatticeCells[l]->GetTextureUnit());
    // the lattice coordinate's two lines per axis: pixel / D, and the last
    // cell's (from its first pixel p0 to the viewport's last pixel)
    float slope[2], offset[2], inverseNodes[2];
    for (int a = 0; a < 2; ++a)
    {
      const int last = cells[l][a] - 1;
      const double p0 = static_cast<double>(last) * spacing[l];
      const double width = viewport[a] - 1 - p0;
      slope[a] = static_cast<float>(1.0 / width);
      offset[a] = static_cast<float>(last - p0 / width);
      inverseNodes[a] = static_cast<float>(1.0 / (cells[l][a] + 1));
    }
    program->SetUniformf("LatticeInverse", static_cast<float>(1.0 / spacing[l]));
    program->SetUniform2f("LatticeLastSlope", slope);
    program->SetUniform2f("LatticeLastOffset", offset);
    program->SetUniform2f("LatticeInverseNodes", inverseNodes);
    // (level 0 reads none of these; its samplers still need a valid unit)
    program->SetUniformi("LatticeCoarseNodes", this->LatticeNodes[0]->GetTextureUnit());
    program->SetUniformi("LatticeNodeMap", (l == 0 ? this->LatticeNodes[0] : this->LatticeNodeMap)->GetTextureUnit());
    program->SetUniformi("LatticeNodeList", (l == 0 ? this->LatticeNodes[0] : this->LatticeNodeList)->GetTextureUnit());
  };
  // Level l's refined cells drawn by the lattice cells' vertex shader on a
  // target of `size` pixels, `scale` pixels per cell: the viewport (scale:
  // the level's spacing) or the next level's cells (scale 2: each cell holds
  // 2 x 2 of the next level's).
  auto drawCells = [&](vtkShaderProgram* program, int l, int scale, const int size[2]) {
    this->EmptyVAO->Bind();
    plume::DrawLatticeCells(program, this->LatticeCells[l]->GetTextureUnit(), scale, cells[l], size);
    this->EmptyVAO->Release();
  };
  auto into = [&](vtkTextureObject* target, const int size[2]) {
    this->LowFrameBuffer->Bind();
    this->LowFrameBuffer->AddColorAttachment(0, target);
    this->LowFrameBuffer->ActivateDrawBuffers(1);
    this->LowFrameBuffer->ActivateReadBuffer(0);
    ostate->vtkglViewport(0, 0, size[0], size[1]);
    ostate->vtkglScissor(0, 0, size[0], size[1]);
  };
  // Level 0's nodes and cells are drawn into LatticeFolded: the first
  // ceil(n / 2) rows of an n-row target at x < its width, the others beside
  // them (the fragment shader unfolds; see the header); `unfold` copies them
  // to `target`, the natural layout.
  auto folded = [&](vtkShaderProgram* program, const int size[2]) {
    const int rows = (size[1] + 1) / 2;
    program->SetUniform2i("LatticeFold", std::array<int, 2>{ size[0], rows }.data());
    const int foldSize[2] = { 2 * size[0], rows };
    into(this->LatticeFolded, foldSize);
  };
  auto unfold = [&](vtkTextureObject* target, const int size[2]) {
    // copied from the bound folded target into `target` on its own texture
    // unit (Bind alone would bind it on the active unit, another lattice
    // texture's), the active unit then put back
    const int rows = (size[1] + 1) / 2;
    GLint active = GL_TEXTURE0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    target->Activate();
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, size[0], rows);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, rows, size[0], 0, size[0], size[1] - rows);
    ostate->vtkglActiveTexture(static_cast<unsigned int>(active));
    into(target, size);
  };
  ostate->vtkglDisable(GL_BLEND);
  for (int l = 0; l < levels; ++l)
  {
    this->LatticeNodes[l]->Activate();
    this->LatticeCells[l]->Activate();
  }
  ostate->PushFramebufferBindings();
  int fineRows = 1; // level 1: rows of LatticeNodes[1] in use

  // The classification's uniforms. An eye-space point's viewport pixel
  // (index units, clamped to +-1e6), written to out[0..1]; its clip w (> 0:
  // in front of the eye) returned.
  auto toPixel = [&](double x, double y, double z, float out[2]) {
    double p[4] = { x, y, z, 1.0 };
    projection->MultiplyPoint(p, p);
    for (int k = 0; k < 2; ++k)
    {
      const double q = (p[k] / p[3] * 0.5 + 0.5) * (k == 0 ? w : h) - 0.5;
      out[k] = static_cast<float>(std::max(-1e6, std::min(q, 1e6)));
    }
    return p[3];
  };
  std::vector<float> pixels(3 * std::max(count, 1), 0.0f);
  for (int l = 0; l < count; ++l)
  {
    // the light's viewport pixel, and whether it is in front of the eye
    float pixel[2];
    if (toPixel(lights[3 * l], lights[3 * l + 1], lights[3 * l + 2], pixel) > 0.0 && lights[3 * l + 2] < 0.0)
    {
      std::copy(pixel, pixel + 2, &pixels[3 * l]);
      pixels[3 * l + 2] = 1.0f;
    }
  }
  // Narrow spots (cone below NarrowSpotAngle): the image of their axis from
  // the apex to the far plane, clipped to the near plane (far away: none).
  std::vector<float> shafts(4 * std::max(count, 1), 1e6f);
  const double nearZ = -std::abs(projection->GetElement(2, 3) / (projection->GetElement(2, 2) - 1.0));
  for (int l = 0; l < count; ++l)
  {
    if (!(cosCones[l] > std::cos(vtkMath::RadiansFromDegrees(NarrowSpotAngle))))
    {
      continue;
    }
    glm::dvec3 a(lights[3 * l], lights[3 * l + 1], lights[3 * l + 2]);
    glm::dvec3 b = a + 1e6 * glm::dvec3(axes[3 * l], axes[3 * l + 1], axes[3 * l + 2]);
    const double zMax = std::isfinite(nearZ) && nearZ < 0 ? nearZ * 1.001 : -1e-6;
    if (a.z > zMax && b.z > zMax)
    {
      continue; // behind the eye
    }
    if (a.z > zMax)
    {
      a += (b - a) * ((a.z - zMax) / (a.z - b.z));
    }
    else if (b.z > zMax)
    {
      b += (a - b) * ((b.z - zMax) / (b.z - a.z));
    }
    toPixel(a.x, a.y, a.z, &shafts[4 * l]);
    toPixel(b.x, b.y, b.z, &shafts[4 * l + 2]);
  }
  double range = 0.0; // the frame's airlight range, from level 0's nodes

  // Per level: 1. the nodes' airlight (light code); 2. the cells to refine
  // (no light code). Level 0 covers the viewport; a finer level only its
  // parent's refined cells (3 x 3 nodes each, the five not its parent's
  // listed on the CPU and evaluated densely; its second differences taken
  // among them; its other cells cleared to 0).
  for (int l = 0; l < levels; ++l)
  {
    const int nodes[2] = { LatticeNodesSize(cells, l, 0), LatticeNodesSize(cells, l, 1) };
    vtkPlumeShaderFeatures f = base;
    f.Enable("LATTICE_NODES").Enable("LATTICE_FINE", l > 0);
    vtkOpenGLQuadHelper* quad = this->Programs->ReadyQuad(renWin, AirlightSource(), f);
    vtkShaderProgram* program = quad ? quad->Program : nullptr;
    if (!program)
    {
      ostate->PopFramebufferBindings();
      return false;
    }
    levelUniforms(program, l);
    if (l == 0)
    {
      folded(program, nodes);
      quad->Render();
      unfold(this->LatticeNodes[l], nodes);
      // read back for the frame's airlight range
      std::vector<float> values(static_cast<size_t>(nodes[0]) * nodes[1] * 4);
      glReadPixels(0, 0, nodes[0], nodes[1], GL_RGBA, GL_FLOAT, values.data());
      float lo = HUGE_VALF, hi = -HUGE_VALF;
      for (size_t k = 0; k < values.size(); ++k)
      {
        if (k % 4 != 3 && std::isfinite(values[k]))
        {
          lo = std::min(lo, values[k]);
          hi = std::max(hi, values[k]);
        }
      }
      // The error goal is relative to the airlight image's range; an 8-bit
      // window shows at most 1 of it (a light in view can make the range huge).
      range = hi > lo ? std::min(static_cast<double>(hi - lo), 1.0) : 0.0;
    }
    else
    {
      // the listed nodes only, 64 a row
      const int used[2] = { nodes[0], fineRows };
      into(this->LatticeNodes[l], used);
      quad->Render();
    }
    this->Profiler.Mark("nodes", l);

    f = base;
    f.Enable("LATTICE_CLASSIFY").Enable("NO_LIGHTS").Enable("LATTICE_FINE", l > 0);
    if (l == 0)
    {
      quad = this->Programs->ReadyQuad(renWin, AirlightSource(), f);
      program = quad ? quad->Program : nullptr;
    }
    else
    {
      program = this->Programs->Ready(renWin, vtkPlumeLatticeCellsVS, nullptr, AirlightSource(), f);
    }
    if (!program)
    {
      ostate->PopFramebufferBindings();
      return false;
    }
    levelUniforms(program, l);
    program->SetUniformf("LatticeTolerance", static_cast<float>(this->UpsamplingTolerance * range));
    program->SetUniformf("LatticeDepthTolerance", static_cast<float>(LatticeDepthTolerance));
    program->SetUniform3fv("LightPixel", std::max(count, 1), reinterpret_cast<const float(*)[3]>(pixels.data()));
    program->SetUniform4fv("LightShaft", std::max(count, 1), reinterpret_cast<const float(*)[4]>(shafts.data()));
    if (l == 0)
    {
      folded(program, cells[l]);
      quad->Render();
      unfold(this->LatticeCells[l], cells[l]);
      if (levels > 1)
      {
        fineRows = this->ListLatticeNodes(cells);
      }
    }
    else
    {
      into(this->LatticeCells[l], cells[l]);
      ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
      ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
      drawCells(program, l - 1, 2, cells[l]);
    }
    this->Profiler.Mark("classify", l);
  }
  // counted only if asked (GetLastRefinedCellFraction): no wait here
  this->LatticeFlagsPending = true;
  this->LatticeFrame = { levels, { w, h } };
  std::copy(spacing, spacing + levels, this->LatticeFrame.Spacing);
  std::copy(&cells[0][0], &cells[0][0] + 2 * levels, &this->LatticeFrame.Cells[0][0]);
  this->LatticeWindow = renWin;
  this->LowFrameBuffer->RemoveColorAttachments(1);
  ostate->PopFramebufferBindings();

  // 3. The frame: level 0's interpolated airlight, none in its refined cells
  // (no light code).
  vtkPlumeShaderFeatures f = base;
  f.Enable("LATTICE_RESOLVE").Enable("NO_LIGHTS");
  vtkOpenGLQuadHelper* quad = this->Programs->ReadyQuad(renWin, AirlightSource(), f);
  if (!quad)
  {
    return false;
  }
  levelUniforms(quad->Program, 0);
  blendGroup();
  ostate->vtkglViewport(x, y, w, h);
  ostate->vtkglScissor(x, y, w, h);
  quad->Render();
  this->Profiler.Mark("resolve");

  // 4. Added in the parent's refined cells: each finer level's interpolated
  // airlight (no light code), then the last level's refined cells' exact
  // airlight.
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  ostate->vtkglDepthMask(GL_FALSE);
  for (int l = 1; l <= levels; ++l)
  {
    const bool refine = l == levels;
    f = base;
    if (refine)
    {
      f.Enable("LATTICE_REFINE");
    }
    else
    {
      f.Enable("LATTICE_INTERPOLATE").Enable("NO_LIGHTS").Enable("LATTICE_FINE");
    }
    vtkShaderProgram* program = this->Programs->Ready(renWin, vtkPlumeLatticeCellsVS, nullptr, AirlightSource(), f);
    if (!program)
    {
      return false;
    }
    levelUniforms(program, refine ? l - 1 : l);
    drawCells(program, l - 1, spacing[l - 1], viewport);
    this->Profiler.Mark(refine ? "refine" : "interpolate", refine ? 0 : l);
  }
  for (int l = 0; l < levels; ++l)
  {
    this->LatticeNodes[l]->Deactivate();
    this->LatticeCells[l]->Deactivate();
  }
  if (levels > 1)
  {
    this->LatticeNodeMap->Deactivate();
    this->LatticeNodeList->Deactivate();
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkPlumeAirlightPass::ListLatticeNodes(const int cells[][2])
{
  // Level 0's flags, from the bound cell target.
  std::vector<float> flags(static_cast<size_t>(cells[0][0]) * cells[0][1]);
  glReadPixels(0, 0, cells[0][0], cells[0][1], GL_RED, GL_FLOAT, flags.data());
  // Level 1's nodes in refined parents that are not level 0's (both indices
  // even), each once; parents one level-1 cell wide (the viewport's edge)
  // are refined whole and need none.
  const int mw = cells[1][0] + 1, mh = cells[1][1] + 1;
  std::vector<float> map(static_cast<size_t>(mw) * mh, -1.0f);
  std::vector<float> list;
  for (int j = 0; j < cells[0][1]; ++j)
  {
    for (int i = 0; i < cells[0][0]; ++i)
    {
      if (flags[static_cast<size_t>(j) * cells[0][0] + i] == 0.0f || 2 * i + 2 > cells[1][0] ||
        2 * j + 2 > cells[1][1])
      {
        continue;
      }
      for (int b = 0; b < 3; ++b)
      {
        for (int a = 0; a < 3; ++a)
        {
          const int nx = 2 * i + a, ny = 2 * j + b;
          float& k = map[static_cast<size_t>(ny) * mw + nx];
          if ((nx % 2 != 0 || ny % 2 != 0) && k < 0.0f)
          {
            k = static_cast<float>(list.size() / 2);
            list.push_back(static_cast<float>(nx));
            list.push_back(static_cast<float>(ny));
          }
        }
      }
    }
  }
  const int rows = std::max(1, static_cast<int>((list.size() / 2 + 63) / 64));
  list.resize(static_cast<size_t>(64) * rows * 2, 0.0f);
  this->LatticeNodeMap->Create2DFromRaw(mw, mh, 1, VTK_FLOAT, map.data());
  this->LatticeNodeList->Create2DFromRaw(64, rows, 2, VTK_FLOAT, list.data());
  this->LatticeNodeMap->Activate();
  this->LatticeNodeList->Activate();
  return rows;
}

//------------------------------------------------------------------------------
void vtkPlumeAirlightPass::CountLatticeFlags()
{
  if (!this->LatticeFlagsPending || !this->LatticeWindow)
  {
    return;
  }
  this->LatticeFlagsPending = false;
  // the lattice of the frame that drew the flags (Downsampling and
  // LatticeLevels may have changed since)
  const int levels = this->LatticeFrame.Levels, w = this->LatticeFrame.Size[0], h = this->LatticeFrame.Size[1];
  const int* spacing = this->LatticeFrame.Spacing;
  const int(*cells)[2] = this->LatticeFrame.Cells;
  for (int l = 0; l < levels; ++l)
  {
    vtkTextureObject* t = this->LatticeCells[l];
    if (!t || static_cast<int>(t->GetWidth()) != cells[l][0] || static_cast<int>(t->GetHeight()) != cells[l][1])
    {
      return; // resized since that frame (a later frame's viewport): nothing to count
    }
  }
  this->LatticeWindow->MakeCurrent();
  for (int l : { 0, levels - 1 })
  {
    vtkSmartPointer<vtkPixelBufferObject> pbo =
      vtkSmartPointer<vtkPixelBufferObject>::Take(this->LatticeCells[l]->Download());
    const float* flags = static_cast<const float*>(pbo->MapPackedBuffer());
    if (!flags)
    {
      continue;
    }
    size_t refinedCells = 0, refinedPixels = 0;
    for (int j = 0; j < cells[l][1]; ++j)
    {
      for (int i = 0; i < cells[l][0]; ++i)
      {
        if (flags[static_cast<size_t>(j) * cells[l][0] + i] != 0.0f)
        {
          // the last cell of a row or column reaches the viewport's edge
          const int cw = (i == cells[l][0] - 1 ? w : (i + 1) * spacing[l]) - i * spacing[l];
          const int ch = (j == cells[l][1] - 1 ? h : (j + 1) * spacing[l]) - j * spacing[l];
          ++refinedCells;
          refinedPixels += static_cast<size_t>(cw) * ch;
        }
      }
    }
    pbo->UnmapPackedBuffer();
    if (l == 0)
    {
      this->LastRefinedCellFraction = refinedCells / double(cells[0][0] * cells[0][1]);
    }
    if (l == levels - 1)
    {
      this->LastRefinedPixelFraction = refinedPixels / double(w * h);
    }
  }
}

//------------------------------------------------------------------------------
double vtkPlumeAirlightPass::GetLastRefinedCellFraction()
{
  this->CountLatticeFlags();
  return this->LastRefinedCellFraction;
}

//------------------------------------------------------------------------------
double vtkPlumeAirlightPass::GetLastRefinedPixelFraction()
{
  this->CountLatticeFlags();
  return this->LastRefinedPixelFraction;
}

//------------------------------------------------------------------------------
void vtkPlumeAirlightPass::ReleaseGraphicsResources(vtkWindow* w)
{
  if (w && w == this->LatticeWindow)
  {
    this->CountLatticeFlags(); // before the flags' textures go
  }
  this->LatticeFlagsPending = false;
  this->Superclass::ReleaseGraphicsResources(w);
  this->Programs->ReleaseGraphicsResources(w);
  // every texture of the pass (the lattice's levels too), in one list
  std::vector<vtkTextureObject**> textures = { &this->ColorTexture, &this->DepthTexture, &this->TableTexture,
    &this->MediaTexture, &this->MediaTransmittanceTexture, &this->TextureAtlas, &this->LatticeNodeMap,
    &this->LatticeNodeList, &this->LatticeFolded };
  for (int l = 0; l < MaximumLatticeLevels; ++l)
  {
    textures.insert(textures.end(), { &this->LatticeNodes[l], &this->LatticeCells[l] });
  }
  for (vtkTextureObject** t : textures)
  {
    if (*t)
    {
      (*t)->Delete();
      *t = nullptr;
    }
  }
  this->EmptyVAO->ReleaseGraphicsResources();
  this->UploadedTableResolution = 0;
  this->TextureAtlasKey.clear();
  for (ShadowMap* m : this->ShadowMaps)
  {
    m->Release();
  }
  for (vtkOpenGLFramebufferObject** f : { &this->FrameBuffer, &this->LowFrameBuffer })
  {
    if (*f)
    {
      (*f)->Delete();
      *f = nullptr;
    }
  }
}
