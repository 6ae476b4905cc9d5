// Numeric test (no baseline): straight glyphs of the analytic vortex land where
// the double-precision CPU projection of p + Scale·v(p) says, and their colour
// is the lookup-table colour of |v(p)|; for 1-pixel lines through both shader
// paths (vertex shader GL_LINES, geometry shader), then for wide quads.
// Then, on a dense overlapping 3D lattice: both paths, and draws split into
// small chunks, give the same image.
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkPlumeVortexSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "plumeGlyphTestUtil.h"

int TestVelocityGlyphAccuracy(int, char*[])
{
  int failures = 0;
  // a single sparse z-slab, so glyphs do not overlap on screen
  vtkNew<vtkPlumeVortexSource> vortex;
  vortex->SetDimensions(7, 6, 1);
  vortex->SetBounds(-1.2, 1.2, -1, 1, 0.1, 0.1);
  vortex->SetCenter(0.2, -0.1, 0);
  vortex->SetCoreRadius(0.6);
  vortex->Update();
  vtkImageData* image = vortex->GetOutput();

  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.0, 0.7);
  lut->Build();

  vtkNew<vtkPlumeVelocityGlyphMapper> mapper;
  mapper->SetInputData(image);
  mapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
  mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
  mapper->SetScale(0.45);
  mapper->SetRootAlpha(1.0);
  mapper->SetLookupTable(lut);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);

  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0, 0, 0);
  ren->AddActor(actor);
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetPosition(0.5, -2.0, 4.0);
  cam->SetFocalPoint(0, 0, 0);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(40);
  ren->ResetCameraClippingRange();
  auto window = plume::test::MakeOffscreenWindow(320, 300);
  window->AddRenderer(ren);

  // pass 0: 1-px lines, vertex shader path; 1: 1-px lines, geometry shader
  // path; 2: wide (quad) glyphs, which must end at the same tip
  const char* passNames[3] = { "1-px lines, vertex shader", "1-px lines, geometry shader",
    "3-px quads" };
  size_t coverage[3] = { 0, 0, 0 };
  for (int pass = 0; pass < 3; ++pass)
  {
    mapper->SetStraightLineShader(pass == 1 ? vtkPlumeVelocityGlyphMapper::GEOMETRY_SHADER
                                            : vtkPlumeVelocityGlyphMapper::VERTEX_SHADER);
    mapper->SetLineWidth(pass == 2 ? 3.0 : 1.0);
    const plume::test::FloatImage img = plume::test::ReadBack(window);
    PLUME_CHECK(!plume::test::HasNonFinite(img));
    const double black[3] = { 0, 0, 0 };
    coverage[pass] = plume::test::CountForeground(img, black, 0.05);
    PLUME_CHECK(plume::test::GLErrors(window).empty());

    // CPU reference: double precision, from the exact field
    double range[2] = { VTK_DOUBLE_MAX, 0 };
    for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
    {
      double v[3];
      vortex->Evaluate(image->GetPoint(i), v);
      const double s = std::sqrt(double(float(v[0])) * float(v[0]) +
        double(float(v[1])) * float(v[1]) + double(float(v[2])) * float(v[2]));
      range[0] = std::min(range[0], s);
      range[1] = std::max(range[1], s);
    }
    lut->SetRange(range);
    int checked = 0, bad = 0;
    double worstTip = 0, worstColor = 0;
    const double bg[3] = { 0, 0, 0 };
    for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
    {
      double p[3], v[3], tip[3], rgb[3];
      image->GetPoint(i, p);
      vortex->Evaluate(p, v);
      for (int a = 0; a < 3; ++a)
      {
        tip[a] = p[a] + mapper->GetScale() * v[a];
      }
      lut->GetColor(vtkMath::Norm(v), rgb);
      // 1-px lines: GL's diamond-exit rule omits the last fragment, so the last
      // drawn pixel centre can be up to ~1.7 px short of the exact tip. Quads
      // (pass 2) cover the tip exactly: 1 px.
      const double tolerance = pass < 2 ? 1.75 : 1.0;
      const plumetest::TipResult res = plumetest::MeasureTip(ren, img, p, tip, bg);
      if (!res.Valid)
      {
        continue;
      }
      ++checked;
      double colorError = 1;
      if (res.HasMid)
      {
        colorError = std::max({ std::fabs(res.MidColor[0] - rgb[0]),
          std::fabs(res.MidColor[1] - rgb[1]), std::fabs(res.MidColor[2] - rgb[2]) });
      }
      worstTip = std::max(worstTip, std::fabs(res.Reach));
      worstColor = std::max(worstColor, colorError);
      if (std::fabs(res.Reach) > tolerance || res.Beyond > 0 || colorError > 0.03)
      {
        ++bad;
        std::cerr << "glyph at node " << i << ": drawn line ends " << res.Reach
                  << " px from the projected tip (length " << res.Length << " px), " << res.Beyond
                  << " pixels beyond the tip, colour error " << colorError << "\n";
      }
    }
    std::cout << passNames[pass] << ": checked " << checked << " glyphs, worst tip error "
              << worstTip << " px, worst colour error " << worstColor << "\n";
    PLUME_CHECK(checked >= 35);
    PLUME_CHECK(bad == 0);
  }
  // 3-px quads cover about three times the pixels of 1-px lines
  const double ratio = double(coverage[2]) / std::max<size_t>(1, coverage[0]);
  std::cout << "coverage 3 px / 1 px: " << ratio << "\n";
  PLUME_CHECK(ratio > 2.4 && ratio < 3.6);
  PLUME_CHECK(coverage[0] == coverage[1]);

  // Dense 3D lattice (overlapping, blended, partly off screen): the vertex
  // shader path, the geometry shader path and chunked draws agree.
  {
    vtkNew<vtkPlumeVortexSource> dense;
    dense->SetDimensions(24, 22, 20);
    dense->Update();
    vtkNew<vtkPlumeVelocityGlyphMapper> denseMapper;
    denseMapper->SetInputData(dense->GetOutput());
    denseMapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
    denseMapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
    denseMapper->SetScale(0.3);
    actor->SetMapper(denseMapper);
    ren->ResetCamera();
    ren->GetActiveCamera()->Zoom(1.6); // some glyphs leave the view
    ren->GetActiveCamera()->Azimuth(25);
    ren->GetActiveCamera()->Elevation(15);
    ren->ResetCameraClippingRange();
    struct Variant
    {
      const char* Name;
      int Shader;
      vtkIdType Chunk;
    };
    const Variant variants[] = { { "vertex shader", vtkPlumeVelocityGlyphMapper::VERTEX_SHADER, 0 },
      { "geometry shader", vtkPlumeVelocityGlyphMapper::GEOMETRY_SHADER, 0 },
      { "vertex shader, 1000 per draw", vtkPlumeVelocityGlyphMapper::VERTEX_SHADER, 1000 },
      { "geometry shader, 777 per draw", vtkPlumeVelocityGlyphMapper::GEOMETRY_SHADER, 777 } };
    plume::test::FloatImage reference, gsImage;
    const double black[3] = { 0, 0, 0 };
    for (const Variant& variant : variants)
    {
      denseMapper->SetStraightLineShader(variant.Shader);
      denseMapper->SetMaximumGlyphsPerDraw(variant.Chunk);
      const plume::test::FloatImage img = plume::test::ReadBack(window);
      PLUME_CHECK(plume::test::GLErrors(window).empty());
      PLUME_CHECK(!plume::test::HasNonFinite(img));
      const size_t fg = plume::test::CountForeground(img, black);
      if (&variant == variants)
      {
        reference = img;
        std::cout << "dense lattice: " << fg << " foreground pixels\n";
        PLUME_CHECK(fg > 20000);
        continue;
      }
      const plume::test::ImageError error = plume::test::Compare(reference, img, 4);
      size_t differing = 0;
      for (size_t i = 0; i < img.RGBA.size(); i += 4)
      {
        differing += std::equal(&img.RGBA[i], &img.RGBA[i] + 4, &reference.RGBA[i]) ? 0 : 1;
      }
      std::cout << "dense lattice, " << variant.Name << " vs vertex shader: RMS " << error.RMS
                << ", max " << error.Max << ", " << differing << " pixels differ\n";
      // Same vertices, same order. The two pipelines differ only in rounding
      // (a few channels by one 8-bit step where lines overlap); chunked draws
      // of one path are identical to its single draw.
      PLUME_CHECK(error.Max <= 1.5 / 255.0);
      PLUME_CHECK(differing <= fg / 1000);
      if (variant.Shader == vtkPlumeVelocityGlyphMapper::VERTEX_SHADER)
      {
        PLUME_CHECK(error.Max == 0.0);
      }
      else if (variant.Chunk == 0)
      {
        gsImage = img;
      }
      else
      {
        PLUME_CHECK(gsImage.RGBA == img.RGBA); // chunked geometry shader draws: identical
      }
    }
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
