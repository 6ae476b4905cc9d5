// Helpers for the Plume::Airlight tests: an asymmetric room-like scene (floor,
// back wall, a box and a sphere), lights, rendering with and without the pass,
// and the comparison with vtkPlumeAirlightReference. Windows, float read-back
// and GL error checks come from PlumeTestSupport (Testing/Support).
#ifndef plumeAirlightTestUtil_h
#define plumeAirlightTestUtil_h

#include "plumeTestSupport.h"

#include "vtkPlumeAirlightPass.h"
#include "vtkPlumeAirlightReference.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkFramebufferPass.h"
#include "vtkPixelBufferObject.h"
#include "vtkTextureObject.h"
#include "vtkImageData.h"
#include "vtkDataArray.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace airtest
{
using plume::test::FloatImage;

struct Scene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkPlumeAirlightPass> Pass;
  vtkNew<vtkRenderStepsPass> Steps;
  // No medium: only the textured spot lights' images on the surfaces.
  vtkNew<vtkPlumeAirlightPass> Surfaces;

  Scene(int w, int h)
  {
    this->Surfaces->SetDelegatePass(this->Steps);
    this->Window = plume::test::MakeOffscreenWindow(w, h);
    this->Renderer->SetBackground(0.1, 0.15, 0.3);
    this->Window->AddRenderer(this->Renderer);
    this->Pass->SetDelegatePass(this->Steps);
    // The unshadowed closed form unless a test turns shadows on (TestAirlightShadow).
    this->Pass->ShadowsOff();
  }

  vtkActor* AddBox(double x0, double x1, double y0, double y1, double z0, double z1, double r, double g, double b)
  {
    vtkNew<vtkCubeSource> cube;
    cube->SetBounds(x0, x1, y0, y1, z0, z1);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(cube->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(r, g, b);
    this->Renderer->AddActor(actor);
    return actor;
  }

  vtkActor* AddSphere(double x, double y, double z, double radius, double r, double g, double b)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(x, y, z);
    sphere->SetRadius(radius);
    sphere->SetThetaResolution(40);
    sphere->SetPhiResolution(20);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(r, g, b);
    this->Renderer->AddActor(actor);
    return actor;
  }

  /** A room: floor y = 0, back wall z = -4, a box left and a sphere right (asymmetric). */
  void AddRoom()
  {
    this->AddBox(-5, 5, -0.1, 0, -4, 4, 0.6, 0.6, 0.55);
    this->AddBox(-5, 5, 0, 5, -4.1, -4, 0.5, 0.55, 0.6);
    this->AddBox(-2.5, -1.2, 0, 1.6, -2, -0.8, 0.8, 0.3, 0.2);
    this->AddSphere(1.6, 0.7, -1.0, 0.7, 0.2, 0.5, 0.8);
  }

  vtkLight* AddPointLight(double x, double y, double z, double r, double g, double b, double intensity = 1.0)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(true);
    light->SetConeAngle(180);
    light->SetPosition(x, y, z);
    light->SetFocalPoint(x, y - 1, z);
    light->SetColor(r, g, b);
    light->SetIntensity(intensity);
    this->Renderer->AddLight(light);
    return light;
  }

  vtkLight* AddSpotLight(const double p[3], const double f[3], double cone, double exponent, double r,
    double g, double b, double intensity = 1.0)
  {
    vtkLight* light = this->AddPointLight(p[0], p[1], p[2], r, g, b, intensity);
    light->SetFocalPoint(f[0], f[1], f[2]);
    light->SetConeAngle(cone);
    light->SetExponent(exponent);
    return light;
  }

  void Camera(double px, double py, double pz, double fx, double fy, double fz, double angle = 50)
  {
    vtkCamera* cam = this->Renderer->GetActiveCamera();
    cam->SetPosition(px, py, pz);
    cam->SetFocalPoint(fx, fy, fz);
    cam->SetViewUp(0, 1, 0);
    cam->SetViewAngle(angle);
    this->Renderer->ResetCameraClippingRange();
  }

  /** The scene without the pass. */
  FloatImage RenderPlain()
  {
    this->Renderer->SetPass(nullptr);
    return plume::test::ReadBack(this->Window);
  }

  /** The scene through the pass. */
  FloatImage RenderAirlight()
  {
    this->Renderer->SetPass(this->Pass);
    return plume::test::ReadBack(this->Window);
  }

  /**
   * The scene through `pass` (nullptr: the plain scene) into an RGBA32F
   * target, read back as floats (no 8-bit rounding, values above 1 kept);
   * depth from the same target (the window's depth format).
   */
  FloatImage RenderFloat(vtkRenderPass* pass)
  {
    vtkNew<vtkFramebufferPass> framebuffer;
    framebuffer->SetDelegatePass(pass ? pass : this->Steps.Get());
    framebuffer->SetColorFormat(vtkTextureObject::Float32);
    this->Renderer->SetPass(framebuffer);
    this->Window->Render();
    FloatImage image;
    vtkTextureObject* color = framebuffer->GetColorTexture();
    vtkTextureObject* depth = framebuffer->GetDepthTexture();
    image.Width = static_cast<int>(color->GetWidth());
    image.Height = static_cast<int>(color->GetHeight());
    auto download = [](vtkTextureObject* texture, int components) {
      vtkSmartPointer<vtkPixelBufferObject> pbo;
      pbo.TakeReference(texture->Download());
      const size_t n = static_cast<size_t>(texture->GetWidth()) * texture->GetHeight() * components;
      std::vector<float> values(n);
      const auto* mapped = static_cast<const float*>(pbo->MapPackedBuffer());
      std::copy(mapped, mapped + n, values.begin());
      pbo->UnmapPackedBuffer();
      return values;
    };
    image.RGBA = download(color, 4);
    image.Depth = download(depth, 1);
    framebuffer->ReleaseGraphicsResources(this->Window);
    this->Renderer->SetPass(nullptr);
    return image;
  }

  /**
   * The surfaces as the pass shows them without a medium (textured spot
   * lights project their images; the plain scene otherwise), float read-back.
   */
  FloatImage RenderSurfaces() { return this->RenderFloat(this->Surfaces); }

  /**
   * The reference frame for the pass's medium, clamped to [0, 1] like the
   * window; `airlight` (optional) gets the airlight alone (surfaces black), clamped too.
   */
  FloatImage Reference(const FloatImage& plain, int stride = 1, FloatImage* airlight = nullptr, bool clampOutput = true)
  {
    vtkNew<vtkPlumeAirlightReference> ref;
    ref->SetScattering(this->Pass->GetScattering());
    ref->SetAbsorption(this->Pass->GetAbsorption());
    ref->SetIntensityScale(this->Pass->GetIntensityScale());
    ref->SetScatteringAnisotropy(this->Pass->GetScatteringAnisotropy());
    if (this->Pass->GetShadows())
    {
      ref->SetOccluders(this->Renderer); // exact ray-cast shadows for spot lights
    }
    ref->SetLights(this->Renderer);
    auto clamp = [clampOutput](FloatImage& img) {
      if (!clampOutput)
      {
        return;
      }
      for (float& v : img.RGBA)
      {
        if (!std::isnan(v))
        {
          v = std::min(std::max(v, 0.0f), 1.0f);
        }
      }
    };
    // Surfaces as the window shows them without the medium (the pass clamps them too).
    std::vector<float> surface(plain.RGBA);
    for (float& v : surface)
    {
      v = std::min(std::max(v, 0.0f), 1.0f);
    }
    FloatImage out = plain;
    if (airlight)
    {
      *airlight = plain; // the same rays' airlight alone (surfaces black)
    }
    ref->ComputeImage(this->Renderer, plain.Width, plain.Height, surface.data(), plain.Depth.data(),
      out.RGBA, stride, airlight ? &airlight->RGBA : nullptr);
    clamp(out);
    if (airlight)
    {
      clamp(*airlight);
    }
    return out;
  }
};

