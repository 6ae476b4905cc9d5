/**
 * @class   vtkPlumeTextureHandOver
 * @brief   a GPU copy of a data array, attached to the array, that Plume's mappers use instead of uploading it
 *
 * A filter that computes an array on the GPU (vtkPlumeGaussianSplatter's GPU
 * backend) already holds the result in a texture. Attach() records that
 * texture in the array's information (key TEXTURE()); the array travels
 * through the pipeline as usual (shallow copies share it), and a Plume mapper
 * rendering in the same OpenGL context calls Find() and binds the texture
 * instead of converting and uploading the array.
 *
 * Find() returns the texture only if
 *  - it lives in the caller's render window (textures are per context),
 *  - the array has not been modified since Attach() (its MTime is unchanged;
 *    a deep copy, which copies the information, has a new MTime), and
 *  - the producer has not revoked it (Revoke(): it is overwriting the texture),
 * else nullptr: the caller uploads the array as it would without a hand-over.
 * The CPU array stays complete, so every other consumer (writers, VTK
 * filters, ParaView) sees ordinary data.
 *
 * Layout contract (checked by the consumer): a 3D texture whose texel
 * (i, j, k) is grid node (i, j, k); for vectors, RGBA32F with xyz = the vector
 * and a = 1 (valid), the layout vtkPlumeVelocityGlyphMapper uploads itself;
 * for scalars (one-component arrays), one float channel holding the raw
 * values (vtkPlumeScalarTexture3D, used by vtkPlumeVolumeMapper).
 */
#ifndef vtkPlumeTextureHandOver_h
#define vtkPlumeTextureHandOver_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h"  // For members
#include "vtkWeakPointer.h"   // For members

class vtkDataArray;
class vtkInformationObjectBaseKey;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

class PLUMERENDERINGCORE_EXPORT vtkPlumeTextureHandOver : public vtkObject
{
public:
  static vtkPlumeTextureHandOver* New();
  vtkTypeMacro(vtkPlumeTextureHandOver, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The key, in a vtkDataArray's information, holding the hand-over. */
  static vtkInformationObjectBaseKey* TEXTURE();

  /**
   * Attach `texture` (created in `window`) to `array` as its GPU copy; the
   * array keeps the texture alive. Call after the array's values are final.
   * Returns the hand-over (null if `array`, `texture` or `window` is null),
   * which the producer revokes before it writes into the texture again.
   */
  static vtkPlumeTextureHandOver* Attach(
    vtkDataArray* array, vtkTextureObject* texture, vtkOpenGLRenderWindow* window);

  /**
   * From now on Find() ignores this hand-over: the producer is about to
   * overwrite the texture (it reuses one texture across executions), so
   * arrays still holding it fall back to an upload of their own values.
   */
  void Revoke();

  /** The GPU copy of `array` usable in `window`, or nullptr (see the class documentation). */
  static vtkTextureObject* Find(vtkDataArray* array, vtkOpenGLRenderWindow* window);

  /**
   * Find(array, window) if the texture also has the layout the consumer
   * needs: dims[0] x dims[1] x dims[2] texels of `components` float channels;
   * else nullptr.
   */
  static vtkTextureObject* Find(
    vtkDataArray* array, vtkOpenGLRenderWindow* window, const int dims[3], int components);

protected:
  vtkPlumeTextureHandOver();
  ~vtkPlumeTextureHandOver() override;

  vtkSmartPointer<vtkTextureObject> Texture;
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  vtkMTimeType ArrayTime = 0; // the array's MTime when attached

private:
  vtkPlumeTextureHandOver(const vtkPlumeTextureHandOver&) = delete;
  void operator=(const vtkPlumeTextureHandOver&) = delete;
};

#endif
