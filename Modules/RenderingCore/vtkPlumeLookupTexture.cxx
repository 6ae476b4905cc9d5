#include "vtkPlumeLookupTexture.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

vtkStandardNewMacro(vtkPlumeLookupTexture);

vtkPlumeLookupTexture::vtkPlumeLookupTexture()
  : Texture(vtkSmartPointer<vtkTextureObject>::New())
{
}

vtkPlumeLookupTexture::~vtkPlumeLookupTexture() = default;

vtkTextureObject* vtkPlumeLookupTexture::GetTextureObject()
{
  return this->Texture;
}

bool vtkPlumeLookupTexture::Update(vtkOpenGLRenderWindow* window, const void* source,
  vtkMTimeType sourceTime, const double range[2], int size, const Entry& entry)
{
  if (!window || size < 2)
  {
    return false;
  }
  if (window == this->Window && source == this->Source && sourceTime == this->SourceTime &&
    range[0] == this->Range[0] && range[1] == this->Range[1] &&
    static_cast<int>(this->Table.size()) == 4 * size && this->Texture->GetHandle())
  {
    return true; // up to date
  }
  this->Table.assign(4 * static_cast<size_t>(size), 0.0f);
  for (int i = 0; i < size; ++i)
  {
    entry(range[0] + (range[1] - range[0]) * i / (size - 1.0), &this->Table[4 * i]);
  }
  if (window != this->Window)
  {
    this->Texture->ReleaseGraphicsResources(this->Window);
  }
  this->Texture->SetContext(window);
  this->Texture->SetWrapS(vtkTextureObject::ClampToEdge);
  this->Texture->SetWrapT(vtkTextureObject::ClampToEdge);
  this->Texture->SetMinificationFilter(vtkTextureObject::Linear);
  this->Texture->SetMagnificationFilter(vtkTextureObject::Linear);
  if (!this->Texture->Create2DFromRaw(size, 1, 4, VTK_FLOAT, this->Table.data()))
  {
    this->Table.clear();
    return false;
  }
  this->Window = window;
  this->Source = source;
  this->SourceTime = sourceTime;
  this->Range[0] = range[0];
  this->Range[1] = range[1];
  ++this->UploadCount;
  return true;
}

void vtkPlumeLookupTexture::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Texture->ReleaseGraphicsResources(window);
  this->Table.clear();
  this->Window = nullptr;
  this->Source = nullptr;
}

void vtkPlumeLookupTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->Table.size() / 4 << "\n";
  os << indent << "Range: " << this->Range[0] << " " << this->Range[1] << "\n";
  os << indent << "UploadCount: " << this->UploadCount << "\n";
}
