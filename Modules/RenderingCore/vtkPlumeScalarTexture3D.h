/**
 * @class   vtkPlumeScalarTexture3D
 * @brief   one scalar field of a vtkImageData as a 3D float texture of raw values, or the producer's GPU copy of it
 *
 * Holds one point-data array of a vtkImageData (one component, a chosen
 * component, or the magnitude of a vector) as a single-channel GL_R32F 3D
 * texture with linear filtering and clamp-to-edge wrapping, so that texel
 * (i, j, k) holds the value at grid node (i, j, k) and the texture coordinate
 * of index-space point p is (p + 0.5) / dims.
 *
 * Raw values, mapped by the shader: texel t = v - GetValueShift(), in data
 * units (data whose span float cannot resolve, beyond 1e30 or below 1e-30,
 * are stored as (v - shift) * GetValueScale() with scale = 1 / span instead). GetScaleBias(range) gives the uniform pair (scale, bias) with
 * u = t * scale + bias = (v - range[0]) / (range[1] - range[0]), so a
 * transfer function over any range reads the same texture: changing the
 * colour or opacity range changes two uniforms and uploads nothing. The shift
 * is the data's finite minimum (in double) for our own uploads, so data far
 * from zero (a temperature of 300 ± 0.01) keep float's 24 bits relative to
 * their span; it is 0 for a handed-over texture, which holds the values as
 * they are. A degenerate range (range[0] == range[1]) gives scale = bias = 0
 * (u = 0 everywhere, as a constant field).
 *
 * Sanitising (non-finite values never reach the GPU):
 *  - NaN  -> the finite minimum (u = 0 over the data range: "empty" for
 *            transfer functions that start at 0)
 *  - +Inf -> the finite maximum, -Inf -> the finite minimum
 * An array with no finite value at all gives range (0, 0) and t = 0.
 *
 * Valid-point mask (optional, e.g. vtkResampleToImage's vtkValidPointMask):
 * nodes whose mask is 0 lie outside the data and are left out of the range.
 * If there are any (GetMasked()), the texture has two channels, GL_RG32F:
 * r = t w and g = w, w = 1 at valid nodes and 0 outside. Linear filtering
 * then gives, at any point, the interpolation weight of valid nodes (g) and
 * r / g = the value interpolated over the valid nodes only, so a shader can
 * fade the data out over the last voxel (weight g) without ever blending in
 * the values of nodes outside it. Block ranges cover valid nodes only.
 *
 * Hand-over (vtkPlumeTextureHandOver): when the producer of the array (e.g. a
 * GPU solver or splatter) attached its own copy, a single-channel float 3D
 * texture of the grid's size in the same window holding the raw values, that
 * texture is bound instead of an upload (GetHandedOver()). The range, the
 * block summary and the non-finite count are still computed from the CPU
 * array (which the hand-over contract keeps complete). The copy is ignored,
 * and the array uploaded, when it is stale (the array was modified or the
 * producer revoked it), lives in another window, has another size, channel
 * count or type, or cannot be used as it is: a mask or gradients are asked
 * for, a component or the magnitude of a multi-component array is asked for,
 * or the array has non-finite values (the copy would hold them unsanitised).
 *
 * Staleness: Update() re-reads the array only when the image, the array, the
 * component, the mask, the gradient option or their MTimes changed, or after
 * ReleaseGraphicsResources (or a change of window, which releases the old
 * window's texture first); GetUploadCount() and GetHandOverCount() let tests
 * check that. Grids larger than GL_MAX_3D_TEXTURE_SIZE along an axis are
 * refused with an error naming the size (never silently cropped).
 *
 * Typical use inside a mapper:
 * @code
 *   if (!this->Texture->Update(renWin, image, array, -1)) return; // -1: magnitude / single component
 *   double sb[2];
 *   this->Texture->GetScaleBias(tableRange, sb);
 *   program->SetUniform2f("ValueScaleBias", ...);
 *   this->Texture->GetTextureObject()->Activate();
 *   program->SetUniformi("Volume", this->Texture->GetTextureObject()->GetTextureUnit());
 * @endcode
 */
