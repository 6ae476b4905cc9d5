/**
 * @class   vtkPlumeFieldTexture3D
 * @brief   what vtkPlumeScalarTexture3D and vtkPlumeVectorTexture3D share: one 3D texture of a field, or the producer's GPU copy
 *
 * A field texture is either its own texture (an upload of the array) or a
 * texture a producer handed over (vtkPlumeTextureHandOver), bound as it is.
 * This base holds both, the window they live in, the counters tests read and
 * the steps every field texture takes the same way:
 *  - BeginUpdate(): a change of window releases the old window's texture
 *    first (textures belong to one context), and a grid larger than
 *    GL_MAX_3D_TEXTURE_SIZE is refused with one message naming the size;
 *  - BindHandOver(): the producer's texture replaces ours (whose GL storage
 *    is released meanwhile), sampled like ours, and each new data version
 *    bound this way is counted (GetHandOverCount());
 *  - SetSampling(): linear filtering, clamp-to-edge wrapping, so the texture
 *    coordinate of index-space point p is (p + 0.5) / dims.
 * Subclasses decide what to upload and when (Update()).
 */
#ifndef vtkPlumeFieldTexture3D_h
#define vtkPlumeFieldTexture3D_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For members
#include "vtkWeakPointer.h"  // For members

#include <string> // For std::string

class vtkDataArray;
class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class PLUMERENDERINGCORE_EXPORT vtkPlumeFieldTexture3D : public vtkObject
{
public:
  vtkTypeMacro(vtkPlumeFieldTexture3D, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The texture to bind after a successful Update: the handed-over one or our own. */
  vtkTextureObject* GetTextureObject();

  /** True if the last Update bound the producer's texture instead of ours. */
  bool GetHandedOver() const { return this->HandedOver; }

  /** Number of uploads so far (tests check that re-renders do not upload). */
  vtkGetMacro(UploadCount, int);

  /** Number of distinct data versions that were bound from a hand-over instead of uploaded. */
  vtkGetMacro(HandOverCount, int);

  /** Description of the last failure, "" after a successful Update. */
  const std::string& GetLastError() const { return this->LastError; }

  /** Release the GL texture (the next Update uploads again). */
  virtual void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkPlumeFieldTexture3D();
  ~vtkPlumeFieldTexture3D() override;

  // what the texture (or the last hand-over) holds; the vector texture leaves
  // Component and Gradients at their defaults
  struct Signature
  {
    vtkImageData* Image = nullptr;
    vtkDataArray* Array = nullptr;
    vtkDataArray* Mask = nullptr;
    int Component = -2;
    bool Gradients = false;
    vtkMTimeType Time = 0;
    bool operator==(const Signature& o) const
    {
      return this->Image == o.Image && this->Array == o.Array && this->Mask == o.Mask &&
        this->Component == o.Component && this->Gradients == o.Gradients && this->Time == o.Time;
    }
  };

  /**
   * Make `window` ours (a different one releases the old window's texture
   * first) and check a dims[0] x dims[1] x dims[2] texture fits it; false
   * with LastError set if it does not.
   */
  bool BeginUpdate(vtkOpenGLRenderWindow* window, const int dims[3]);

  /**
   * Bind the producer's `handed` texture instead of ours, for data `sig`; our
   * own texture's GL storage is released meanwhile. Returns true (and counts
   * it in HandOverCount) if `sig` is a data version not bound before.
   */
  bool BindHandOver(vtkTextureObject* handed, vtkOpenGLRenderWindow* window, const Signature& sig);

  /** Linear filtering, clamp-to-edge wrapping along s, t and r. */
  static void SetSampling(vtkTextureObject* texture);

  vtkSmartPointer<vtkTextureObject> Texture;
  vtkTextureObject* Bound = nullptr; // Texture or the handed-over one
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  int Max3DTextureSize = 0;
  bool HandedOver = false;
  int UploadCount = 0;
  int HandOverCount = 0;
  std::string LastError;
  Signature Uploaded;
  Signature Handed;

private:
  vtkPlumeFieldTexture3D(const vtkPlumeFieldTexture3D&) = delete;
  void operator=(const vtkPlumeFieldTexture3D&) = delete;
};

#endif
