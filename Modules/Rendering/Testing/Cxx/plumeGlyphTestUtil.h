// Helpers for the Plume::Rendering tests: offscreen window, float read-back,
// image metrics, GL error check, and projection in double precision.
//
// These mirror Testing/Support/plumeTestSupport.h (PlumeTestSupport) so these
// tests do not depend on the dataset reader being built; switch to that target
// once it is stable.
#ifndef plumeGlyphTestUtil_h
#define plumeGlyphTestUtil_h

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPNGWriter.h"
#include "vtkWindowToImageFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace plumetest
{
inline vtkSmartPointer<vtkRenderWindow> MakeWindow(int width, int height)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  return window;
}

struct FloatImage
{
  int Width = 0;
  int Height = 0;
  std::vector<float> RGBA;
  std::vector<float> Depth;
  const float* Pixel(int x, int y) const
  {
    return &this->RGBA[4 * (static_cast<size_t>(y) * this->Width + x)];
  }
};

inline FloatImage ReadBack(vtkRenderWindow* window, bool render = true)
{
  if (render)
  {
    window->Render();
  }
  FloatImage image;
  const int* size = window->GetSize();
  image.Width = size[0];
  image.Height = size[1];
  vtkNew<vtkFloatArray> rgba;
  window->GetRGBAPixelData(0, 0, image.Width - 1, image.Height - 1, 0, rgba, 0);
  image.RGBA.assign(
    rgba->GetPointer(0), rgba->GetPointer(0) + 4 * static_cast<size_t>(image.Width) * image.Height);
  image.Depth.resize(static_cast<size_t>(image.Width) * image.Height);
  window->GetZbufferData(0, 0, image.Width - 1, image.Height - 1, image.Depth.data());
  return image;
}

inline bool HasNonFinite(const FloatImage& image)
{
  for (float v : image.RGBA)
  {
    if (!std::isfinite(v))
    {
      return true;
    }
  }
  for (float v : image.Depth)
  {
    if (!std::isfinite(v))
    {
      return true;
    }
  }
  return false;
}

inline bool IsForeground(const FloatImage& image, int x, int y, const double bg[3], double tol)
{
  const float* p = image.Pixel(x, y);
  return std::fabs(p[0] - bg[0]) > tol || std::fabs(p[1] - bg[1]) > tol ||
    std::fabs(p[2] - bg[2]) > tol;
}

inline size_t CountForeground(const FloatImage& image, const double bg[3], double tol = 1.0 / 255)
{
  size_t count = 0;
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      count += IsForeground(image, x, y, bg, tol) ? 1 : 0;
    }
  }
  return count;
}

/** RMS and max absolute difference of RGB. */
inline void Compare(const FloatImage& a, const FloatImage& b, double& rms, double& maxDiff)
{
  rms = maxDiff = 0;
  if (a.Width != b.Width || a.Height != b.Height)
  {
    rms = maxDiff = HUGE_VAL;
    return;
  }
  double sum = 0;
  const size_t n = static_cast<size_t>(a.Width) * a.Height;
  for (size_t p = 0; p < n; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double d = std::fabs(double(a.RGBA[4 * p + c]) - double(b.RGBA[4 * p + c]));
      sum += d * d;
      maxDiff = std::max(maxDiff, std::isnan(d) ? HUGE_VAL : d);
    }
  }
  rms = std::sqrt(sum / (3.0 * n));
}

inline std::string GLErrors(vtkRenderWindow* window)
{
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!gl)
  {
    return "not an OpenGL render window";
  }
  gl->MakeCurrent();
  std::ostringstream out;
  for (int i = 0; i < 16; ++i)
  {
    const GLenum e = glGetError();
    if (e == GL_NO_ERROR)
    {
      break;
    }
    out << "GL error 0x" << std::hex << e << std::dec << " ";
  }
  return out.str();
}