/** The textured-light tests' image: an asymmetric coloured 16 x 12 image (bars, a colour ramp, a block of zeros in a corner). */
inline vtkSmartPointer<vtkImageData> Gobo()
{
  const int w = 16, h = 12;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(w * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const bool bar = ((i / 4 + j / 3) % 2) == 1;
      const double v = (i < 4 && j < 3) ? 0.0 : (bar ? 1.0 : 0.15); // a block of zeros in a corner
      rgb->SetComponent(i + j * w, 0, std::round(255 * v));
      rgb->SetComponent(i + j * w, 1, std::round(255 * v * i / (w - 1.0)));
      rgb->SetComponent(i + j * w, 2, std::round(255 * v * (1.0 - 0.7 * j / (h - 1.0))));
    }
  }
  image->GetPointData()->SetScalars(rgb);
  return image;
}

/** A w x h float RGB image of one colour. */
inline vtkSmartPointer<vtkImageData> ConstantImage(int w, int h, float r, float g, float b)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<vtkFloatArray> rgb;
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(w * h);
  for (vtkIdType p = 0; p < w * h; ++p)
  {
    rgb->SetTuple3(p, r, g, b);
  }
  image->GetPointData()->SetScalars(rgb);
  return image;
}

/** Error of `image` against `reference` over the pixels the reference computed, relative to the range of `airlight`. */
struct Error
{
  double RMS = 0;   // fraction of the airlight range
  double Max = 0;   // fraction of the airlight range
  double Range = 0; // max - min of the (clamped) reference airlight over all channels
  size_t Pixels = 0;
  int MaxX = 0, MaxY = 0;
};

