#include "vtkPlumeScalarTexture3D.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

#include "vtk_glew.h"

#include <algorithm>
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

vtkPlumeScalarTexture3D::vtkPlumeScalarTexture3D()
  : Texture(vtkSmartPointer<vtkTextureObject>::New())
{
}

vtkPlumeScalarTexture3D::~vtkPlumeScalarTexture3D() = default;

vtkTextureObject* vtkPlumeScalarTexture3D::GetTextureObject()
{
  return this->Texture;
}

void vtkPlumeScalarTexture3D::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Texture->ReleaseGraphicsResources(window);
  this->UploadedImage = nullptr;
  this->UploadedArray = nullptr;
  this->UploadedComponent = -2;
  this->UploadedTime = 0;
  this->UploadedMask = nullptr;
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
  const vtkMTimeType time =
    std::max({ image->GetMTime(), array->GetMTime(), mask ? mask->GetMTime() : vtkMTimeType(0) });
  if (this->Texture->GetContext() == window && this->Texture->GetHandle() &&
    this->UploadedImage == image && this->UploadedArray == array &&
    this->UploadedComponent == component && this->UploadedTime == time && this->UploadedMask == mask &&
    (this->Masked || this->UploadedGradients == this->Gradients)) // (masked: no gradients either way)
  {
    return true;
  }

  GLint maxSize = 0;
  window->MakeCurrent();
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSize);
  if (dims[0] > maxSize || dims[1] > maxSize || dims[2] > maxSize)
  {
    std::ostringstream msg;
    msg << "grid " << dims[0] << "x" << dims[1] << "x" << dims[2]
        << " exceeds GL_MAX_3D_TEXTURE_SIZE = " << maxSize
        << " along at least one axis; resample the data to a coarser image";
    this->LastError = msg.str();
    return false;
  }

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
      outside.clear(); // nothing masked: plain u
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
  const double span = hi - lo;
  const double inv = (span > 0 && std::isfinite(1.0 / span)) ? 1.0 / span : 0.0;
  std::vector<float> u(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = values[i];
    double t;
    if (std::isnan(v))
    {
      t = 0.0;
    }
    else if (std::isinf(v))
    {
      t = v > 0 ? 1.0 : 0.0;
    }
    else
    {
      t = (v - lo) * inv;
    }
    // (v - lo) * inv can overflow for spans near DBL_MAX; clamp keeps it finite
    u[i] = static_cast<float>(std::min(1.0, std::max(0.0, std::isfinite(t) ? t : 0.0)));
  }
  if (span > 0 && inv == 0.0)
  {
    // span so large that 1/span underflows: scale in two steps
    const double half = 0.5 * hi - 0.5 * lo;
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double v = values[i];
      if (std::isfinite(v))
      {
        u[i] = static_cast<float>(std::min(1.0, std::max(0.0, 0.5 * ((0.5 * v - 0.5 * lo) / half))));
      }
    }
  }
  if (masked)
  {
    // (u w, w): see the class documentation
    std::vector<float> uw(2 * static_cast<size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      uw[2 * i] = outside[i] ? 0.0f : u[i];
      uw[2 * i + 1] = outside[i] ? 0.0f : 1.0f;
    }
    u.swap(uw);
  }
  const bool gradients = this->Gradients && !masked;
  if (gradients)
  {
    // (u, central differences along x, y, z): see the class documentation
    std::vector<float> ug(4 * static_cast<size_t>(n));
    const size_t sx = 1, sy = static_cast<size_t>(dims[0]), sz = sy * dims[1];
    for (int k = 0; k < dims[2]; ++k)
    {
      for (int j = 0; j < dims[1]; ++j)
      {
        for (int i = 0; i < dims[0]; ++i)
        {
          const size_t id = i + sy * j + sz * k;
          ug[4 * id] = u[id];
          ug[4 * id + 1] = u[id + (i + 1 < dims[0] ? sx : 0)] - u[id - (i > 0 ? sx : 0)];
          ug[4 * id + 2] = u[id + (j + 1 < dims[1] ? sy : 0)] - u[id - (j > 0 ? sy : 0)];
          ug[4 * id + 3] = u[id + (k + 1 < dims[2] ? sz : 0)] - u[id - (k > 0 ? sz : 0)];
        }
      }
    }
    u.swap(ug);
  }
  const int channels = masked ? 2 : (gradients ? 4 : 1);

  this->Texture->SetContext(window);
  // the format is cached by the texture object: one or two channels per upload
  this->Texture->ResetFormatAndType();
  this->Texture->SetWrapS(vtkTextureObject::ClampToEdge);
  this->Texture->SetWrapT(vtkTextureObject::ClampToEdge);
  this->Texture->SetWrapR(vtkTextureObject::ClampToEdge);
  this->Texture->SetMinificationFilter(vtkTextureObject::Linear);
  this->Texture->SetMagnificationFilter(vtkTextureObject::Linear);
  if (!this->Texture->Create3DFromRaw(dims[0], dims[1], dims[2], channels, VTK_FLOAT, u.data()))
  {
    std::ostringstream msg;
    msg << "could not create the " << dims[0] << "x" << dims[1] << "x" << dims[2]
        << (masked ? " RG32F" : (gradients ? " RGBA32F" : " R32F")) << " 3D texture";
    this->LastError = msg.str();
    this->UploadedImage = nullptr;
    return false;
  }
  // min/max per block of BlockSize voxels (nodes I·B .. (I+1)·B)
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
    const size_t ch = static_cast<size_t>(channels); // per node in u
    for (int bk = 0; bk < this->BlockDimensions[2]; ++bk)
    {
      for (int bj = 0; bj < this->BlockDimensions[1]; ++bj)
      {
        for (int bi = 0; bi < this->BlockDimensions[0]; ++bi)
        {
          float mn = 1.0f, mx = 0.0f;
          for (int k = bk * b; k <= std::min((bk + 1) * b, dims[2] - 1); ++k)
          {
            for (int j = bj * b; j <= std::min((bj + 1) * b, dims[1] - 1); ++j)
            {
              const float* row = &u[ch * static_cast<size_t>(dims[0]) * (j + static_cast<size_t>(dims[1]) * k)];
              for (int i = bi * b; i <= std::min((bi + 1) * b, dims[0] - 1); ++i)
              {
                if (masked && row[ch * i + 1] == 0.0f)
                {
                  continue; // outside the data
                }
                mn = std::min(mn, row[ch * i]);
                mx = std::max(mx, row[ch * i]);
              }
            }
          }
          const size_t id = bi + static_cast<size_t>(this->BlockDimensions[0]) * (bj + static_cast<size_t>(this->BlockDimensions[1]) * bk);
          this->BlockRanges[2 * id] = mn;
          this->BlockRanges[2 * id + 1] = mx;
        }
      }
    }
  }
  this->ScalarRange[0] = lo;
  this->ScalarRange[1] = hi;
  std::copy(dims, dims + 3, this->Dimensions);
  this->NonFiniteCount = nonFinite;
  this->UploadedImage = image;
  this->UploadedArray = array;
  this->UploadedComponent = component;
  this->UploadedTime = time;
  this->UploadedMask = mask;
  this->Masked = masked;
  this->HasGradients = gradients;
  this->UploadedGradients = this->Gradients;
  ++this->UploadCount;
  return true;
}

void vtkPlumeScalarTexture3D::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ScalarRange: " << this->ScalarRange[0] << " " << this->ScalarRange[1] << "\n";
  os << indent << "Dimensions: " << this->Dimensions[0] << " " << this->Dimensions[1] << " "
     << this->Dimensions[2] << "\n";
  os << indent << "NonFiniteCount: " << this->NonFiniteCount << "\n";
  os << indent << "UploadCount: " << this->UploadCount << "\n";
}
