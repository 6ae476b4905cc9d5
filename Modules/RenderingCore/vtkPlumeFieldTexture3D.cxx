#include "vtkPlumeFieldTexture3D.h"

#include "vtkPlumeTexture3DSize.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

vtkPlumeFieldTexture3D::vtkPlumeFieldTexture3D()
  : Texture(vtkSmartPointer<vtkTextureObject>::New())
{
}

vtkPlumeFieldTexture3D::~vtkPlumeFieldTexture3D() = default;

vtkTextureObject* vtkPlumeFieldTexture3D::GetTextureObject()
{
  return this->Bound ? this->Bound : this->Texture.Get();
}

void vtkPlumeFieldTexture3D::SetSampling(vtkTextureObject* texture)
{
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetWrapR(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
}

bool vtkPlumeFieldTexture3D::BeginUpdate(vtkOpenGLRenderWindow* window, const int dims[3])
{
  if (this->Window && this->Window != window)
  {
    this->ReleaseGraphicsResources(this->Window); // textures belong to one context
  }
  this->Window = window;
  this->LastError = plume::Check3DTextureSize(window, dims, this->Max3DTextureSize);
  return this->LastError.empty();
}

bool vtkPlumeFieldTexture3D::BindHandOver(
  vtkTextureObject* handed, vtkOpenGLRenderWindow* window, const Signature& sig)
{
  if (this->Texture->GetHandle())
  {
    this->Texture->ReleaseGraphicsResources(window); // not needed meanwhile
  }
  this->Uploaded = Signature();
  SetSampling(handed);
  this->Bound = handed;
  if (sig == this->Handed)
  {
    return false;
  }
  this->Handed = sig;
  ++this->HandOverCount;
  return true;
}

void vtkPlumeFieldTexture3D::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Texture->ReleaseGraphicsResources(window);
  this->Bound = nullptr;
  this->HandedOver = false;
  this->Uploaded = Signature();
  this->Max3DTextureSize = 0;
  this->Window = nullptr;
}

void vtkPlumeFieldTexture3D::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HandedOver: " << this->HandedOver << "\n";
  os << indent << "UploadCount: " << this->UploadCount << "\n";
  os << indent << "HandOverCount: " << this->HandOverCount << "\n";
}