inline Error Compare(const FloatImage& image, const FloatImage& reference, const FloatImage& airlight)
{
  Error e;
  double lo = HUGE_VAL, hi = -HUGE_VAL, sum = 0;
  const size_t n = static_cast<size_t>(image.Width) * image.Height;
  for (size_t p = 0; p < n; ++p)
  {
    if (std::isnan(reference.RGBA[4 * p]))
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      lo = std::min(lo, double(airlight.RGBA[4 * p + c]));
      hi = std::max(hi, double(airlight.RGBA[4 * p + c]));
      const double d = std::fabs(double(image.RGBA[4 * p + c]) - reference.RGBA[4 * p + c]);
      sum += d * d;
      if (d > e.Max)
      {
        e.Max = d;
        e.MaxX = static_cast<int>(p % image.Width);
        e.MaxY = static_cast<int>(p / image.Width);
      }
    }
    ++e.Pixels;
  }
  e.Range = hi - lo;
  const double scale = e.Range > 0 ? e.Range : 1.0;
  e.RMS = std::sqrt(sum / std::max<size_t>(3 * e.Pixels, 1)) / scale;
  e.Max /= scale;
  return e;
}

/** Writes `image` (RGB in [0, 1], scaled by `gain`) as a PNG: for looking at test images ($PLUME_AIRLIGHT_DUMP). */
inline void Dump(const FloatImage& image, const std::string& name, double gain = 1.0)
{
  const char* dir = std::getenv("PLUME_AIRLIGHT_DUMP");
  if (!dir)
  {
    return;
  }
  vtkNew<vtkImageData> img;
  img->SetDimensions(image.Width, image.Height, 1);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(static_cast<vtkIdType>(image.Width) * image.Height);
  for (vtkIdType p = 0; p < rgb->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = gain * image.RGBA[4 * p + c];
      rgb->SetComponent(p, c, std::isnan(v) ? 255 : std::min(255.0, std::max(0.0, 255.0 * v + 0.5)));
    }
  }
  img->GetPointData()->SetScalars(rgb);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(img);
  writer->SetFileName((std::string(dir) + "/" + name + ".png").c_str());
  writer->Write();
}

// Largest difference, in 8-bit levels, between an image (rounded as Dump
// rounds, which wrote the baseline) and the committed baseline NAME.png; -1
// when the sizes differ. `overOne` counts the channels off by more than one
// level. With PLUME_AIRLIGHT_WRITE_BASELINE set, writes /tmp/NAME.png first.
inline int BaselineDifference(const FloatImage& image, const std::string& name, size_t* overOne = nullptr)
{
  const std::string path = PLUME_SOURCE_DIR "/Modules/Airlight/Testing/Data/Baseline/" + name + ".png";
  if (std::getenv("PLUME_AIRLIGHT_WRITE_BASELINE"))
  {
    setenv("PLUME_AIRLIGHT_DUMP", "/tmp", 1);
    Dump(image, name);
    std::cout << "wrote /tmp/" << name << ".png: copy it to " << path << "\n";
  }
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* baseline = reader->GetOutput();
  int dims[3] = { 0, 0, 0 };
  baseline->GetDimensions(dims);
  if (dims[0] != image.Width || dims[1] != image.Height)
  {
    return -1;
  }
  vtkDataArray* bytes = baseline->GetPointData()->GetScalars();
  int worst = 0;
  size_t off = 0;
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(image.Width) * image.Height; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = image.RGBA[4 * p + c];
      const int mine = std::isnan(v) ? 255 : static_cast<int>(std::min(255.0, std::max(0.0, 255.0 * v + 0.5)));
      const int d = std::abs(mine - static_cast<int>(bytes->GetComponent(p, c)));
      worst = std::max(worst, d);
      off += d > 1;
    }
  }
  if (overOne)
  {
    *overOne = off;
  }
  return worst;
}

inline void Print(const char* what, const Error& e)
{
  std::cout << what << ": RMS " << 100 * e.RMS << " %, max " << 100 * e.Max << " % (at " << e.MaxX << ", "
            << e.MaxY << ") of the airlight range " << e.Range << " over " << e.Pixels << " pixels\n";
}

