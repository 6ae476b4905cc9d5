// Valid-point mask (vtkResampleToImage's vtkValidPointMask): nodes outside
// the data draw nothing. A 32³ field valid for x <= 15 (index), masked and 0
// beyond, as resampling writes; the transfer function is hazy (opacity 0.3)
// at 0. Looking down z with a parallel projection, rays left of the boundary
// see only valid nodes and must match a volume cropped to them; rays right of
// it see only masked nodes and must draw nothing, while ignoring the mask
// (ValidMaskArrayName "") draws the haze there; composite, MIP, smoke and
// isosurface. Near the boundary no value from outside the data is blended in
// (an opacity that only values absent there have stays invisible), and editing
// the mask re-uploads.
#include "plumeVolumeTestUtil.h"

#include "vtkUnsignedCharArray.h"

namespace
{
vtkSmartPointer<vtkImageData> Field(int nx, bool withMask)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, 32, 32);
  image->SetSpacing(1.0 / 31, 1.0 / 31, 1.0 / 31);
  vtkNew<vtkFloatArray> v;
  v->SetName("v");
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName("vtkValidPointMask");
  for (int k = 0; k < 32; ++k)
  {
    for (int j = 0; j < 32; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        const bool valid = i <= 15;
        const double x = i / 31.0, y = j / 31.0, z = k / 31.0;
        v->InsertNextValue(valid ? static_cast<float>(1.0 + 0.5 * std::sin(6 * x + 4 * y) * std::cos(5 * z)) : 0.0f);
        mask->InsertNextValue(valid ? 1 : 0);
      }
    }
  }
  image->GetPointData()->SetScalars(v);
  if (withMask)
  {
    image->GetPointData()->AddArray(mask);
  }
  return image;
}

// mean RGB difference of two images over the pixels whose centre lies at world x in [x0, x1)
double MeanDifference(const plume::test::FloatImage& a, const plume::test::FloatImage& b, vtkRenderer* ren,
  double x0, double x1)
{
  double sum = 0;
  int count = 0;
  for (int y = 0; y < a.Height; ++y)
  {
    for (int x = 0; x < a.Width; ++x)
    {
      ren->SetDisplayPoint(x + 0.5, y + 0.5, 0.5);
      ren->DisplayToWorld();
      double w[4];
      ren->GetWorldPoint(w);
      const double wx = w[0] / w[3], wy = w[1] / w[3];
      if (wx < x0 || wx >= x1 || wy < 0.05 || wy > 0.95)
      {
        continue;
      }
      for (int c = 0; c < 3; ++c)
      {
        sum += std::fabs(a.Pixel(x, y)[c] - b.Pixel(x, y)[c]);
      }
      ++count;
    }
  }
  return count ? sum / count : -1.0;
}
}

