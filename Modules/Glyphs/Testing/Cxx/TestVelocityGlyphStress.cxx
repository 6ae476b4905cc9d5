// Stress tests (no baseline). Every case asserts: no NaN/Inf in the float
// read-back, no GL error, no crash, and a sensible amount of foreground.
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkPlumeVortexSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include "plumeGlyphTestUtil.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
const double Background[3] = { 0.0, 0.0, 0.0 };

vtkSmartPointer<vtkImageData> MakeImage(
  int nx, int ny, int nz, const double origin[3], const double spacing[3], const float v[3])
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  image->SetOrigin(origin[0], origin[1], origin[2]);
  image->SetSpacing(spacing[0], spacing[1], spacing[2]);
  vtkNew<vtkFloatArray> vectors;
  vectors->SetName("velocity");
  vectors->SetNumberOfComponents(3);
  vectors->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    vectors->SetTypedTuple(i, v);
  }
  image->GetPointData()->SetVectors(vectors);
  return image;
}

struct Scene
{
  vtkNew<vtkPlumeVelocityGlyphMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkSmartPointer<vtkRenderWindow> Window;

  // one X window for all cases (fewer X connections, quicker)
  static vtkRenderWindow* SharedWindow()
  {
    static vtkSmartPointer<vtkRenderWindow> window = plume::test::MakeOffscreenWindow(200, 200);
    return window;
  }

  explicit Scene(vtkDataObject* image, int size = 200)
  {
    this->Mapper->SetInputDataObject(image);
    this->Mapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
    this->Mapper->SetRootAlpha(1.0);
    this->Mapper->ColorByMagnitudeOff();
    this->Actor->SetMapper(this->Mapper);
    this->Actor->GetProperty()->SetDiffuseColor(1, 1, 1);
    this->Renderer->SetBackground(Background[0], Background[1], Background[2]);
    this->Renderer->AddActor(this->Actor);
    this->Window = SharedWindow();
    this->Window->SetSize(size, size);
    this->Window->AddRenderer(this->Renderer);
  }

  ~Scene()
  {
    // releases the mapper's GL resources through the prop
    this->Renderer->RemoveActor(this->Actor);
    this->Window->RemoveRenderer(this->Renderer);
  }

  // renders, checks the generic conditions; returns the number of foreground pixels
  size_t Check(const char* name, int& failures, plume::test::FloatImage* out = nullptr)
  {
    const plume::test::FloatImage img = plume::test::ReadBack(this->Window);
    plumetest::DumpPNG(this->Window, std::string("Stress_") + name);
    const std::string gl = plume::test::GLErrors(this->Window);
    const bool finite = !plume::test::HasNonFinite(img);
    const size_t fg = plume::test::CountForeground(img, Background, 0.02);
    std::cout << name << ": " << fg << " foreground pixels, roots " << this->Mapper->GetLastRootCount()
              << (finite ? "" : ", NON-FINITE read-back") << (gl.empty() ? "" : ", " + gl) << "\n";
    if (!finite || !gl.empty())
    {
      std::cerr << name << ": failed generic checks\n";
      ++failures;
    }
    if (out)
    {
      *out = img;
    }
    return fg;
  }
};
}