/** Write the window to $PLUME_GLYPH_DUMP/<name>.png when that variable is set (debugging aid). */
inline void DumpPNG(vtkRenderWindow* window, const std::string& name)
{
  const char* dir = std::getenv("PLUME_GLYPH_DUMP");
  if (!dir || !*dir)
  {
    return;
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName((std::string(dir) + "/" + name + ".png").c_str());
  writer->Write();
}

/**
 * Project a world point to window pixel coordinates (x, y, origin at the
 * bottom-left pixel corner; pixel centres at +0.5) in double precision.
 * Returns false if the point is behind the camera.
 */
inline bool Project(vtkRenderer* ren, const double p[3], double out[2])
{
  int w = 0, h = 0, x0 = 0, y0 = 0;
  ren->GetTiledSizeAndOrigin(&w, &h, &x0, &y0);
  vtkMatrix4x4* m =
    ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(double(w) / h, -1, 1);
  double in[4] = { p[0], p[1], p[2], 1.0 };
  double c[4];
  m->MultiplyPoint(in, c);
  if (c[3] <= 0)
  {
    return false;
  }
  out[0] = x0 + (c[0] / c[3] * 0.5 + 0.5) * w;
  out[1] = y0 + (c[1] / c[3] * 0.5 + 0.5) * h;
  return true;
}

/**
 * Where does the drawn glyph end? Looks at foreground pixels in a corridor
 * (±1.2 px) around the screen-space segment from `from` to `tip` (world) and
 * reports the furthest drawn pixel centre along it relative to the projected
 * tip (negative: short), how many drawn pixels lie 2..6 px beyond the tip, and
 * the colour of the drawn pixel nearest the segment's midpoint.
 */
struct TipResult
{
  bool Valid = false; // projected, on screen and long enough to judge
  double Length = 0;  // projected segment length, px
  double Reach = 0;   // furthest drawn pixel centre along the segment minus Length
  int Beyond = 0;
  bool HasMid = false;
  float MidColor[3] = { 0, 0, 0 };
};

inline TipResult MeasureTip(vtkRenderer* ren, const FloatImage& img, const double from[3],
  const double tip[3], const double bg[3], double minLength = 6)
{
  TipResult res;
  double r[2], t[2];
  if (!Project(ren, from, r) || !Project(ren, tip, t))
  {
    return res;
  }
  const double dx = t[0] - r[0], dy = t[1] - r[1];
  const double len = std::sqrt(dx * dx + dy * dy);
  if (len < minLength)
  {
    return res;
  }
  for (const double* q : { r, t })
  {
    if (q[0] < 3 || q[1] < 3 || q[0] > img.Width - 3 || q[1] > img.Height - 3)
    {
      return res;
    }
  }
  const double ux = dx / len, uy = dy / len;
  double reach = -1e9, bestMid = 1e9;
  const int x0 = std::max(0, int(std::min(r[0], t[0])) - 10);
  const int x1 = std::min(img.Width - 1, int(std::max(r[0], t[0])) + 10);
  const int y0 = std::max(0, int(std::min(r[1], t[1])) - 10);
  const int y1 = std::min(img.Height - 1, int(std::max(r[1], t[1])) + 10);
  for (int y = y0; y <= y1; ++y)
  {
    for (int x = x0; x <= x1; ++x)
    {
      if (!IsForeground(img, x, y, bg, 0.05))
      {
        continue;
      }
      const double px = x + 0.5 - r[0], py = y + 0.5 - r[1];
      const double s = px * ux + py * uy;
      const double d = std::fabs(px * uy - py * ux);
      if (d > 1.2)
      {
        continue;
      }
      if (s >= len + 2 && s <= len + 6)
      {
        ++res.Beyond;
      }
      if (s >= -1 && s <= len + 6)
      {
        reach = std::max(reach, s);
      }
      const double m = std::hypot(x + 0.5 - (r[0] + t[0]) / 2, y + 0.5 - (r[1] + t[1]) / 2);
      if (m < bestMid && m <= 1.5)
      {
        bestMid = m;
        res.HasMid = true;
        std::copy(img.Pixel(x, y), img.Pixel(x, y) + 3, res.MidColor);
      }
    }
  }
  res.Valid = true;
  res.Length = len;
  res.Reach = reach - len;
  return res;
}

#define PLUME_CHECK(cond)                                                                          \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #cond "\n";                   \
      ++failures;                                                                                  \
    }                                                                                              \
  } while (false)
}

#endif
