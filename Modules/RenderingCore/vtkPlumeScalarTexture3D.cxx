#include "vtkPlumeScalarTexture3D.h"

#include "vtkPlumeTextureHandOver.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

#include "vtk_glew.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkPlumeScalarTexture3D);

namespace
{
// value of tuple i as the renderers see it (component or magnitude), in double
template <typename T>
void Extract(const T* src, vtkIdType n, int comps, int component, std::vector<double>& out)
{
  for (vtkIdType i = 0; i < n; ++i)
  {
    const T* t = src + i * comps;
    if (component >= 0)
    {
      out[i] = static_cast<double>(t[component]);
    }
    else if (comps == 1)
    {
      out[i] = static_cast<double>(t[0]);
    }
    else
    {
      double s = 0;
      for (int c = 0; c < comps; ++c)
      {
        s += static_cast<double>(t[c]) * static_cast<double>(t[c]);
      }
      out[i] = std::sqrt(s);
    }
  }
}
}

vtkPlumeScalarTexture3D::vtkPlumeScalarTexture3D() = default;
vtkPlumeScalarTexture3D::~vtkPlumeScalarTexture3D() = default;

void vtkPlumeScalarTexture3D::GetScaleBias(const double range[2], double scaleBias[2]) const
{
  // u = (t / ValueScale + ValueShift - range[0]) / span, halves so that spans
  // near DBL_MAX do not overflow
  const double halfSpan = 0.5 * range[1] - 0.5 * range[0];
  double scale = halfSpan != 0.0 ? (0.5 / halfSpan) / this->ValueScale : 0.0;
  double bias = halfSpan != 0.0 ? (0.5 * this->ValueShift - 0.5 * range[0]) / halfSpan : 0.0;
  if (!std::isfinite(scale) || !std::isfinite(bias))
  {
    scale = bias = 0.0;
  }
  scaleBias[0] = scale;
  scaleBias[1] = bias;
}

void vtkPlumeScalarTexture3D::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  this->Handed = Signature(); // a hand-over bound again after a release counts again
}

bool vtkPlumeScalarTexture3D::Update(vtkOpenGLRenderWindow* window, vtkImageData* image,
  vtkDataArray* array, int component, vtkDataArray* mask)
{
  this->LastError.clear();
  if (!window || !image || !array)
  {
    this->LastError = "no window, image or array";
    return false;
  }
  const int comps = array->GetNumberOfComponents();
  if (component >= comps)
  {
    std::ostringstream msg;
    msg << "component " << component << " requested but array '"
        << (array->GetName() ? array->GetName() : "") << "' has " << comps << " component(s)";
    this->LastError = msg.str();
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  const vtkIdType n = static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2];
  if (n <= 0 || array->GetNumberOfTuples() != n)
  {
    std::ostringstream msg;
    msg << "array '" << (array->GetName() ? array->GetName() : "") << "' has "
        << array->GetNumberOfTuples() << " tuples but the image has " << n << " points";
    this->LastError = msg.str();
    return false;
  }
  if (mask && (mask->GetNumberOfTuples() != n || mask->GetNumberOfComponents() != 1))
  {
    std::ostringstream msg;
    msg << "valid-point mask '" << (mask->GetName() ? mask->GetName() : "") << "' must have one component and "
        << n << " tuples (has " << mask->GetNumberOfComponents() << " and " << mask->GetNumberOfTuples() << ")";
    this->LastError = msg.str();
    return false;
  }
  if (!this->BeginUpdate(window, dims))
  {
    return false;
  }

  const Signature sig{ image, array, mask, component, this->Gradients,
    std::max({ image->GetMTime(), array->GetMTime(), mask ? mask->GetMTime() : vtkMTimeType(0) }) };

  // the producer's GPU copy: raw values of a one-component array, one float channel, our size;
  // usable as it is only without a mask, gradients or non-finite values
  vtkTextureObject* handed = (mask || this->Gradients || comps != 1)
    ? nullptr
    : vtkPlumeTextureHandOver::Find(array, window, dims, 1);
  if (handed)
  {
    if (!(sig == this->Analysed) || this->ValueShift != 0.0 || this->ValueScale != 1.0)
    {
      this->ValueShift = 0.0; // the producer's texels are the values themselves
      if (!this->Analyse(array, component, mask, dims, nullptr))
      {
        return false;
      }
      this->Analysed = sig;
    }
    if (this->NonFiniteCount > 0)
    {
      handed = nullptr; // its NaN/Inf would reach the shader: upload sanitised values instead
    }
  }
  this->HandedOver = handed != nullptr;
  if (handed)
  {
    if (this->BindHandOver(handed, window, sig))
    {
      ++this->DataVersion;
    }
    return true;
  }
  this->Handed = Signature();
  this->Bound = this->Texture;
  if (sig == this->Uploaded && this->Texture->GetHandle())
  {
    return true;
  }

  std::vector<float> texels;
  if (!this->Analyse(array, component, mask, dims, &texels))
  {
    return false;
  }
  this->Analysed = sig;
  const int channels = this->Masked ? 2 : (this->HasGradients ? 4 : 1);
  this->Texture->SetContext(window);
  // the format is cached by the texture object: one, two or four channels per upload
  this->Texture->ResetFormatAndType();
  SetSampling(this->Texture);
  if (!this->Texture->Create3DFromRaw(dims[0], dims[1], dims[2], channels, VTK_FLOAT, texels.data()))
  {
    std::ostringstream msg;
    msg << "could not create the " << dims[0] << "x" << dims[1] << "x" << dims[2]
        << (this->Masked ? " RG32F" : (this->HasGradients ? " RGBA32F" : " R32F")) << " 3D texture";
    this->LastError = msg.str();
    this->Uploaded = Signature();
    this->Analysed = Signature();
    return false;
  }
  this->Uploaded = sig;
  ++this->UploadCount;
  ++this->DataVersion;
  return true;
}

