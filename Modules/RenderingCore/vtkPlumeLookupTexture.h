/**
 * @class   vtkPlumeLookupTexture
 * @brief   a 1D RGBA float table over a value range, as a texture that knows when it is stale
 *
 * Colour maps and transfer functions reach Plume's shaders as a table of
 * `size` RGBA entries sampled evenly over a value range (linear filtering,
 * clamped). Update() tabulates and uploads only when the source object, its
 * modification time, the range, the size or the window changed since the
 * last upload (camera moves and re-renders upload nothing); the caller says
 * how an entry is computed. Model: vtkOpenGLVolumeLookupTable's
 * NeedsUpdate / InternalUpdate.
 */
#ifndef vtkPlumeLookupTexture_h
#define vtkPlumeLookupTexture_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For Texture
#include "vtkWeakPointer.h"  // For Window

#include <functional> // For std::function
#include <vector>     // For std::vector

class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class PLUMERENDERINGCORE_EXPORT vtkPlumeLookupTexture : public vtkObject
{
public:
  static vtkPlumeLookupTexture* New();
  vtkTypeMacro(vtkPlumeLookupTexture, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

#ifndef __VTK_WRAP__
  /** Computes the RGBA entry of `value`. */
  using Entry = std::function<void(double value, float rgba[4])>;

  /**
   * Brings the texture up to date: if `source` (any object whose state the
   * entries depend on), `sourceTime`, `range`, `size` or `window` differ from
   * the last upload, tabulates `entry` at size points from range[0] to
   * range[1] and uploads. Returns false if the texture cannot be created.
   */
  bool Update(vtkOpenGLRenderWindow* window, const void* source, vtkMTimeType sourceTime,
    const double range[2], int size, const Entry& entry);
#endif

  /** The texture (valid after a successful Update). */
  vtkTextureObject* GetTextureObject();
  /** The table of the last upload, size x RGBA. */
  const std::vector<float>& GetTable() const { return this->Table; }
  /** Uploads so far (tests: re-renders must not add any). */
  vtkGetMacro(UploadCount, int);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkPlumeLookupTexture();
  ~vtkPlumeLookupTexture() override;

  vtkSmartPointer<vtkTextureObject> Texture;
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  const void* Source = nullptr;
  vtkMTimeType SourceTime = 0;
  double Range[2] = { 0, 0 };
  std::vector<float> Table;
  int UploadCount = 0;

private:
  vtkPlumeLookupTexture(const vtkPlumeLookupTexture&) = delete;
  void operator=(const vtkPlumeLookupTexture&) = delete;
};

#endif
