/**
 * @class   vtkPlumeScalarTexture3D
 * @brief   one scalar field of a vtkImageData as a normalised 3D float texture (shared by Plume's renderers)
 *
 * Uploads one point-data array of a vtkImageData (one component, a chosen
 * component, or the magnitude of a vector) as a single-channel GL_R32F 3D
 * texture with linear filtering and clamp-to-edge wrapping, so that texel
 * (i, j, k) holds the value at grid node (i, j, k) and the texture coordinate
 * of index-space point p is (p + 0.5) / dims.
 *
 * Values are stored normalised, u = (v - range[0]) / (range[1] - range[0]),
 * where range is the finite range of the array (GetScalarRange(); computed in
 * double, so huge or far-from-zero values keep their float precision). A
 * constant field stores u = 0 everywhere.
 *
 * Sanitising (non-finite values never reach the GPU):
 *  - NaN  -> range[0] (u = 0: "empty" for transfer functions that start at 0)
 *  - +Inf -> range[1] (u = 1)
 *  - -Inf -> range[0] (u = 0)
 * An array with no finite value at all gives range (0, 0) and u = 0.
 *
 * Valid-point mask (optional, e.g. vtkResampleToImage's vtkValidPointMask):
 * nodes whose mask is 0 lie outside the data and are left out of the range.
 * If there are any (GetMasked()), the texture has two channels, GL_RG32F:
 * r = u w and g = w, w = 1 at valid nodes and 0 outside. Linear filtering
 * then gives, at any point, the interpolation weight of valid nodes (g) and
 * r / g = the value interpolated over the valid nodes only, so a shader can
 * fade the data out over the last voxel (weight g) without ever blending in
 * the values of nodes outside it. Block ranges cover valid nodes only (a
 * block with none has min 1 > max 0).
 *
 * Re-upload happens only when the image, the array, the component choice or
 * their MTimes change, or after ReleaseGraphicsResources; GetUploadCount()
 * lets tests check that. Grids larger than GL_MAX_3D_TEXTURE_SIZE along an
 * axis are refused with an error naming the size (never silently cropped).
 *
 * Typical use inside a mapper's Render():
 * @code
 *   if (!this->Texture->Update(renWin, image, array, -1)) return; // -1: magnitude / single component
 *   this->Texture->GetTextureObject()->Activate();
 *   program->SetUniformi("Volume", this->Texture->GetTextureObject()->GetTextureUnit());
 * @endcode
 */
#ifndef vtkPlumeScalarTexture3D_h
#define vtkPlumeScalarTexture3D_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For members

#include <string> // For std::string
#include <vector> // For std::vector

class vtkDataArray;
class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class PLUMERENDERINGCORE_EXPORT vtkPlumeScalarTexture3D : public vtkObject
{
public:
  static vtkPlumeScalarTexture3D* New();
  vtkTypeMacro(vtkPlumeScalarTexture3D, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Make the texture hold `array` (a point array of `image`) in the context of
   * `window`. `component`: -1 (default) = the only component, or the magnitude
   * when the array has several; k >= 0 = component k. Uploads only if needed.
   * Returns false (and sets GetLastError()) on bad input or a GL failure.
   * `mask` (optional): one-component point array, 0 = node outside the data
   * (see the class documentation).
   */
  bool Update(vtkOpenGLRenderWindow* window, vtkImageData* image, vtkDataArray* array, int component = -1,
    vtkDataArray* mask = nullptr);

  /** True if the last upload had masked nodes: a two-channel (u w, w) texture. */
  bool GetMasked() const { return this->Masked; }

  /** The GL texture (valid after a successful Update). */
  vtkTextureObject* GetTextureObject();

  /** Finite range of the uploaded values in data units: u = 0 at [0], u = 1 at [1]. */
  const double* GetScalarRange() const { return this->ScalarRange; }

  /** Grid dimensions of the uploaded texture. */
  const int* GetDimensions() const { return this->Dimensions; }

  ///@{
  /**
   * Block size (in voxels) of the min/max summary computed at each upload, for
   * empty-space skipping. Block (I, J, K) covers the nodes I·B .. (I+1)·B along
   * x (likewise y, z; clamped to the grid), i.e. every node a trilinear sample
   * inside the block can touch. 0 = no summary. Default 8; takes effect at the next upload.
   */
  vtkSetClampMacro(BlockSize, int, 0, 1024);
  vtkGetMacro(BlockSize, int);
  ///@}

  ///@{
  /**
   * Also store central differences (GL_RGBA32F: r = u, gba = u[i+1] - u[i-1]
   * along x, y, z, the neighbours clamped to the grid as the texture's
   * clamp-to-edge does). Because trilinear interpolation is linear, the
   * filtered gba at any point equals the central difference (one voxel each
   * way) of the filtered u there, so a shader gets the gradient in one
   * look-up instead of six. Ignored for masked uploads (see GetMasked; their
   * values are normalised per sample, r / g). 4x the memory. Default off;
   * a change re-uploads.
   */
  vtkSetMacro(Gradients, bool);
  vtkGetMacro(Gradients, bool);
  ///@}

  /** True if the last upload stored gradients (RGBA32F: u, du/dx, du/dy, du/dz, central differences). */
  bool GetHasGradients() const { return this->HasGradients; }

  /** Number of blocks along each axis (ceil((dims - 1) / B), at least 1). */
  const int* GetBlockDimensions() const { return this->BlockDimensions; }

  /** Per block, the min and max of the normalised values u (2 floats per block, x fastest). */
  const std::vector<float>& GetBlockRanges() const { return this->BlockRanges; }

  /** Number of values that were NaN or infinite in the last upload. */
  vtkGetMacro(NonFiniteCount, long long);

  /** Number of uploads so far (tests check that re-renders do not upload). */
  vtkGetMacro(UploadCount, int);

  /** Description of the last failure, "" after a successful Update. */
  const std::string& GetLastError() const { return this->LastError; }

  /** Release the GL texture (the next Update uploads again). */
  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkPlumeScalarTexture3D();
  ~vtkPlumeScalarTexture3D() override;

  vtkSmartPointer<vtkTextureObject> Texture;
  double ScalarRange[2] = { 0, 0 };
  int Dimensions[3] = { 0, 0, 0 };
  long long NonFiniteCount = 0;
  int UploadCount = 0;
  int BlockSize = 8;
  bool Gradients = false;
  bool HasGradients = false;
  int BlockDimensions[3] = { 0, 0, 0 };
  std::vector<float> BlockRanges;
  std::string LastError;

  // what the texture was built from
  vtkImageData* UploadedImage = nullptr;
  vtkDataArray* UploadedArray = nullptr;
  int UploadedComponent = -2;
  vtkMTimeType UploadedTime = 0;
  vtkDataArray* UploadedMask = nullptr;
  bool Masked = false;
  bool UploadedGradients = false;

private:
  vtkPlumeScalarTexture3D(const vtkPlumeScalarTexture3D&) = delete;
  void operator=(const vtkPlumeScalarTexture3D&) = delete;
};

#endif