bool vtkPlumeScalarTexture3D::Analyse(
  vtkDataArray* array, int component, vtkDataArray* mask, const int dims[3], std::vector<float>* texels)
{
  const vtkIdType n = static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2];
  const int comps = array->GetNumberOfComponents();
  std::vector<double> values(static_cast<size_t>(n));
  switch (array->GetDataType())
  {
    vtkTemplateMacro(Extract(
      static_cast<const VTK_TT*>(array->GetVoidPointer(0)), n, comps, component, values));
    default:
    {
      std::vector<double> tuple(comps);
      for (vtkIdType i = 0; i < n; ++i)
      {
        array->GetTuple(i, tuple.data());
        double s = 0;
        for (int c = 0; c < comps; ++c)
        {
          s += tuple[c] * tuple[c];
        }
        values[i] = component >= 0 ? tuple[component] : (comps == 1 ? tuple[0] : std::sqrt(s));
      }
    }
  }

  // nodes outside the data (mask 0)
  std::vector<bool> outside;
  if (mask)
  {
    outside.resize(static_cast<size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      outside[i] = mask->GetComponent(i, 0) == 0.0;
    }
    if (std::find(outside.begin(), outside.end(), true) == outside.end())
    {
      outside.clear(); // nothing masked: plain values
    }
  }
  const bool masked = !outside.empty();

  // finite range in double (of the valid nodes)
  double lo = VTK_DOUBLE_MAX, hi = -VTK_DOUBLE_MAX;
  long long nonFinite = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = values[i];
    if (masked && outside[i])
    {
      continue;
    }
    if (std::isfinite(v))
    {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    else
    {
      ++nonFinite;
    }
  }
  if (lo > hi)
  {
    lo = hi = 0.0;
  }
  // our uploads store v - lo (see the class documentation); a hand-over holds v (shift 0).
  // Spans float cannot hold with its precision (beyond 1e30 or below 1e-30) are
  // stored divided by the span instead (in [0, 1])
  const double shift = texels ? lo : 0.0;
  const double halfSpan = 0.5 * hi - 0.5 * lo;
  const bool rescale = texels && halfSpan > 0 && (halfSpan > 0.5e30 || halfSpan < 0.5e-30);
  const double valueScale = rescale ? 0.5 / halfSpan : 1.0;
  // the texel value of every node, sanitised; float(v - shift) is what the GPU interpolates
  std::vector<float> t(static_cast<size_t>(n));
  const double fmax = static_cast<double>(FLT_MAX);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double v = values[i];
    if (std::isnan(v))
    {
      v = lo;
    }
    else if (std::isinf(v))
    {
      v = v > 0 ? hi : lo;
    }
    const double stored = rescale ? (0.5 * v - 0.5 * shift) / halfSpan : v - shift;
    // (a handed-over array's values beyond float's range saturate instead of becoming Inf)
    t[i] = static_cast<float>(std::min(fmax, std::max(-fmax, stored)));
  }
  values.clear();
  values.shrink_to_fit();

  const bool gradients = this->Gradients && !masked;
  // min/max per block of BlockSize voxels (nodes I·B .. (I+1)·B), valid nodes only
  this->BlockRanges.clear();
  if (this->BlockSize > 0)
  {
    const int b = this->BlockSize;
    for (int a = 0; a < 3; ++a)
    {
      this->BlockDimensions[a] = std::max(1, (dims[a] - 1 + b - 1) / b);
    }
    const size_t blocks =
      static_cast<size_t>(this->BlockDimensions[0]) * this->BlockDimensions[1] * this->BlockDimensions[2];
    this->BlockRanges.resize(2 * blocks);
    for (int bk = 0; bk < this->BlockDimensions[2]; ++bk)
    {
      for (int bj = 0; bj < this->BlockDimensions[1]; ++bj)
      {
        for (int bi = 0; bi < this->BlockDimensions[0]; ++bi)
        {
          float mn = FLT_MAX, mx = -FLT_MAX;
          for (int k = bk * b; k <= std::min((bk + 1) * b, dims[2] - 1); ++k)
          {
            for (int j = bj * b; j <= std::min((bj + 1) * b, dims[1] - 1); ++j)
            {
              const size_t row = static_cast<size_t>(dims[0]) * (j + static_cast<size_t>(dims[1]) * k);
              for (int i = bi * b; i <= std::min((bi + 1) * b, dims[0] - 1); ++i)
              {
                if (masked && outside[row + i])
                {
                  continue; // outside the data
                }
                mn = std::min(mn, t[row + i]);
                mx = std::max(mx, t[row + i]);
              }
            }
          }
          const size_t id = bi + static_cast<size_t>(this->BlockDimensions[0]) *
              (bj + static_cast<size_t>(this->BlockDimensions[1]) * bk);
          this->BlockRanges[2 * id] = mn;
          this->BlockRanges[2 * id + 1] = mx;
        }
      }
    }
  }

  if (texels)
  {
    if (masked)
    {
      // (t w, w): see the class documentation
      texels->resize(2 * static_cast<size_t>(n));
      for (vtkIdType i = 0; i < n; ++i)
      {
        (*texels)[2 * i] = outside[i] ? 0.0f : t[i];
        (*texels)[2 * i + 1] = outside[i] ? 0.0f : 1.0f;
      }
    }
    else if (gradients)
    {
      // (t, central differences along x, y, z): see the class documentation
      texels->resize(4 * static_cast<size_t>(n));
      float* ug = texels->data();
      const size_t sx = 1, sy = static_cast<size_t>(dims[0]), sz = sy * dims[1];
      for (int k = 0; k < dims[2]; ++k)
      {
        for (int j = 0; j < dims[1]; ++j)
        {
          for (int i = 0; i < dims[0]; ++i)
          {
            const size_t id = i + sy * j + sz * k;
            ug[4 * id] = t[id];
            ug[4 * id + 1] = t[id + (i + 1 < dims[0] ? sx : 0)] - t[id - (i > 0 ? sx : 0)];
            ug[4 * id + 2] = t[id + (j + 1 < dims[1] ? sy : 0)] - t[id - (j > 0 ? sy : 0)];
            ug[4 * id + 3] = t[id + (k + 1 < dims[2] ? sz : 0)] - t[id - (k > 0 ? sz : 0)];
          }
        }
      }
    }
    else
    {
      texels->swap(t);
    }
  }
  this->ValueShift = shift;
  this->ValueScale = valueScale;
  this->ScalarRange[0] = lo;
  this->ScalarRange[1] = hi;
  std::copy(dims, dims + 3, this->Dimensions);
  this->NonFiniteCount = nonFinite;
  this->Masked = masked;
  this->HasGradients = gradients;
  return true;
}

void vtkPlumeScalarTexture3D::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ScalarRange: " << this->ScalarRange[0] << " " << this->ScalarRange[1] << "\n";
  os << indent << "ValueShift: " << this->ValueShift << " ValueScale: " << this->ValueScale << "\n";
  os << indent << "Dimensions: " << this->Dimensions[0] << " " << this->Dimensions[1] << " "
     << this->Dimensions[2] << "\n";
  os << indent << "NonFiniteCount: " << this->NonFiniteCount << "\n";
}
