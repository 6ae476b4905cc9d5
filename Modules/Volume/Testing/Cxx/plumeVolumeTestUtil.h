// Helpers shared by the Plume::Volume tests: an analytic smoke field, a scene
// around a vtkPlumeVolumeMapper, and the comparison of its read-back image
// with vtkPlumeVolumeReference (composited over the read-back of the same
// scene without the volume, whose depth also stops the reference's rays).
#ifndef plumeVolumeTestUtil_h
#define plumeVolumeTestUtil_h

#include "plumeTestSupport.h"
#include "vtkPlumeVolumeMapper.h"
#include "vtkPlumeVolumeReference.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkUnsignedCharArray.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace plumevolumetest
{
/** Asymmetric smoke: three Gaussian puffs in the unit cube, values in [0, ~1]. */
inline vtkSmartPointer<vtkImageData> SmokeField(int n, double offset = 0.0)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetSpacing(1.0 / (n - 1), 1.0 / (n - 1), 1.0 / (n - 1));
  image->SetOrigin(offset, offset, offset);
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  const double c[3][4] = { { 0.35, 0.4, 0.45, 0.18 }, { 0.68, 0.6, 0.5, 0.12 },
    { 0.5, 0.25, 0.7, 0.08 } };
  vtkIdType id = 0;
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i, ++id)
      {
        const double x = double(i) / (n - 1), y = double(j) / (n - 1), z = double(k) / (n - 1);
        double v = 0;
        for (const auto& g : c)
        {
          const double r2 = (x - g[0]) * (x - g[0]) + (y - g[1]) * (y - g[1]) + (z - g[2]) * (z - g[2]);
          v += std::exp(-r2 / (2 * g[3] * g[3]));
        }
        values->SetValue(id, static_cast<float>(std::min(v, 1.2)));
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

/** Blue-white-orange colours, opacity ramp from lo+10% to hi over [lo, hi]. */
inline void SetTransferFunctions(vtkVolumeProperty* property, double lo, double hi, double peakOpacity,
  double unitDistance)
{
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(lo, 0.1, 0.2, 0.8);
  color->AddRGBPoint(lo + 0.5 * (hi - lo), 0.9, 0.9, 0.8);
  color->AddRGBPoint(hi, 1.0, 0.5, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(lo, 0.0);
  opacity->AddPoint(lo + 0.05 * (hi - lo), 0.0);
  opacity->AddPoint(hi, peakOpacity);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(unitDistance);
  property->SetInterpolationTypeToLinear();
}

struct Scene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkVolume> Volume;
  vtkSmartPointer<vtkPlumeVolumeMapper> Mapper;
  vtkSmartPointer<vtkImageData> Image;
};

inline Scene MakeScene(vtkImageData* image, int width, int height)
{
  Scene s;
  s.Image = image;
  s.Window = plume::test::MakeOffscreenWindow(width, height);
  s.Renderer = vtkSmartPointer<vtkRenderer>::New();
  s.Renderer->SetBackground(0.12, 0.1, 0.18);
  s.Window->AddRenderer(s.Renderer);
  s.Mapper = vtkSmartPointer<vtkPlumeVolumeMapper>::New();
  s.Mapper->SetInputData(image);
  s.Volume = vtkSmartPointer<vtkVolume>::New();
  s.Volume->SetMapper(s.Mapper);
  double range[2];
  image->GetPointData()->GetScalars()->GetRange(range);
  SetTransferFunctions(s.Volume->GetProperty(), range[0], range[1], 0.8, 0.03 * image->GetLength());
  s.Renderer->AddVolume(s.Volume);
  vtkCamera* camera = s.Renderer->GetActiveCamera();
  camera->SetPosition(0.3, -0.4, 1.0);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  s.Renderer->ResetCamera();
  return s;
}

/**
 * The 32³ smoke in smoke mode (shadow step 0.5 voxel, ambient 0.25, diffuse
 * 0.9) under one scene light from the side, so self-shadowing shows; 96 x 80.
 */
inline Scene SideLitSmoke()
{
  Scene s = MakeScene(SmokeField(32), 96, 80);
  s.Mapper->SmokeOn();
  s.Mapper->SetShadowSampleDistance(0.5);
  s.Volume->GetProperty()->SetAmbient(0.25);
  s.Volume->GetProperty()->SetDiffuse(0.9);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(1.5, 1.0, 0.2);
  light->SetFocalPoint(0.5, 0.5, 0.5);
  light->SetPositional(false);
  s.Renderer->AddLight(light);
  s.Renderer->AutomaticLightCreationOff();
  return s;
}

/** Write RGB of a float image as PNG (debugging: set PLUME_VOLUME_DUMP to a folder). */
inline void SavePNG(const std::vector<float>& rgba, int width, int height, const std::string& path)
{
  vtkNew<vtkImageData> out;
  out->SetDimensions(width, height, 1);
  vtkNew<vtkUnsignedCharArray> px;
  px->SetNumberOfComponents(3);
  px->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  for (vtkIdType i = 0; i < px->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = std::min(1.0, std::max(0.0, double(rgba[4 * i + c])));
      px->SetValue(3 * i + c, static_cast<unsigned char>(v * 255 + 0.5));
    }
  }
  out->GetPointData()->SetScalars(px);
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(out);
  writer->Write();
}