#ifndef vtkPlumeScalarTexture3D_h
#define vtkPlumeScalarTexture3D_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkPlumeFieldTexture3D.h"

#include <vector> // For std::vector

class PLUMERENDERINGCORE_EXPORT vtkPlumeScalarTexture3D : public vtkPlumeFieldTexture3D
{
public:
  static vtkPlumeScalarTexture3D* New();
  vtkTypeMacro(vtkPlumeScalarTexture3D, vtkPlumeFieldTexture3D);
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

  /** Finite range of the values in data units (of the valid nodes with a mask). */
  const double* GetScalarRange() const { return this->ScalarRange; }

  /** The texel holds v - shift (data units): the finite minimum for our uploads, 0 for a hand-over. */
  double GetValueShift() const { return this->ValueShift; }

  /** ... times this: 1, or 1 / span for spans beyond 1e30 or below 1e-30 (see the class documentation). */
  double GetValueScale() const { return this->ValueScale; }

  /**
   * The shader's (scale, bias): u = t scale + bias maps `range` (data units)
   * to [0, 1] from texel values t. range[0] == range[1] (or a non-finite
   * result) gives (0, 0).
   */
  void GetScaleBias(const double range[2], double scaleBias[2]) const;

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
   * Also store central differences (GL_RGBA32F: r = t, gba = t[i+1] - t[i-1]
   * along x, y, z, the neighbours clamped to the grid as the texture's
   * clamp-to-edge does). Because trilinear interpolation is linear, the
   * filtered gba at any point equals the central difference (one voxel each
   * way) of the filtered t there, so a shader gets the gradient in one
   * look-up instead of six (times the scale of GetScaleBias for u). Ignored
   * for masked uploads (see GetMasked; their values are divided per sample,
   * r / g). 4x the memory. A hand-over is not used with gradients. Default
   * off; a change re-uploads.
   */
  vtkSetMacro(Gradients, bool);
  vtkGetMacro(Gradients, bool);
  ///@}

  /** True if the last upload stored gradients (RGBA32F: t and its central differences along x, y, z). */
  bool GetHasGradients() const { return this->HasGradients; }

  /** Number of blocks along each axis (ceil((dims - 1) / B), at least 1). */
  const int* GetBlockDimensions() const { return this->BlockDimensions; }

  /**
   * Per block, the min and max of the texel values t (2 floats per block, x
   * fastest; map them with GetScaleBias). A block with no valid node has
   * min > max (+FLT_MAX, -FLT_MAX).
   */
  const std::vector<float>& GetBlockRanges() const { return this->BlockRanges; }

  /** Number of values that were NaN or infinite in the last upload. */
  vtkGetMacro(NonFiniteCount, long long);

  /**
   * Number of distinct data versions seen (uploaded or handed over): what the
   * block summary and the range were computed from; consumers that derive
   * things from them (a mapper's empty-space texture) compare it.
   */
  vtkGetMacro(DataVersion, int);

  /** Release the GL texture (the next Update uploads again). */
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkPlumeScalarTexture3D();
  ~vtkPlumeScalarTexture3D() override;

  // reads the array: range, shift, block summary; fills `texels` (channels per node) unless null
  bool Analyse(vtkDataArray* array, int component, vtkDataArray* mask, const int dims[3],
    std::vector<float>* texels);

  int DataVersion = 0;
  double ValueShift = 0.0;
  double ValueScale = 1.0;
  double ScalarRange[2] = { 0, 0 };
  int Dimensions[3] = { 0, 0, 0 };
  long long NonFiniteCount = 0;
  int BlockSize = 8;
  bool Gradients = false;
  bool HasGradients = false;
  int BlockDimensions[3] = { 0, 0, 0 };
  std::vector<float> BlockRanges;
  Signature Analysed; // what ScalarRange, the block summary and Masked describe
  bool Masked = false;

private:
  vtkPlumeScalarTexture3D(const vtkPlumeScalarTexture3D&) = delete;
  void operator=(const vtkPlumeScalarTexture3D&) = delete;
};

#endif
