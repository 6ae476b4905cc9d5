#include "vtkPlumePingPongTexture3D.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

#include "vtk_glew.h"

#include <string>

vtkStandardNewMacro(vtkPlumePingPongTexture3D);

vtkPlumePingPongTexture3D::vtkPlumePingPongTexture3D() = default;

vtkTextureObject* vtkPlumePingPongTexture3D::GetFront()
{
  return this->Textures[this->FrontIndex];
}

vtkTextureObject* vtkPlumePingPongTexture3D::GetBack()
{
  return this->Textures[1 - this->FrontIndex];
}

vtkPlumePingPongTexture3D::~vtkPlumePingPongTexture3D()
{
  this->ReleaseGraphicsResources(this->Window);
}

bool vtkPlumePingPongTexture3D::Allocate(vtkOpenGLRenderWindow* window, const int dims[3], int components)
{
  this->LastError.clear();
  if (!window || (components != 1 && components != 4) || dims[0] < 1 || dims[1] < 1 || dims[2] < 1)
  {
    this->LastError = "ping-pong texture: needs a window, 1 or 4 channels and positive sizes (got " +
      std::to_string(components) + " channels, " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) +
      "x" + std::to_string(dims[2]) + ")";
    return false;
  }
  if (window == this->Window && this->Textures[0] && this->Textures[0]->GetHandle() &&
    this->Components == components && this->Dimensions[0] == dims[0] && this->Dimensions[1] == dims[1] &&
    this->Dimensions[2] == dims[2])
  {
    return true;
  }
  this->ReleaseGraphicsResources(this->Window);
  for (auto& texture : this->Textures)
  {
    texture = vtkSmartPointer<vtkTextureObject>::New();
    texture->SetContext(window);
    texture->SetMinificationFilter(vtkTextureObject::Nearest);
    texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    texture->SetWrapS(vtkTextureObject::ClampToEdge);
    texture->SetWrapT(vtkTextureObject::ClampToEdge);
    texture->SetWrapR(vtkTextureObject::ClampToEdge);
    if (!texture->Create3DFromRaw(dims[0], dims[1], dims[2], components, VTK_FLOAT, nullptr))
    {
      this->LastError = "ping-pong texture: could not create a " + std::to_string(dims[0]) + "x" +
        std::to_string(dims[1]) + "x" + std::to_string(dims[2]) + " float texture of " +
        std::to_string(components) + " channels";
      this->ReleaseGraphicsResources(window);
      return false;
    }
  }
  this->Window = window;
  std::copy(dims, dims + 3, this->Dimensions);
  this->Components = components;
  this->FrontIndex = 0;
  this->Modified();
  return true;
}

bool vtkPlumePingPongTexture3D::Upload(const float* values)
{
  vtkTextureObject* front = this->GetFront();
  if (!front || !front->GetHandle())
  {
    this->LastError = "ping-pong texture: upload before Allocate";
    return false;
  }
  front->Activate();
  // float rows are 4·n bytes, so VTK's GL_UNPACK_ALIGNMENT of 1 fits; setting 4 here
  // left it changed for later byte uploads (the volume's occupancy rows: ASan overflow)
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, this->Dimensions[0], this->Dimensions[1], this->Dimensions[2],
    this->Components == 4 ? GL_RGBA : GL_RED, GL_FLOAT, values);
  front->Deactivate();
  return true;
}

bool vtkPlumePingPongTexture3D::Download(float* values)
{
  vtkTextureObject* front = this->GetFront();
  if (!front || !front->GetHandle())
  {
    this->LastError = "ping-pong texture: download before Allocate";
    return false;
  }
  front->Activate();
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTexImage(GL_TEXTURE_3D, 0, this->Components == 4 ? GL_RGBA : GL_RED, GL_FLOAT, values);
  front->Deactivate();
  return true;
}

void vtkPlumePingPongTexture3D::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto& texture : this->Textures)
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(window);
      texture = nullptr;
    }
  }
  this->Dimensions[0] = this->Dimensions[1] = this->Dimensions[2] = 0;
  this->Components = 0;
  this->Window = nullptr;
}

void vtkPlumePingPongTexture3D::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Dimensions: " << this->Dimensions[0] << " " << this->Dimensions[1] << " "
     << this->Dimensions[2] << "\n";
  os << indent << "Components: " << this->Components << "\n";
  os << indent << "FrontIndex: " << this->FrontIndex << "\n";
}