inline void Dump(const char* name, const std::vector<float>& rgba, int width, int height)
{
  const char* dir = std::getenv("PLUME_VOLUME_DUMP");
  if (dir && *dir)
  {
    SavePNG(rgba, width, height, std::string(dir) + "/" + name + ".png");
  }
}

struct Result
{
  double RMS = 0, Max = 0;
  size_t Covered = 0; // pixels where the reference volume has alpha > 1/255
  bool NonFinite = false;
  std::string GLError;
};

/**
 * Render the scene without and with the volume (same clipping range), compute
 * the reference for `mode` and compare. The reference's image is written to
 * `referenceOut` if given.
 */
inline Result CompareWithReference(Scene& s, int mode, double referenceStep = 0.125,
  plume::test::FloatImage* rendered = nullptr)
{
  Result r;
  s.Renderer->ResetCameraClippingRange(); // with the volume: both renders share it
  s.Volume->VisibilityOff();
  const plume::test::FloatImage background = plume::test::ReadBack(s.Window);
  s.Volume->VisibilityOn();
  const plume::test::FloatImage image = plume::test::ReadBack(s.Window);
  r.GLError = plume::test::GLErrors(s.Window);
  r.NonFinite = plume::test::HasNonFinite(image);
  vtkNew<vtkPlumeVolumeReference> reference;
  reference->SetInputData(s.Image);
  reference->SetVolume(s.Volume);
  reference->SetRenderer(s.Renderer);
  reference->SetMode(mode);
  reference->SetIsoValue(s.Mapper->GetIsoValue());
  reference->SetScalarComponent(s.Mapper->GetScalarComponent());
  reference->SetValidMaskArrayName(s.Mapper->GetValidMaskArrayName());
  if (s.Mapper->GetArrayAccessMode() == VTK_GET_ARRAY_BY_NAME && s.Mapper->GetArrayName())
  {
    reference->SetArrayName(s.Mapper->GetArrayName());
  }
  reference->SetStep(referenceStep);
  reference->SetOpaqueDepth(background.Depth);
  if (!reference->Compute(image.Width, image.Height))
  {
    std::printf("reference failed: %s\n", reference->GetLastError().c_str());
    r.RMS = r.Max = HUGE_VAL;
    return r;
  }
  plume::test::FloatImage expected = image;
  expected.RGBA = reference->CompositeOver(background.RGBA);
  const plume::test::ImageError e = plume::test::Compare(image, expected, 3);
  r.RMS = e.RMS;
  r.Max = e.Max;
  const std::vector<float>& v = reference->GetImage();
  for (size_t p = 3; p < v.size(); p += 4)
  {
    r.Covered += v[p] > 1.0 / 255 ? 1 : 0;
  }
  static int counter = 0;
  ++counter;
  Dump(("case" + std::to_string(counter) + "_gpu").c_str(), image.RGBA, image.Width, image.Height);
  Dump(("case" + std::to_string(counter) + "_ref").c_str(), expected.RGBA, image.Width, image.Height);
  if (rendered)
  {
    *rendered = image;
  }
  return r;
}

/** Print and check one case; returns 1 on failure. */
inline int Check(const char* name, const Result& r, double maxRMS, double maxError, size_t minCovered = 100)
{
  const bool ok = r.RMS <= maxRMS && r.Max <= maxError && !r.NonFinite && r.GLError.empty() &&
    r.Covered >= minCovered;
  std::printf("%-40s RMS %.5f (<= %.4f)  max %.4f (<= %.3f)  covered %zu px %s%s\n", name, r.RMS, maxRMS,
    r.Max, maxError, r.Covered, r.GLError.c_str(), ok ? "" : "  FAIL");
  return ok ? 0 : 1;
}
}

#endif
