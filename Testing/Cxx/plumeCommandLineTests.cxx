// Unit tests (GoogleTest) for the command line's CPU-side pieces: strict
// scene parameters, window depth → distance for EXR, colour maps.
#include "plumeColorMaps.h"
#include "plumeImageOutput.h"
#include "plumeParameters.h"
#include "plumeRepresentationHelpers.h"
#include "plumeSceneError.h"

#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkScalarsToColors.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using nlohmann::json;

TEST(Parameters, ReadsTypedValuesWithDefaults)
{
  const json j = json::parse(R"({"scale": 2.5, "segments": 4, "on": true, "name": "x",
                                 "color": [0.1, 0.2, 0.3], "mode": "rk4"})");
  plume::Parameters p(j, "rep");
  EXPECT_DOUBLE_EQ(p.Number("scale", 1.0), 2.5);
  EXPECT_EQ(p.Integer("segments", 8, 1, 32), 4);
  EXPECT_TRUE(p.Boolean("on", false));
  EXPECT_EQ(p.String("name", ""), "x");
  EXPECT_EQ(p.Choice("mode", "straight", { "straight", "rk2", "rk4" }), "rk4");
  const auto c = p.Vector<3>("color", { 1, 1, 1 });
  EXPECT_DOUBLE_EQ(c[1], 0.2);
  EXPECT_DOUBLE_EQ(p.Number("absent", 7.0), 7.0);
  EXPECT_NO_THROW(p.RejectUnknown());
}