int TestVolumeMask(int, char*[])
{
  using namespace plumevolumetest;
  int failures = 0;
  auto configure = [](Scene& s) {
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.0, 0.9, 0.9, 0.9);
    color->AddRGBPoint(1.5, 1.0, 0.6, 0.2);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.3); // haze at 0: what the masked zeros would show
    opacity->AddPoint(1.5, 0.6);
    vtkVolumeProperty* p = s.Volume->GetProperty();
    p->SetColor(color);
    p->SetScalarOpacity(opacity);
    p->SetScalarOpacityUnitDistance(0.2);
    p->SetInterpolationTypeToLinear();
    vtkCamera* c = s.Renderer->GetActiveCamera();
    c->ParallelProjectionOn();
    c->SetFocalPoint(0.5, 0.5, 0.5);
    c->SetPosition(0.5, 0.5, 3.0);
    c->SetViewUp(0, 1, 0);
    c->SetParallelScale(0.55);
    c->SetClippingRange(1.0, 5.0);
  };
  Scene full = MakeScene(Field(32, true), 120, 120);
  Scene crop = MakeScene(Field(16, false), 120, 120); // nodes 0..15: the valid ones
  configure(full);
  configure(crop);
  const double boundary = 15.0 / 31.0;
  full.Volume->SetVisibility(false);
  const auto background = plume::test::ReadBack(full.Window); // (as read back: 8-bit)
  full.Volume->SetVisibility(true);

  for (int mip = 0; mip < 2; ++mip)
  {
    for (Scene* s : { &full, &crop })
    {
      if (mip)
      {
        s->Mapper->SetBlendModeToMaximumIntensity();
      }
    }
    full.Mapper->SetValidMaskArrayName("vtkValidPointMask");
    const auto masked = plume::test::ReadBack(full.Window);
    const auto cropped = plume::test::ReadBack(crop.Window);
    full.Mapper->SetValidMaskArrayName("");
    const auto ignored = plume::test::ReadBack(full.Window);
    const char* mode = mip ? "MIP" : "composite";

    // left of the boundary (away from the last cell): the cropped volume's image
    double diff = 0, maxDiff = 0;
    int n = 0;
    for (int y = 0; y < masked.Height; ++y)
    {
      for (int x = 0; x < masked.Width; ++x)
      {
        full.Renderer->SetDisplayPoint(x + 0.5, y + 0.5, 0.5);
        full.Renderer->DisplayToWorld();
        double w[4];
        full.Renderer->GetWorldPoint(w);
        if (w[0] / w[3] > boundary - 1.5 / 31 || w[0] / w[3] < 0.02)
        {
          continue;
        }
        for (int c = 0; c < 3; ++c)
        {
          const double d = std::fabs(masked.Pixel(x, y)[c] - cropped.Pixel(x, y)[c]);
          diff += d * d;
          maxDiff = std::max(maxDiff, d);
          ++n;
        }
      }
    }
    const double rms = n ? std::sqrt(diff / n) : 1.0;
    const double right = MeanDifference(masked, background, full.Renderer, boundary + 1.5 / 31, 0.98);
    const double hazeRight = MeanDifference(ignored, background, full.Renderer, boundary + 1.5 / 31, 0.98);
    const double left = MeanDifference(masked, background, full.Renderer, 0.02, boundary - 1.5 / 31);
    std::printf("%s: valid side vs cropped RMS %.5f max %.5f (%d values); masked side %.5f (mask ignored: %.4f); "
                "valid side %.4f\n",
      mode, rms, maxDiff, n, right, hazeRight, left);
    PLUME_CHECK(n > 1000);
    PLUME_CHECK(rms < 0.004 && maxDiff < 0.02); // table steps differ by one entry (1/1023 of the range)
    PLUME_CHECK(right == 0.0);                    // nothing written outside the data
    PLUME_CHECK(hazeRight > 0.05);                // ... where the zeros would show haze
    PLUME_CHECK(left > 0.1);                      // and the data is drawn
    PLUME_CHECK(!plume::test::HasNonFinite(masked));
    PLUME_CHECK(plume::test::GLErrors(full.Window).empty());
  }

  // smoke and isosurface modes: the masked side stays empty, no NaN, no GL error
  for (int m = 0; m < 2; ++m)
  {
    full.Mapper->SetBlendModeToComposite();
    full.Mapper->SetSmoke(m == 0);
    if (m == 1)
    {
      full.Mapper->SetBlendModeToIsoSurface();
      full.Mapper->SetIsoValue(1.2);
    }
    full.Mapper->SetValidMaskArrayName("vtkValidPointMask");
    const auto img = plume::test::ReadBack(full.Window);
    const double right = MeanDifference(img, background, full.Renderer, boundary + 1.5 / 31, 0.98);
    const double left = MeanDifference(img, background, full.Renderer, 0.02, boundary - 1.5 / 31);
    std::printf("%s: masked side %.5f, valid side %.4f\n", m == 0 ? "smoke" : "isosurface", right, left);
    PLUME_CHECK(right == 0.0 && left > 0.05);
    PLUME_CHECK(!plume::test::HasNonFinite(img));
    PLUME_CHECK(plume::test::GLErrors(full.Window).empty());
  }
  full.Mapper->SetSmoke(false);
  full.Mapper->SetBlendModeToComposite();

  // no values from outside the data near its boundary: valid nodes are 1.5 (one
  // far corner 0.5, for the range) and only values below 0.6 are opaque; blending
  // the outside's zeros into the last cell would sweep through them (an opaque wall)
  {
    vtkDataArray* v = full.Image->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < v->GetNumberOfTuples(); ++i)
    {
      v->SetTuple1(i, (i % 32) <= 15 ? 1.5 : 0.0);
    }
    v->SetTuple1(0, 0.5);
    v->Modified();
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.5, 0.9);
    opacity->AddPoint(0.6, 0.9);
    opacity->AddPoint(0.7, 0.0);
    opacity->AddPoint(1.5, 0.0);
    full.Volume->GetProperty()->SetScalarOpacity(opacity);
    // nearly opaque per 1/1000 of the box: even a faint weight would show
    full.Volume->GetProperty()->SetScalarOpacityUnitDistance(0.001);
    for (int skip = 0; skip < 2; ++skip) // without skipping every boundary cell is sampled
    {
      full.Mapper->SetEmptySpaceSkipping(skip == 1);
      const auto img = plume::test::ReadBack(full.Window);
      const double wall = MeanDifference(img, background, full.Renderer, boundary - 1.5 / 31, boundary + 1.5 / 31);
      std::printf("boundary cells, opacity only below the data near them, skipping %s: %.5f\n", skip ? "on" : "off", wall);
      PLUME_CHECK(wall == 0.0);
    }
  }

  // isosurface across a gap in the data: below the iso value before it, above
  // after it; no crossing has two samples with valid nodes around, so nothing
  // is drawn, with empty-space skipping (which jumps the gap's blocks) or without
  {
    auto gap = Field(32, true);
    vtkDataArray* v = gap->GetPointData()->GetScalars();
    vtkDataArray* m = gap->GetPointData()->GetArray("vtkValidPointMask");
    for (vtkIdType id = 0; id < v->GetNumberOfTuples(); ++id)
    {
      const int i = static_cast<int>(id % 32);
      v->SetTuple1(id, i <= 8 ? 0.5 : (i >= 25 ? 1.5 : 0.0));
      m->SetTuple1(id, i <= 8 || i >= 25 ? 1 : 0);
    }
    Scene g = MakeScene(gap, 96, 96);
    configure(g);
    vtkCamera* c = g.Renderer->GetActiveCamera();
    c->SetPosition(-3.0, 0.5, 0.5); // rays along +x: through the low part, the gap, the high part
    c->SetViewUp(0, 0, 1);
    g.Mapper->SetBlendModeToIsoSurface();
    g.Mapper->SetIsoValue(1.0);
    g.Volume->SetVisibility(false);
    const auto empty = plume::test::ReadBack(g.Window);
    g.Volume->SetVisibility(true);
    for (int skip = 0; skip < 2; ++skip)
    {
      g.Mapper->SetEmptySpaceSkipping(skip == 1);
      const auto img = plume::test::ReadBack(g.Window);
      const double drawn = plume::test::Compare(img, empty).Max;
      std::printf("isosurface across a gap, skipping %s: largest difference from the empty frame %.4f\n",
        skip ? "on" : "off", drawn);
      PLUME_CHECK(drawn == 0.0);
      PLUME_CHECK(plume::test::GLErrors(g.Window).empty());
    }
  }

  // editing the mask re-uploads: with every node valid the masked side shows the zeros' haze
  {
    full.Mapper->SetBlendModeToComposite();
    full.Mapper->SetValidMaskArrayName("vtkValidPointMask");
    const int uploads = full.Mapper->GetUploadCount();
    vtkDataArray* mask = full.Image->GetPointData()->GetArray("vtkValidPointMask");
    mask->Fill(1);
    mask->Modified();
    const auto all = plume::test::ReadBack(full.Window);
    const double right = MeanDifference(all, background, full.Renderer, boundary + 1.5 / 31, 0.98);
    std::printf("mask all ones: masked side %.4f, uploads %d -> %d\n", right, uploads, full.Mapper->GetUploadCount());
    PLUME_CHECK(full.Mapper->GetUploadCount() == uploads + 1);
    PLUME_CHECK(right > 0.05);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
