#include "vtkPlumeTextureHandOver.h"

#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

vtkStandardNewMacro(vtkPlumeTextureHandOver);
vtkInformationKeyMacro(vtkPlumeTextureHandOver, TEXTURE, ObjectBase);

vtkPlumeTextureHandOver::vtkPlumeTextureHandOver() = default;
vtkPlumeTextureHandOver::~vtkPlumeTextureHandOver() = default;

vtkPlumeTextureHandOver* vtkPlumeTextureHandOver::Attach(
  vtkDataArray* array, vtkTextureObject* texture, vtkOpenGLRenderWindow* window)
{
  if (!array)
  {
    return nullptr;
  }
  if (!texture || !window)
  {
    if (array->HasInformation())
    {
      array->GetInformation()->Remove(TEXTURE());
    }
    return nullptr;
  }
  vtkNew<vtkPlumeTextureHandOver> handOver;
  handOver->Texture = texture;
  handOver->Window = window;
  array->GetInformation()->Set(TEXTURE(), handOver);
  // after the Set: whatever it does to the array's MTime is part of "unchanged"
  handOver->ArrayTime = array->GetMTime();
  return handOver; // the array's information holds it
}

void vtkPlumeTextureHandOver::Revoke()
{
  this->Texture = nullptr;
}

vtkTextureObject* vtkPlumeTextureHandOver::Find(vtkDataArray* array, vtkOpenGLRenderWindow* window)
{
  if (!array || !window || !array->HasInformation())
  {
    return nullptr;
  }
  auto* handOver = vtkPlumeTextureHandOver::SafeDownCast(array->GetInformation()->Get(TEXTURE()));
  if (!handOver || handOver->Window != window || handOver->ArrayTime != array->GetMTime() ||
    !handOver->Texture || !handOver->Texture->GetHandle())
  {
    return nullptr;
  }
  return handOver->Texture;
}

vtkTextureObject* vtkPlumeTextureHandOver::Find(
  vtkDataArray* array, vtkOpenGLRenderWindow* window, const int dims[3], int components)
{
  vtkTextureObject* texture = vtkPlumeTextureHandOver::Find(array, window);
  if (!texture || texture->GetWidth() != static_cast<unsigned int>(dims[0]) ||
    texture->GetHeight() != static_cast<unsigned int>(dims[1]) ||
    texture->GetDepth() != static_cast<unsigned int>(dims[2]) || texture->GetComponents() != components ||
    texture->GetVTKDataType() != VTK_FLOAT)
  {
    return nullptr;
  }
  return texture;
}

void vtkPlumeTextureHandOver::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Texture: " << this->Texture.Get() << "\n";
  os << indent << "Window: " << this->Window.Get() << "\n";
  os << indent << "ArrayTime: " << this->ArrayTime << "\n";
}