TEST(Parameters, RejectsUnknownKeysNamingThem)
{
  const json j = json::parse(R"({"scale": 1, "scal": 2})");
  plume::Parameters p(j, "representations[0] (glyphs)");
  p.Number("scale", 1.0);
  try
  {
    p.RejectUnknown();
    FAIL() << "unknown key accepted";
  }
  catch (const plume::SceneError& e)
  {
    EXPECT_NE(std::string(e.what()).find("unknown parameter 'scal'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("representations[0] (glyphs)"), std::string::npos) << e.what();
  }
}

TEST(Parameters, RejectsWrongTypesAndRanges)
{
  const json j = json::parse(R"({"a": "big", "b": 40, "c": 1.5, "d": [1, "x", 3], "e": "rk9", "f": [1, 2]})");
  plume::Parameters p(j, "rep");
  EXPECT_THROW(p.Number("a", 1.0), plume::SceneError);
  EXPECT_THROW(p.Integer("b", 8, 1, 32), plume::SceneError);
  EXPECT_THROW(p.Integer("c", 8, 1, 32), plume::SceneError);
  EXPECT_THROW((p.Vector<3>("d", { 0, 0, 0 })), plume::SceneError);
  EXPECT_THROW(p.Choice("e", "straight", { "straight", "rk2", "rk4" }), plume::SceneError);
  EXPECT_THROW((p.Vector<3>("f", { 0, 0, 0 })), plume::SceneError);
  EXPECT_THROW(plume::Parameters(json::array(), "x"), plume::SceneError);
}

namespace
{
/** Window depth of a point at distance `d` in front of the camera, through VTK's own projection. */
double WindowDepth(vtkCamera* camera, double d)
{
  vtkNew<vtkMatrix4x4> m;
  m->DeepCopy(camera->GetCompositeProjectionTransformMatrix(1.0, -1, 1));
  double fp[3], pos[3], dir[3];
  camera->GetFocalPoint(fp);
  camera->GetPosition(pos);
  camera->GetDirectionOfProjection(dir);
  double p[4] = { pos[0] + d * dir[0], pos[1] + d * dir[1], pos[2] + d * dir[2], 1.0 };
  double clip[4];
  m->MultiplyPoint(p, clip);
  return 0.5 * (clip[2] / clip[3]) + 0.5;
}
}

TEST(LinearDepth, InvertsThePerspectiveProjection)
{
  vtkNew<vtkCamera> camera;
  camera->SetPosition(1, 2, 10);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetClippingRange(0.5, 40);
  for (double d : { 0.5, 1.0, 3.3, 10.0, 25.0, 40.0 })
  {
    EXPECT_NEAR(plume::LinearDepth(WindowDepth(camera, d), camera), d, 1e-6 * d) << d;
  }
  EXPECT_TRUE(std::isinf(plume::LinearDepth(1.0, camera)));
}

TEST(LinearDepth, InvertsTheParallelProjection)
{
  vtkNew<vtkCamera> camera;
  camera->ParallelProjectionOn();
  camera->SetPosition(0, 0, 10);
  camera->SetClippingRange(2, 30);
  for (double d : { 2.0, 7.5, 29.0 })
  {
    EXPECT_NEAR(plume::LinearDepth(WindowDepth(camera, d), camera), d, 1e-9 * d) << d;
  }
}

TEST(ColorMaps, SpanTheRequestedRangeWithTheirEndColours)
{
  for (const auto& name : plume::ColorMapNames())
  {
    auto map = plume::MakeColorMap(name, -2, 6);
    ASSERT_NE(map, nullptr) << name;
    const double* range = map->GetRange();
    EXPECT_DOUBLE_EQ(range[0], -2) << name;
    EXPECT_DOUBLE_EQ(range[1], 6) << name;
  }
  double low[3], high[3];
  plume::MakeColorMap("grayscale", 0, 1)->GetColor(0.0, low);
  plume::MakeColorMap("grayscale", 0, 1)->GetColor(1.0, high);
  EXPECT_NEAR(low[0], 0, 1e-9);
  EXPECT_NEAR(high[0], 1, 1e-9);
  EXPECT_EQ(plume::MakeColorMap("nope", 0, 1), nullptr);
}

TEST(Coloring, DefaultRangeLeavesOutMaskedPoints)
{
  // resampled data: 0 at points outside it (mask 0) must not widen the range
  vtkNew<vtkFloatArray> values;
  vtkNew<vtkUnsignedCharArray> mask;
  for (float v : { 0.0f, 5.0f, 7.0f, 10.0f, 0.0f })
  {
    values->InsertNextValue(v);
    mask->InsertNextValue(v != 0.0f ? 1 : 0);
  }
  plume::Coloring coloring;
  coloring.Map = "grayscale";
  coloring.Verbose = false;
  // 1-99 % percentiles, rank q (n - 1) interpolated: valid {5, 7, 10} ->
  // ranks 0.02 and 1.98 -> 5 + 0.02 * 2 and 7 + 0.98 * 3
  const auto masked = coloring.Table(values, 0, mask);
  EXPECT_NEAR(masked->GetRange()[0], 5.04, 1e-12);
  EXPECT_NEAR(masked->GetRange()[1], 9.94, 1e-12);
  // all {0, 0, 5, 7, 10} -> ranks 0.04 and 3.96
  const auto plain = coloring.Table(values, 0);
  EXPECT_NEAR(plain->GetRange()[0], 0, 1e-12);
  EXPECT_NEAR(plain->GetRange()[1], 7 + 0.96 * 3, 1e-12);
}

TEST(Coloring, DefaultRangeIgnoresOutliersAndNonFiniteValues)
{
  // 0..999 plus one huge outlier, a NaN and an Inf: the range must follow the
  // bulk ([10, 990]: ranks 10 and 990 of the 1001 finite values), not [0, 1e6]
  vtkNew<vtkFloatArray> values;
  for (int i = 0; i < 1000; ++i)
  {
    values->InsertNextValue(static_cast<float>(i));
  }
  values->InsertNextValue(1e6f);
  values->InsertNextValue(std::numeric_limits<float>::quiet_NaN());
  values->InsertNextValue(std::numeric_limits<float>::infinity());
  plume::Coloring coloring;
  coloring.Map = "viridis";
  coloring.Verbose = false;
  const auto table = coloring.Table(values, 0);
  EXPECT_NEAR(table->GetRange()[0], 10, 1e-9);
  EXPECT_NEAR(table->GetRange()[1], 990, 1e-9);
  std::array<double, 2> extremes;
  size_t count = 0;
  plume::Coloring::RobustRange(values, 0, nullptr, &extremes, &count);
  EXPECT_EQ(count, 1001u);
  EXPECT_DOUBLE_EQ(extremes[1], 1e6);

  // magnitude of 3-component vectors: the same bulk along x
  vtkNew<vtkFloatArray> vectors;
  vectors->SetNumberOfComponents(3);
  for (int i = 0; i < 1000; ++i)
  {
    vectors->InsertNextTuple3(0, -double(i), 0);
  }
  vectors->InsertNextTuple3(1e6, 0, 0);
  const auto magnitude = coloring.Table(vectors, -1);
  EXPECT_NEAR(magnitude->GetRange()[0], 10, 1e-9);
  EXPECT_NEAR(magnitude->GetRange()[1], 990, 1e-9);

  // an explicit range is kept as given
  coloring.HasRange = true;
  coloring.Range = { -1, 2e6 };
  EXPECT_DOUBLE_EQ(coloring.Table(values, 0)->GetRange()[1], 2e6);
}

TEST(Coloring, ConstantBulkFallsBackToTheExtremes)
{
  // 99.9 % of the values equal: the percentiles coincide, so the few others
  // decide the range instead of an empty one
  vtkNew<vtkFloatArray> values;
  for (int i = 0; i < 1000; ++i)
  {
    values->InsertNextValue(300.0f);
  }
  values->InsertNextValue(301.5f);
  const auto range = plume::Coloring::RobustRange(values, 0, nullptr);
  EXPECT_DOUBLE_EQ(range[0], 300.0);
  EXPECT_DOUBLE_EQ(range[1], 301.5);
}

TEST(Coloring, RoundingResidueIsZero)
{
  // speeds at walls that should be 0 but carry interpolation residue (the
  // kitchen's 1 % percentile was 9.15e-19): the range starts at 0; a small
  // but real value (1e-6 of the range) is kept
  vtkNew<vtkDoubleArray> speeds;
  for (int i = 0; i < 50; ++i)
  {
    speeds->InsertNextValue(1e-18 * i);
  }
  for (int i = 0; i < 950; ++i)
  {
    speeds->InsertNextValue(0.2 * i / 949.0);
  }
  const auto range = plume::Coloring::RobustRange(speeds, 0, nullptr);
  EXPECT_EQ(range[0], 0.0);
  EXPECT_NEAR(range[1], 0.2 * 0.99, 0.01);
  vtkNew<vtkDoubleArray> offset;
  for (int i = 0; i < 1000; ++i)
  {
    offset->InsertNextValue(1e-6 + 0.2 * i / 999.0);
  }
  EXPECT_GT(plume::Coloring::RobustRange(offset, 0, nullptr)[0], 1e-6);
}

TEST(TextColor, ReadableOnAnyBackground)
{
  // dark text on light backgrounds, light text on dark ones (WCAG contrast)
  const double white[3] = { 1, 1, 1 }, paper[3] = { 0.92, 0.92, 0.88 }, grey[3] = { 0.5, 0.5, 0.5 },
               yellow[3] = { 1, 1, 0 }, dark[3] = { 0.1, 0.1, 0.12 }, blue[3] = { 0, 0, 1 }, black[3] = { 0, 0, 0 };
  for (const double* light : { white, paper, grey, yellow })
  {
    EXPECT_LT(plume::TextColorOn(light)[0], 0.5) << light[0] << " " << light[1] << " " << light[2];
  }
  for (const double* deep : { dark, blue, black })
  {
    EXPECT_GT(plume::TextColorOn(deep)[0], 0.5) << deep[0] << " " << deep[1] << " " << deep[2];
  }
}
