// Soak: one process renders each representation (glyphs, volume, sheet) for
// FRAMES frames while the camera orbits; every 50 frames the data (vortex
// circulation and drift, or the mesh's density array), the arrays (which
// vector/scalar array is drawn), the transfer functions / colour map and
// the parameters (scale, sample distance, density, blur) change. Asserts:
// no GL error, no NaN pixel, no stale frame (at each change the frame with
// the same camera differs from the one before the change), and flat memory:
// the least-squares slope of RSS over the frames after warm-up, and the
// number of live GL textures, buffers and programs (counted with glIs* over
// the name range in use) after warm-up, stay within bounds. Prints one JSON
// line per representation (frames, rss_start/end_mb, rss_slope_mb_per_1000,
// gl_objects min/max).
//   plumeSoak [FRAMES]   (default 1000; ctest: 1000 under the label "soak", 150 in the default suite)
#include "plumeTestSupport.h"

#include "vtkPlumeSheetMapper.h"
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkPlumeVolumeMapper.h"
#include "vtkPlumeVortexSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtk_glew.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
double RssMB()
{
  long pages = 0, resident = 0;
  if (FILE* f = std::fopen("/proc/self/statm", "r"))
  {
    if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2)
    {
      resident = 0;
    }
    std::fclose(f);
  }
  return double(resident) * double(sysconf(_SC_PAGE_SIZE)) / (1 << 20);
}

// Live GL names: VTK hands out small consecutive names, so probing 1..4096 counts them all.
int CountGLObjects(vtkRenderWindow* window)
{
  window->MakeCurrent();
  int n = 0;
  for (GLuint id = 1; id <= 4096; ++id)
  {
    n += glIsTexture(id) ? 1 : 0;
    n += glIsBuffer(id) ? 1 : 0;
    n += glIsProgram(id) ? 1 : 0;
  }
  return n;
}

double Slope(const std::vector<double>& y, size_t from)
{
  // least squares of y[i] over i >= from, per frame
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = double(y.size() - from);
  for (size_t i = from; i < y.size(); ++i)
  {
    sx += double(i);
    sy += y[i];
    sxx += double(i) * double(i);
    sxy += double(i) * y[i];
  }
  const double d = n * sxx - sx * sx;
  return d > 0 ? (n * sxy - sx * sy) / d : 0.0;
}

struct Representation
{
  std::string Name;
  std::function<void(vtkRenderer*)> Add;
  std::function<void(int change)> Change; // change = 1, 2, ...
  std::function<void(vtkRenderer*)> Remove;
};

vtkSmartPointer<vtkImageData> Vortex(double circulation, double drift)
{
  vtkNew<vtkPlumeVortexSource> source;
  source->SetDimensions(40, 40, 40);
  source->SetCirculation(circulation);
  source->SetDrift(drift, 0, 0);
  source->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(source->GetOutput());
  // a second vector and scalar array, to switch arrays
  vtkDataArray* v = image->GetPointData()->GetArray("velocity");
  vtkNew<vtkFloatArray> swirl, height;
  swirl->SetName("swirl");
  swirl->SetNumberOfComponents(3);
  swirl->SetNumberOfTuples(v->GetNumberOfTuples());
  height->SetName("height");
  height->SetNumberOfTuples(v->GetNumberOfTuples());
  for (vtkIdType i = 0; i < v->GetNumberOfTuples(); ++i)
  {
    double t[3], p[3];
    v->GetTuple(i, t);
    image->GetPoint(i, p);
    swirl->SetTuple3(i, -t[1], t[0], 0.5 * t[2]);
    height->SetValue(i, static_cast<float>(0.5 * (p[2] + 1.0) + 0.1 * vtkMath::Norm(t))); // depends on the data too
  }
  image->GetPointData()->AddArray(swirl);
  image->GetPointData()->AddArray(height);
  return image;
}
}