int TestVelocityGlyphStress(int, char*[])
{
  int failures = 0;
  const double zero[3] = { 0, 0, 0 };
  const double unit[3] = { 0.1, 0.1, 0.1 };

  // --- zero field: nothing drawn
  {
    const float v[3] = { 0, 0, 0 };
    auto image = MakeImage(8, 8, 8, zero, unit, v);
    Scene scene(image);
    scene.Renderer->ResetCamera();
    PLUME_CHECK(scene.Check("zero", failures) == 0);
    PLUME_CHECK(scene.Mapper->GetLastRootCount() == 512);
  }

  // --- NaN / Inf vectors and mask == 0 nodes are skipped, the others drawn
  {
    const float v[3] = { 0.05f, 0.02f, 0.0f };
    auto image = MakeImage(8, 8, 1, zero, unit, v);
    auto* vectors = vtkFloatArray::SafeDownCast(image->GetPointData()->GetVectors());
    vtkNew<vtkUnsignedCharArray> mask;
    mask->SetName("vtkValidPointMask");
    mask->SetNumberOfTuples(image->GetNumberOfPoints());
    mask->FillValue(1);
    image->GetPointData()->AddArray(mask);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<bool> skipped(image->GetNumberOfPoints(), false);
    for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
    {
      if (i % 5 == 1)
      {
        vectors->SetComponent(i, int(i % 3), i % 2 ? nan : inf);
        skipped[i] = true;
      }
      else if (i % 7 == 3)
      {
        mask->SetValue(i, 0);
        skipped[i] = true;
      }
    }
    Scene scene(image, 240);
    scene.Mapper->SetLineWidth(3.0);
    vtkCamera* cam = scene.Renderer->GetActiveCamera();
    cam->SetPosition(0.35, 0.35, 2.0);
    cam->SetFocalPoint(0.35, 0.35, 0.0);
    cam->SetViewUp(0, 1, 0);
    cam->SetViewAngle(30);
    scene.Renderer->ResetCameraClippingRange();
    plume::test::FloatImage img;
    const size_t fg = scene.Check("nan_inf_mask", failures, &img);
    PLUME_CHECK(fg > 0);
    int wrong = 0;
    for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
    {
      double p[3], mid[3], px[2];
      image->GetPoint(i, p);
      for (int a = 0; a < 3; ++a)
      {
        mid[a] = p[a] + 0.5 * v[a];
      }
      if (!plumetest::Project(scene.Renderer, mid, px))
      {
        continue;
      }
      const bool drawn = plumetest::IsForeground(img, int(px[0]), int(px[1]), Background, 0.02);
      if (drawn == skipped[i])
      {
        ++wrong;
        std::cerr << "node " << i << (skipped[i] ? " should be skipped" : " should be drawn") << "\n";
      }
    }
    PLUME_CHECK(wrong == 0);
  }

  // --- huge vectors: no NaN, no GL error; ordinary glyphs still drawn
  {
    const float v[3] = { 0.03f, 0.01f, 0.0f };
    auto image = MakeImage(6, 6, 2, zero, unit, v);
    auto* vectors = vtkFloatArray::SafeDownCast(image->GetPointData()->GetVectors());
    vectors->SetComponent(7, 0, 1e30f);
    vectors->SetComponent(7, 1, -1e30f);
    vectors->SetComponent(20, 2, 3e38f);
    for (int mode = 0; mode < 2; ++mode)
    {
      Scene scene(image);
      scene.Mapper->SetLineWidth(mode == 0 ? 1.0 : 4.0);
      scene.Mapper->SetColorByMagnitude(mode == 1);
      vtkCamera* cam = scene.Renderer->GetActiveCamera();
      cam->SetPosition(0.6, -0.9, 1.2);
      cam->SetFocalPoint(0.25, 0.25, 0.05);
      cam->SetViewUp(0, 0, 1);
      scene.Renderer->ResetCameraClippingRange(); // from the padded (capped) bounds
      const double* b = scene.Mapper->GetBounds();
      PLUME_CHECK(std::isfinite(b[0]) && std::isfinite(b[1]) && b[1] - b[0] < 1e4);
      PLUME_CHECK(scene.Check(mode == 0 ? "huge_thin" : "huge_wide_lut", failures) > 20);
    }
  }

  // --- one-voxel-thick grids and a single node
  {
    const float v[3] = { 0.05f, 0.03f, 0.02f };
    const int shapes[4][3] = { { 9, 7, 1 }, { 9, 1, 1 }, { 1, 1, 1 }, { 1, 6, 5 } };
    for (const auto& shape : shapes)
    {
      auto image = MakeImage(shape[0], shape[1], shape[2], zero, unit, v);
      for (int integrator : { vtkPlumeVelocityGlyphMapper::STRAIGHT, vtkPlumeVelocityGlyphMapper::RK4 })
      {
        Scene scene(image);
        scene.Mapper->SetIntegrator(integrator);
        scene.Mapper->SetLineWidth(2.0);
        scene.Renderer->ResetCamera();
        scene.Renderer->GetActiveCamera()->Azimuth(30);
        scene.Renderer->GetActiveCamera()->Elevation(20);
        scene.Renderer->ResetCameraClippingRange();
        std::ostringstream name;
        name << "thin_" << shape[0] << "x" << shape[1] << "x" << shape[2] << "_"
             << (integrator ? "rk4" : "straight");
        const size_t fg = scene.Check(name.str().c_str(), failures);
        // streamlets ignore the component across a one-node-thick axis; a
        // single node has no room to integrate in
        const bool single = shape[0] * shape[1] * shape[2] == 1;
        if (integrator == vtkPlumeVelocityGlyphMapper::STRAIGHT || !single)
        {
          PLUME_CHECK(fg > 5);
        }
      }
    }
  }

  // --- anisotropic spacing 1e-3 vs 1e2
  {
    const double spacing[3] = { 1e-3, 1e2, 1.0 };
    const float v[3] = { 2e-3f, 50.0f, 0.3f };
    auto image = MakeImage(6, 6, 6, zero, spacing, v);
    Scene scene(image);
    scene.Mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
    scene.Mapper->SetScale(0.5);
    scene.Renderer->ResetCamera();
    const size_t fg = scene.Check("anisotropic", failures);
    PLUME_CHECK(fg > 50);
  }

  // --- far from the origin: same picture as at the origin with the camera shifted
  {
    plume::test::FloatImage images[2];
    for (int far = 0; far < 2; ++far)
    {
      const double shift = far ? 1e6 : 0.0;
      vtkNew<vtkPlumeVortexSource> vortex;
      vortex->SetDimensions(16, 16, 8);
      vortex->SetBounds(shift - 1, shift + 1, shift - 1, shift + 1, shift - 0.5, shift + 0.5);
      vortex->SetCenter(shift + 0.2, shift - 0.1, shift);
      vortex->Update();
      Scene scene(vortex->GetOutput(), 200);
      scene.Mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
      scene.Mapper->SetScale(0.3);
      scene.Mapper->SetLatticeStride(2);
      scene.Mapper->SetColorByMagnitude(true);
      scene.Mapper->SetLineWidth(far ? 1.0 : 1.0);
      vtkCamera* cam = scene.Renderer->GetActiveCamera();
      cam->SetPosition(shift + 0.8, shift - 2.5, shift + 2.0);
      cam->SetFocalPoint(shift, shift, shift);
      cam->SetViewUp(0, 0, 1);
      cam->SetClippingRange(0.5, 8.0);
      scene.Check(far ? "far_1e6" : "far_0", failures, &images[far]);
    }
    const plume::test::ImageError error = plume::test::Compare(images[0], images[1]);
    const double rms = error.RMS, maxDiff = error.Max;
    std::cout << "far vs origin: RMS " << rms << ", max " << maxDiff << "\n";
    PLUME_CHECK(plume::test::CountForeground(images[0], Background, 0.02) > 500);
    PLUME_CHECK(rms < 0.01);
  }

  // --- camera inside the data (thin and wide lines, streamlets)
  {
    vtkNew<vtkPlumeVortexSource> vortex;
    vortex->SetDimensions(20, 20, 20);
    vortex->Update();
    for (int mode = 0; mode < 3; ++mode)
    {
      Scene scene(vortex->GetOutput(), 200);
      scene.Mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
      scene.Mapper->SetScale(0.2);
      scene.Mapper->SetLineWidth(mode == 0 ? 1.0 : 3.0);
      scene.Mapper->SetIntegrator(mode == 2 ? vtkPlumeVelocityGlyphMapper::RK4 : vtkPlumeVelocityGlyphMapper::STRAIGHT);
      scene.Mapper->SetColorByMagnitude(true);
      vtkCamera* cam = scene.Renderer->GetActiveCamera();
      cam->SetPosition(0.3, -0.2, 0.1);
      cam->SetFocalPoint(-0.5, 0.6, 0.0);
      cam->SetViewUp(0, 0, 1);
      scene.Renderer->ResetCameraClippingRange();
      const char* names[3] = { "inside_thin", "inside_wide", "inside_rk4_wide" };
      PLUME_CHECK(scene.Check(names[mode], failures) > 2000);
    }
  }

  // --- depth compositing with opaque actors: a red square in front of the
  // left half of a glyph slab hides it; a blue square behind the right half
  // is drawn over by the glyphs (and the glyphs write depth)
  {
    const float v[3] = { 0.08f, 0.0f, 0.0f };
    const double origin[3] = { -1, -1, 0 };
    auto image = MakeImage(21, 21, 1, origin, unit, v);
    Scene scene(image, 200);
    scene.Mapper->SetLineWidth(2.0);
    vtkNew<vtkPlaneSource> front, back;
    front->SetOrigin(-1.2, -1.2, 0.3);
    front->SetPoint1(-0.05, -1.2, 0.3);
    front->SetPoint2(-1.2, 1.2, 0.3);
    back->SetOrigin(0.05, -1.2, -0.3);
    back->SetPoint1(1.2, -1.2, -0.3);
    back->SetPoint2(0.05, 1.2, -0.3);
    vtkNew<vtkPolyDataMapper> fm, bm;
    fm->SetInputConnection(front->GetOutputPort());
    bm->SetInputConnection(back->GetOutputPort());
    vtkNew<vtkActor> fa, ba;
    fa->SetMapper(fm);
    ba->SetMapper(bm);
    fa->GetProperty()->SetColor(1, 0, 0);
    ba->GetProperty()->SetColor(0, 0, 1);
    fa->GetProperty()->LightingOff();
    ba->GetProperty()->LightingOff();
    // opaque actors added after the glyph actor too: depth must still be right where it is opaque
    scene.Renderer->AddActor(fa);
    scene.Renderer->AddActor(ba);
    vtkCamera* cam = scene.Renderer->GetActiveCamera();
    cam->SetPosition(0, 0, 4);
    cam->SetFocalPoint(0, 0, 0);
    cam->SetViewUp(0, 1, 0);
    scene.Renderer->ResetCameraClippingRange();
    plume::test::FloatImage img;
    scene.Check("depth", failures, &img);
    size_t leftWhite = 0, rightWhite = 0, rightBlue = 0;
    for (int y = 20; y < 180; ++y)
    {
      for (int x = 10; x < 190; ++x)
      {
        const float* p = img.Pixel(x, y);
        const bool white = p[0] > 0.9 && p[1] > 0.9 && p[2] > 0.9;
        if (x < 90)
        {
          leftWhite += white ? 1 : 0;
        }
        else if (x > 110)
        {
          rightWhite += white ? 1 : 0;
          rightBlue += (p[2] > 0.9 && p[0] < 0.1) ? 1 : 0;
        }
      }
    }
    scene.Renderer->RemoveActor(fa);
    scene.Renderer->RemoveActor(ba);
    std::cout << "depth: glyph pixels behind the front square " << leftWhite << ", over the back square "
              << rightWhite << ", back square " << rightBlue << "\n";
    PLUME_CHECK(leftWhite == 0);
    PLUME_CHECK(rightWhite > 500);
    PLUME_CHECK(rightBlue > 1000);
  }

  // --- translucency: glyphs are blended whenever they are not fully opaque
  // (actor opacity, RootAlpha, or a table with alpha < 1), and drawn without
  // blending only when all three are opaque; an actor with opacity < 1 goes
  // through VTK's translucent pass, whichever it is (order-independent
  // transparency by default, or depth peeling). One white
  // glyph over black: its brightest pixel is its alpha.
  {
    const float v[3] = { 1, 0, 0 };
    auto image = MakeImage(1, 1, 1, zero, unit, v);
    Scene scene(image);
    scene.Mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
    scene.Mapper->SetScale(0.15);
    scene.Renderer->ResetCamera();
    auto brightest = [&](const std::string& name) {
      plume::test::FloatImage img;
      scene.Check(name.c_str(), failures, &img);
      float top = 0;
      for (size_t i = 0; i < img.RGBA.size(); i += 4)
      {
        top = std::max(top, img.RGBA[i]);
      }
      std::cout << name << ": brightest red " << top << "\n";
      return top;
    };
    PLUME_CHECK(std::fabs(brightest("opaque_solid") - 1.0f) < 0.01f);
    scene.Actor->GetProperty()->SetOpacity(0.5);
    for (int peeling = 0; peeling < 2; ++peeling)
    {
      scene.Renderer->SetUseDepthPeeling(peeling); // off: VTK's order-independent transparency
      PLUME_CHECK(std::fabs(brightest(peeling ? "opacity_half_peeling" : "opacity_half_oit") - 0.5f) < 0.01f);
    }
    scene.Renderer->SetUseDepthPeeling(false);
    scene.Actor->GetProperty()->SetOpacity(1.0);
    vtkNew<vtkLookupTable> table;
    table->SetSaturationRange(0, 0);
    table->SetValueRange(1, 1);
    table->SetAlphaRange(0.5, 0.5);
    table->Build();
    scene.Mapper->SetLookupTable(table);
    scene.Mapper->ColorByMagnitudeOn();
    PLUME_CHECK(std::fabs(brightest("table_alpha_half") - 0.5f) < 0.01f);
    table->SetAlphaRange(1, 1);
    table->ForceBuild();
    PLUME_CHECK(std::fabs(brightest("table_opaque") - 1.0f) < 0.01f);
  }

  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