// Splits a comparison into pixels near a shadow boundary of the reference
// (its shadow, refLit - ref, changes by > 2 % of the range to a neighbour) and the others.
struct EdgeSplit
{
  airtest::Error Inner, Edge;
  size_t EdgePixels = 0;
};

// Splits the comparison into pixels near a shadow boundary and the others.
inline EdgeSplit CompareAwayFromEdges(const airtest::FloatImage& image, const airtest::FloatImage& ref,
  const airtest::FloatImage& refLit, const airtest::FloatImage& air, int stride)
{
  const int w = image.Width, h = image.Height;
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (size_t p = 0; p < static_cast<size_t>(w) * h; ++p)
  {
    for (int c = 0; c < 3 && !std::isnan(air.RGBA[4 * p]); ++c)
    {
      lo = std::min(lo, double(air.RGBA[4 * p + c]));
      hi = std::max(hi, double(air.RGBA[4 * p + c]));
    }
  }
  const double range = hi - lo;
  auto shadow = [&](int i, int j, int c) {
    const size_t p = static_cast<size_t>(j) * w + i;
    return double(refLit.RGBA[4 * p + c]) - ref.RGBA[4 * p + c];
  };
  airtest::FloatImage inner = ref, edge = ref;
  EdgeSplit split;
  for (int j = 0; j < h; j += stride)
  {
    for (int i = 0; i < w; i += stride)
    {
      bool isEdge = false;
      for (int dj = -stride; dj <= stride && !isEdge; dj += stride)
      {
        for (int di = -stride; di <= stride && !isEdge; di += stride)
        {
          const int a = i + di, b = j + dj;
          if (a < 0 || b < 0 || a >= w || b >= h)
          {
            continue;
          }
          for (int c = 0; c < 3; ++c)
          {
            isEdge = isEdge || std::fabs(shadow(a, b, c) - shadow(i, j, c)) > 0.02 * range;
          }
        }
      }
      const size_t p = static_cast<size_t>(j) * w + i;
      (isEdge ? inner : edge).RGBA[4 * p] = std::numeric_limits<float>::quiet_NaN();
      split.EdgePixels += isEdge;
    }
  }
  split.Inner = airtest::Compare(image, inner, air);
  split.Edge = airtest::Compare(image, edge, air);
  return split;
}
/**
 * The shadowed tests' common comparison: the scene `s` (lights, medium and
 * camera set) rendered through the pass with shadows off and on, and the
 * reference without and with exact ray-cast shadows on every `stride`-th
 * pixel; the error split at the reference's shadow edges, and the shafts:
 * pixels the shadow darkens by more than 2 % of the airlight range in the
 * pass and in the reference, and pixels it brightens (by > 0.2 %) in the pass.
 * Leaves the pass with shadows on.
 */
struct ShadowComparison
{
  FloatImage Plain, Lit, RefLit, Image, Ref, Air;
  Error All;
  EdgeSplit Split;
  size_t Darker = 0, RefDarker = 0, Brighter = 0;
  double MaxDark = 0, MaxRefDark = 0;
  int ShadowedLightsOff = -1, ShadowedLightsOn = -1;
  bool GLClean = false, Finite = false;
};

// The shadow tests' room: the room of AddRoom, a plate under where their
// lights hang, a light haze and the view from the door. Returns the plate.
inline vtkActor* PlateRoom(Scene& s)
{
  s.AddRoom();
  vtkActor* plate = s.AddBox(-0.7, 0.5, 2.5, 2.6, -2.1, -0.9, 0.9, 0.9, 0.8);
  s.Pass->SetScattering(0.22, 0.2, 0.18);
  s.Pass->SetAbsorption(0.02, 0.03, 0.05);
  s.Pass->SetIntensityScale(30.0);
  s.Camera(2.5, 1.6, 5.5, -0.3, 1.4, -1.5);
  return plate;
}

