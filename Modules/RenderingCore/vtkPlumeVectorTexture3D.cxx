#include "vtkPlumeVectorTexture3D.h"

#include "vtkPlumeTextureHandOver.h"

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

vtkStandardNewMacro(vtkPlumeVectorTexture3D);

namespace
{
template <typename T>
void CopyVectors(const T* src, vtkIdType begin, vtkIdType end, float* rgba)
{
  for (vtkIdType i = begin; i < end; ++i, rgba += 4)
  {
    for (int c = 0; c < 3; ++c)
    {
      rgba[c] = static_cast<float>(src[3 * i + c]);
    }
    rgba[3] = 1.0f;
  }
}

template <typename T>
void ApplyMask(const T* src, vtkIdType begin, vtkIdType end, int comps, float* rgba)
{
  for (vtkIdType i = begin; i < end; ++i, rgba += 4)
  {
    if (src[i * comps] == T(0))
    {
      rgba[3] = 0.0f;
    }
  }
}
} // namespace

vtkPlumeVectorTexture3D::vtkPlumeVectorTexture3D() = default;
vtkPlumeVectorTexture3D::~vtkPlumeVectorTexture3D() = default;

void vtkPlumeVectorTexture3D::ConvertSlab(
  vtkDataArray* vectors, vtkDataArray* mask, vtkIdType begin, vtkIdType end, float* rgba)
{
  switch (vectors->GetDataType())
  {
    vtkTemplateMacro(
      CopyVectors(static_cast<const VTK_TT*>(vectors->GetVoidPointer(0)), begin, end, rgba));
    default:
      for (vtkIdType i = begin; i < end; ++i)
      {
        double v[3];
        vectors->GetTuple(i, v);
        float* t = rgba + 4 * (i - begin);
        for (int c = 0; c < 3; ++c)
        {
          t[c] = static_cast<float>(v[c]);
        }
        t[3] = 1.0f;
      }
  }
  if (mask)
  {
    const int comps = mask->GetNumberOfComponents();
    switch (mask->GetDataType())
    {
      vtkTemplateMacro(
        ApplyMask(static_cast<const VTK_TT*>(mask->GetVoidPointer(0)), begin, end, comps, rgba));
      default:
        for (vtkIdType i = begin; i < end; ++i)
        {
          if (mask->GetComponent(i, 0) == 0.0)
          {
            rgba[4 * (i - begin) + 3] = 0.0f;
          }
        }
    }
  }
  for (vtkIdType i = begin; i < end; ++i)
  {
    float* t = rgba + 4 * (i - begin);
    if (!std::isfinite(t[0]) || !std::isfinite(t[1]) || !std::isfinite(t[2]) || t[3] == 0.0f)
    {
      t[0] = t[1] = t[2] = t[3] = 0.0f;
    }
  }
}

bool vtkPlumeVectorTexture3D::Update(
  vtkOpenGLRenderWindow* window, vtkImageData* image, vtkDataArray* vectors, vtkDataArray* mask)
{
  this->LastError.clear();
  if (!window || !image || !vectors)
  {
    this->LastError = "no window, image or vector array";
    return false;
  }
  const vtkIdType n = image->GetNumberOfPoints();
  if (vectors->GetNumberOfComponents() != 3 || vectors->GetNumberOfTuples() != n ||
    (mask && mask->GetNumberOfTuples() != n))
  {
    std::ostringstream msg;
    msg << "vector array '" << (vectors->GetName() ? vectors->GetName() : "(unnamed)") << "' has "
        << vectors->GetNumberOfComponents() << " components and " << vectors->GetNumberOfTuples()
        << " tuples for " << n << " points; 3 components and one tuple per point are required";
    if (mask && mask->GetNumberOfTuples() != n)
    {
      msg << " (the mask has " << mask->GetNumberOfTuples() << " tuples)";
    }
    this->LastError = msg.str();
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  if (!this->BeginUpdate(window, dims))
  {
    return false;
  }

  Signature sig;
  sig.Image = image;
  sig.Array = vectors;
  sig.Mask = mask;
  sig.Time = std::max({ image->GetMTime(), vectors->GetMTime(), mask ? mask->GetMTime() : 0 });

  // the producer's GPU copy (same context, array unchanged, our layout), never with a mask
  vtkTextureObject* handed = mask ? nullptr : vtkPlumeTextureHandOver::Find(vectors, window, dims, 4);
  this->HandedOver = handed != nullptr;
  if (handed)
  {
    this->BindHandOver(handed, window, sig);
    return true;
  }
  this->Bound = this->Texture;
  if (sig == this->Uploaded && this->Texture->GetHandle())
  {
    return true;
  }
  if (!this->Upload(window, vectors, mask, dims))
  {
    std::ostringstream msg;
    msg << "could not create the " << dims[0] << "x" << dims[1] << "x" << dims[2]
        << " RGBA32F vector texture";
    this->LastError = msg.str();
    this->Uploaded = Signature();
    return false;
  }
  this->Uploaded = sig;
  ++this->UploadCount;
  return true;
}

bool vtkPlumeVectorTexture3D::Upload(
  vtkOpenGLRenderWindow* window, vtkDataArray* vectors, vtkDataArray* mask, const int dims[3])
{
  vtkTextureObject* texture = this->Texture;
  texture->SetContext(window);
  SetSampling(texture);
  texture->SetInternalFormat(GL_RGBA32F);
  if (!texture->Create3DFromRaw(dims[0], dims[1], dims[2], 4, VTK_FLOAT, nullptr))
  {
    return false;
  }
  const vtkIdType slice = vtkIdType(dims[0]) * dims[1];
  const int slabSlices = static_cast<int>(std::max<vtkIdType>(1, SlabPoints / slice));
  std::vector<float> slab(4 * static_cast<size_t>(slice) * std::min(slabSlices, dims[2]));
  texture->Activate();
  // rows are 16·dims[0] bytes: any GL_UNPACK_ALIGNMENT fits
  for (int z = 0; z < dims[2]; z += slabSlices)
  {
    const int nz = std::min(slabSlices, dims[2] - z);
    ConvertSlab(vectors, mask, z * slice, (z + nz) * slice, slab.data());
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, z, dims[0], dims[1], nz, GL_RGBA, GL_FLOAT, slab.data());
  }
  texture->Deactivate();
  return true;
}

void vtkPlumeVectorTexture3D::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
