// Glyph-specific helpers for the Plume::Rendering tests: projection of world
// points in double precision, where a drawn glyph ends (MeasureTip), a PNG
// dump for debugging, the image tests' outline and ending (OutlineActor,
// RenderAndCompare). Windows, float read-back, image metrics, GL error checks
// and PLUME_CHECK come from PlumeTestSupport (Testing/Support).
#ifndef plumeGlyphTestUtil_h
#define plumeGlyphTestUtil_h

#include "plumeTestSupport.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOutlineSource.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace plumetest
{
using plume::test::FloatImage;

/** True if the pixel's RGB differs from `bg` by more than `tol` in some channel. */
inline bool IsForeground(const FloatImage& image, int x, int y, const double bg[3], double tol)
{
  const float* p = image.Pixel(x, y);
  return std::fabs(p[0] - bg[0]) > tol || std::fabs(p[1] - bg[1]) > tol ||
    std::fabs(p[2] - bg[2]) > tol;
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

/** A wireframe box around `bounds` in grey level `grey`: the image tests' frame of reference. */
inline vtkSmartPointer<vtkActor> OutlineActor(const double bounds[6], double grey)
{
  vtkNew<vtkOutlineSource> outline;
  outline->SetBounds(bounds);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(outline->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(grey, grey, grey);
  return actor;
}

/**
 * The end of an image test: render `window`; any GL error fails, otherwise
 * the comparison with the test's baseline decides (EXIT_SUCCESS / EXIT_FAILURE).
 */
inline int RenderAndCompare(vtkRenderWindow* window, int argc, char* argv[])
{
  window->Render();
  const std::string errors = plume::test::GLErrors(window);
  if (!errors.empty())
  {
    std::cerr << errors << "\n";
    return EXIT_FAILURE;
  }
  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
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
}

#endif