inline ShadowComparison CompareShadowed(Scene& s, int stride, const std::string& what)
{
  ShadowComparison r;
  r.Plain = s.RenderFloat(nullptr);
  s.Pass->ShadowsOff();
  r.RefLit = s.Reference(r.Plain, stride, nullptr, false);
  r.Lit = s.RenderFloat(s.Pass);
  r.ShadowedLightsOff = s.Pass->GetNumberOfShadowedLights();
  s.Pass->ShadowsOn();
  r.Ref = s.Reference(r.Plain, stride, &r.Air, false);
  r.Image = s.RenderFloat(s.Pass);
  r.ShadowedLightsOn = s.Pass->GetNumberOfShadowedLights();
  r.GLClean = plume::test::GLErrors(s.Window).empty();
  r.Finite = !plume::test::HasNonFinite(r.Image);
  Dump(r.Image, what + " pass");
  Dump(r.Ref, what + " reference");
  Dump(r.Lit, what + " unshadowed pass");
  r.All = Compare(r.Image, r.Ref, r.Air);
  Print((what + ", all pixels").c_str(), r.All);
  r.Split = CompareAwayFromEdges(r.Image, r.Ref, r.RefLit, r.Air, stride);
  Print((what + ", away from shadow edges").c_str(), r.Split.Inner);
  Print((what + ", shadow-edge pixels").c_str(), r.Split.Edge);
  std::cout << "edge pixels: " << r.Split.EdgePixels << " of " << r.All.Pixels << "\n";
  const size_t n = static_cast<size_t>(r.Image.Width) * r.Image.Height;
  for (size_t p = 0; p < n; ++p)
  {
    if (std::isnan(r.Ref.RGBA[4 * p]))
    {
      continue;
    }
    const double d = double(r.Lit.RGBA[4 * p]) - r.Image.RGBA[4 * p];
    const double dr = double(r.RefLit.RGBA[4 * p]) - r.Ref.RGBA[4 * p];
    r.Darker += d > 0.02 * r.All.Range;
    r.RefDarker += dr > 0.02 * r.All.Range;
    r.MaxDark = std::max(r.MaxDark, d);
    r.MaxRefDark = std::max(r.MaxRefDark, dr);
    r.Brighter += d < -0.002 * r.All.Range;
  }
  std::cout << "shafts: " << r.Darker << " pixels darker by > 2 % (reference " << r.RefDarker << "), "
            << r.Brighter << " brighter; largest darkening " << r.MaxDark << " (reference " << r.MaxRefDark
            << ")\n";
  return r;
}

/** The goal away from shadow edges (RMS <= 0.5 %, max <= 2 %), edges bounded loosely; returns the failures. */
inline int CheckShadowGoal(const ShadowComparison& r)
{
  int failures = 0;
  PLUME_CHECK(r.GLClean);
  PLUME_CHECK(r.Finite);
  PLUME_CHECK(r.ShadowedLightsOff == 0);
  PLUME_CHECK(r.Split.Inner.Range > 0.3);
  PLUME_CHECK(r.Split.Inner.RMS <= 0.005);
  PLUME_CHECK(r.Split.Inner.Max <= 0.02);
  PLUME_CHECK(r.Split.EdgePixels < r.All.Pixels / 5);
  PLUME_CHECK(r.Split.Edge.RMS <= 0.05); // aliasing of the map and the march, bounded loosely
  return failures;
}

/**
 * Min-max shadow mipmaps: the frame with them (r.Image) against the march that
 * tests every step (the same sums up to float rounding: max <= 1e-4 of the
 * range), and the share of march runs they decided (from the pass's run
 * statistics) at least `minDecided`; returns the failures.
 */
inline int CheckMinMax(Scene& s, const ShadowComparison& r, double minDecided)
{
  int failures = 0;
  s.Pass->SetShadowMinMax(false);
  const FloatImage perStep = s.RenderFloat(s.Pass);
  s.Pass->SetShadowMinMax(true);
  const Error same = Compare(r.Image, perStep, r.Air);
  Print("min-max mipmaps vs every step tested", same);
  PLUME_CHECK(same.Max <= 1e-4);
  s.Pass->SetShadowRunStatistics(true);
  const FloatImage stats = s.RenderFloat(s.Pass);
  s.Pass->SetShadowRunStatistics(false);
  double decided = 0, total = 0;
  for (size_t p = 0; p < static_cast<size_t>(stats.Width) * stats.Height; ++p)
  {
    decided += stats.RGBA[4 * p];
    total += stats.RGBA[4 * p + 1];
  }
  std::cout << "min-max runs decided: " << decided << " of " << total << " ("
            << 100.0 * decided / std::max(total, 1.0) << " %)\n";
  PLUME_CHECK(total > 0);
  PLUME_CHECK(decided >= minDecided * total);
  return failures;
}

/**
 * Lit rays: the scene's shadows on against off (every shadow test passes, the
 * march telescopes to the closed form); returns the comparison, the pass left
 * with shadows on. `shadowed` gets the number of shadowed lights.
 */
inline Error ShadowsOnVersusOff(Scene& s, int& shadowed)
{
  s.Pass->ShadowsOff();
  const FloatImage off = s.RenderFloat(s.Pass);
  s.Pass->ShadowsOn();
  const FloatImage on = s.RenderFloat(s.Pass);
  shadowed = s.Pass->GetNumberOfShadowedLights();
  return Compare(on, off, off);
}
}

#endif
