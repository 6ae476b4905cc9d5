/**
 * @class   vtkPlumeVectorTexture3D
 * @brief   a 3-component point array of a vtkImageData as a 3D RGBA32F texture, or the producer's GPU copy of it
 *
 * The vector companion of vtkPlumeScalarTexture3D: texel (i, j, k) holds the
 * vector at grid node (i, j, k) in raw data units (xyz) and a validity weight
 * (a = 1 valid, 0 invalid), linear filtering, clamp-to-edge wrapping; the
 * texture coordinate of index-space point p is (p + 0.5) / dims. This is the
 * layout vtkPlumeTextureHandOver documents for vectors, so a texture handed
 * over by the filter that computed the array (vtkPlumeGaussianSplatter's GPU
 * backend) is bound as it is instead of converting and uploading the array.
 *
 * Raw values rather than a normalised range: a velocity is integrated, not
 * looked up in a table, and float32 keeps 24 bits relative to each vector's
 * own size (a normalised scalar range is what loses precision far from 0).
 *
 * Sanitising (ConvertSlab; non-finite values never reach the GPU): a node
 * whose vector has a NaN or infinite component, or whose mask value is 0,
 * becomes (0, 0, 0, 0). A handed-over texture is used only without a mask
 * (the producer's texture has no mask channel) and when its size, component
 * count and type match.
 *
 * Staleness: Update() uploads only when the image, the vector or mask array or
 * their MTimes changed, or after ReleaseGraphicsResources (or a change of
 * window, which releases the old window's texture first). The array is
 * converted in slabs of whole z-slices, so a full sanitised copy never exists
 * on the CPU. Grids larger than GL_MAX_3D_TEXTURE_SIZE along an axis are
 * refused with an error naming the size (never silently cropped).
 *
 * @code
 *   if (!this->Velocity->Update(renWin, image, vectors, mask)) { error(this->Velocity->GetLastError()); }
 *   this->Velocity->GetTextureObject()->Activate();
 * @endcode
 */
#ifndef vtkPlumeVectorTexture3D_h
#define vtkPlumeVectorTexture3D_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkPlumeFieldTexture3D.h"

class PLUMERENDERINGCORE_EXPORT vtkPlumeVectorTexture3D : public vtkPlumeFieldTexture3D
{
public:
  static vtkPlumeVectorTexture3D* New();
  vtkTypeMacro(vtkPlumeVectorTexture3D, vtkPlumeFieldTexture3D);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Make the texture hold `vectors` (3 components, one tuple per point of
   * `image`) in `window`: the producer's handed-over copy if there is a
   * usable one, else an upload if the data changed. `mask` (optional): one
   * tuple per point, 0 = node outside the data. Returns false (and sets
   * GetLastError()) on bad input or a GL failure.
   */
  bool Update(vtkOpenGLRenderWindow* window, vtkImageData* image, vtkDataArray* vectors,
    vtkDataArray* mask = nullptr);

  /**
   * The texture's layout, for CPU code that must see the same values (range
   * statistics): points [begin, end) of `vectors` (3 components) as RGBA
   * floats (v, valid) into rgba[0 .. 4 (end - begin)), non-finite or masked
   * nodes as (0, 0, 0, 0). `mask` may be null.
   */
  static void ConvertSlab(
    vtkDataArray* vectors, vtkDataArray* mask, vtkIdType begin, vtkIdType end, float* rgba);

  /** Points converted per slab (the CPU memory of an upload is 16 bytes times this, at least one z-slice). */
  static constexpr vtkIdType SlabPoints = 1 << 16;

protected:
  vtkPlumeVectorTexture3D();
  ~vtkPlumeVectorTexture3D() override;

  bool Upload(vtkOpenGLRenderWindow* window, vtkDataArray* vectors, vtkDataArray* mask, const int dims[3]);

private:
  vtkPlumeVectorTexture3D(const vtkPlumeVectorTexture3D&) = delete;
  void operator=(const vtkPlumeVectorTexture3D&) = delete;
};

#endif