int main(int argc, char* argv[])
{
  const int frames = argc > 1 ? std::atoi(argv[1]) : 1000;
  const int every = 50;
  const int warmup = std::min(200, frames / 3);
  auto window = plume::test::MakeOffscreenWindow(160, 120);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.12);
  window->AddRenderer(renderer);
  int failures = 0;

  // --- glyphs
  vtkNew<vtkPlumeVelocityGlyphMapper> glyphs;
  vtkNew<vtkActor> glyphActor;
  glyphActor->SetMapper(glyphs);
  vtkNew<vtkLookupTable> lut;
  lut->Build();
  // --- volume
  vtkNew<vtkPlumeVolumeMapper> volumeMapper;
  vtkNew<vtkVolume> volume;
  volume->SetMapper(volumeMapper);
  // --- sheet
  // a small oblique sheet (the office sheet takes seconds a frame on llvmpipe)
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1, -1, -0.3);
  plane->SetPoint1(1, -0.8, 0.2);
  plane->SetPoint2(-0.9, 1, 0.4);
  plane->SetResolution(24, 24);
  plane->Update();
  vtkSmartPointer<vtkPolyData> sheetData = plane->GetOutput();
  vtkNew<vtkPlumeSheetMapper> sheet;
  vtkNew<vtkActor> sheetActor;
  sheetActor->SetMapper(sheet);

  std::vector<Representation> reps;
  reps.push_back({ "glyphs",
    [&](vtkRenderer* r) {
      glyphs->SetInputData(Vortex(2.0, 0.1));
      glyphs->SetVectorArrayName("velocity");
      glyphs->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
      glyphs->SetLatticeStride(3);
      glyphs->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
      glyphs->SetScale(0.05);
      glyphs->SetLookupTable(lut);
      r->AddActor(glyphActor);
    },
    [&](int k) {
      switch (k % 4)
      {
        case 1: glyphs->SetInputData(Vortex(2.0 + 0.3 * k, 0.1 * (k % 3))); break; // data
        case 2: glyphs->SetVectorArrayName(k % 8 == 2 ? "swirl" : "velocity"); break; // arrays
        case 3: lut->SetHueRange(0.1 * (k % 7), 0.7); lut->ForceBuild(); lut->Modified(); break; // colour map
        default: glyphs->SetScale(0.03 + 0.01 * (k % 5)); // parameters
      }
    },
    [&](vtkRenderer* r) { r->RemoveActor(glyphActor); } });
  reps.push_back({ "volume",
    [&](vtkRenderer* r) {
      volumeMapper->SetInputData(Vortex(2.0, 0.1));
      volumeMapper->SetArrayAccessMode(VTK_GET_ARRAY_BY_NAME);
      volumeMapper->SelectScalarArray("speed");
      volumeMapper->SetScalarModeToUsePointFieldData();
      vtkNew<vtkColorTransferFunction> color;
      color->AddRGBPoint(0, 0.1, 0.2, 0.8);
      color->AddRGBPoint(3, 1.0, 0.5, 0.1);
      vtkNew<vtkPiecewiseFunction> opacity;
      opacity->AddPoint(0, 0);
      opacity->AddPoint(3, 0.6);
      volume->GetProperty()->SetColor(color);
      volume->GetProperty()->SetScalarOpacity(opacity);
      volume->GetProperty()->SetScalarOpacityUnitDistance(0.2);
      r->AddVolume(volume);
    },
    [&](int k) {
      switch (k % 4)
      {
        case 1: volumeMapper->SetInputData(Vortex(2.0 + 0.4 * k, 0.05 * (k % 4))); break;
        case 2: volumeMapper->SelectScalarArray(k % 8 == 2 ? "height" : "speed"); break;
        case 3:
        {
          vtkColorTransferFunction* color = volume->GetProperty()->GetRGBTransferFunction();
          color->RemoveAllPoints();
          color->AddRGBPoint(0, 0.1 * (k % 5), 0.2, 0.8);
          color->AddRGBPoint(1 + 0.2 * (k % 6), 1.0, 0.5, 0.1 * (k % 9));
          break;
        }
        default: volumeMapper->SetSampleDistance((k / 4) % 2 ? 0.9 : 0.4); // differs from the last value
      }
    },
    [&](vtkRenderer* r) { r->RemoveVolume(volume); } });
  reps.push_back({ "sheet",
    [&](vtkRenderer* r) {
      sheet->SetInputData(sheetData);
      sheet->SetDensity(1.0);
      sheet->SetBlurRadius(0.05);
      sheet->SetThickness(0.05);
      sheet->SetSmokeColor(0.9, 0.6, 0.3);
      r->AddActor(sheetActor);
    },
    [&](int k) {
      switch (k % 4)
      {
        case 1:
        {
          auto copy = vtkSmartPointer<vtkPolyData>::New();
          copy->DeepCopy(sheetData);
          vtkNew<vtkFloatArray> d;
          d->SetName("d");
          d->SetNumberOfTuples(copy->GetNumberOfPoints());
          for (vtkIdType i = 0; i < copy->GetNumberOfPoints(); ++i)
          {
            d->SetValue(i, static_cast<float>(0.5 + 0.3 * ((i + k) % 7)));
          }
          copy->GetPointData()->AddArray(d);
          vtkNew<vtkPoints> moved; // the mesh itself changes too
          moved->DeepCopy(copy->GetPoints());
          for (vtkIdType i = 0; i < moved->GetNumberOfPoints(); ++i)
          {
            double p[3];
            moved->GetPoint(i, p);
            p[2] += 0.1 * std::sin(3.0 * p[0] + k);
            moved->SetPoint(i, p);
          }
          copy->SetPoints(moved);
          sheet->SetInputData(copy); // data
          break;
        }
        case 2: sheet->SetDensityArrayName(k % 8 == 2 ? "d" : ""); break; // arrays
        case 3: sheet->SetSmokeColor(0.2 * (k % 5), 0.6, 0.35); break;       // "transfer function": colour
        default: sheet->SetBlurRadius((k / 4) % 2 ? 0.12 : 0.05); // differs from the last value
      }
    },
    [&](vtkRenderer* r) { r->RemoveActor(sheetActor); } });

  for (auto& rep : reps)
  {
    rep.Add(renderer);
    renderer->ResetCamera();
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->Elevation(20);
    std::vector<double> rss;
    int glMin = 1 << 30, glMax = 0, stale = 0, changes = 0;
    std::string glErrors;
    for (int f = 0; f < frames; ++f)
    {
      if (f > 0 && f % every == 0)
      {
        // same camera before and after the change: the frames must differ
        const plume::test::FloatImage before = plume::test::ReadBack(window);
        rep.Change(++changes);
        const plume::test::FloatImage after = plume::test::ReadBack(window);
        if (plume::test::Compare(before, after).Max < 1.0 / 255)
        {
          ++stale;
          std::cerr << rep.Name << ": frame " << f << " did not change after change " << changes << "\n";
        }
        if (plume::test::HasNonFinite(after))
        {
          std::cerr << rep.Name << ": NaN pixel after change " << changes << "\n";
          ++failures;
        }
      }
      camera->Azimuth(360.0 / 250.0);
      window->Render();
      const std::string e = plume::test::GLErrors(window);
      if (!e.empty() && glErrors.empty())
      {
        glErrors = e;
      }
      rss.push_back(RssMB());
      if (f >= warmup && (f % every == every - 1))
      {
        const int n = CountGLObjects(window);
        glMin = std::min(glMin, n);
        glMax = std::max(glMax, n);
      }
    }
    rep.Remove(renderer);
    const double slope = 1000.0 * Slope(rss, warmup);
    std::printf("{\"soak\": \"%s\", \"frames\": %d, \"changes\": %d, \"rss_start_mb\": %.1f, \"rss_end_mb\": %.1f, "
                "\"rss_slope_mb_per_1000\": %.2f, \"gl_objects_min\": %d, \"gl_objects_max\": %d, \"stale\": %d}\n",
      rep.Name.c_str(), frames, changes, rss[warmup], rss.back(), slope, glMin, glMax, stale);
    std::fflush(stdout);
    if (!glErrors.empty())
    {
      std::cerr << rep.Name << ": GL errors: " << glErrors << "\n";
      ++failures;
    }
    failures += stale;
    // flat: under 2 MB per 1000 frames after warm-up, and a constant number of GL objects
    if (std::fabs(slope) > 2.0)
    {
      std::cerr << rep.Name << ": RSS grows " << slope << " MB per 1000 frames\n";
      ++failures;
    }
    if (glMax - glMin > 2)
    {
      std::cerr << rep.Name << ": GL objects vary from " << glMin << " to " << glMax << "\n";
      ++failures;
    }
  }
  return failures ? 1 : 0;
}
