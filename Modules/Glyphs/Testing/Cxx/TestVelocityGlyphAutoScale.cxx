// ScaleMode SCALE_AUTO: the scale makes a glyph at the robust maximum speed
// (99th percentile of the valid speeds) span two root spacings, i.e. two
// cells times the effective stride (lattice: LatticeStride; screen-adaptive:
// the frame's stride, here 4, so the glyphs keep their length on screen;
// with the stride left out, screen roots drew a third of that). Checked
// against a double-precision reference (a full sort, no code shared with the
// mapper's vtkPlumePercentile) on a field with an outlier, a masked node and
// a NaN; the bounds and the drawn image must use that scale: the auto render
// equals a fixed render at the reference scale and differs from Scale 1.
// SCALE_AUTO is the default; AutomaticScaleSpeed replaces the robust speed;
// ComputeRobustMaximumSpeed over a sub-extent equals the reference over it.
#include "plumeTestSupport.h"
#include "vtkPlumeVelocityGlyphMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace
{
constexpr int NX = 12, NY = 10, NZ = 2;
constexpr double Spacing = 0.25;

// speeds 0.01 * (1 + i mod 97) along a rotating direction; node 5 is a large
// outlier, node 7 is masked (and huge), node 11 is NaN
vtkSmartPointer<vtkImageData> MakeField()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(NX, NY, NZ);
  image->SetSpacing(Spacing, Spacing, 0.5 * Spacing);
  vtkNew<vtkFloatArray> v;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName("vtkValidPointMask");
  const vtkIdType n = image->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double s = 0.01 * double(1 + i % 97);
    const double a = 0.37 * double(i);
    double t[3] = { s * std::cos(a), s * std::sin(a), 0.0 };
    if (i == 5 || i == 7)
    {
      t[0] = 10.0;
    }
    if (i == 11)
    {
      t[1] = std::numeric_limits<double>::quiet_NaN();
    }
    v->InsertNextTuple(t);
    mask->InsertNextValue(i == 7 ? 0 : 1);
  }
  image->GetPointData()->AddArray(v);
  image->GetPointData()->SetVectors(v);
  image->GetPointData()->AddArray(mask);
  return image;
}

// over the nodes with x index < xEnd
double ReferenceRobustSpeed(vtkImageData* image, int xEnd = NX)
{
  vtkDataArray* v = image->GetPointData()->GetArray("v");
  vtkDataArray* mask = image->GetPointData()->GetArray("vtkValidPointMask");
  std::vector<double> speeds;
  for (vtkIdType i = 0; i < v->GetNumberOfTuples(); ++i)
  {
    const double* t = v->GetTuple3(i);
    const double s = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    if (mask->GetComponent(i, 0) != 0 && std::isfinite(s) && i % NX < xEnd)
    {
      speeds.push_back(s);
    }
  }
  std::sort(speeds.begin(), speeds.end());
  return speeds[static_cast<size_t>(std::floor(0.99 * double(speeds.size() - 1)))];
}

// roots: a lattice of every node, or screen-adaptive with a spacing that
// gives stride 4 in this view (`stride`: the stride drawn)
plume::test::FloatImage Draw(
  vtkImageData* image, int scaleMode, double scale, bool screen = false, int* stride = nullptr)
{
  vtkNew<vtkLookupTable> lut;
  lut->Build();
  vtkNew<vtkPlumeVelocityGlyphMapper> mapper;
  mapper->SetInputData(image);
  mapper->SetRootMode(
    screen ? vtkPlumeVelocityGlyphMapper::ROOTS_SCREEN_ADAPTIVE : vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
  mapper->SetScreenSpacing(40.0);
  mapper->SetScaleMode(scaleMode);
  mapper->SetScale(scale);
  mapper->SetLookupTable(lut);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0, 0, 0);
  ren->AddActor(actor);
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetFocalPoint(1.4, 1.1, 0);
  cam->SetPosition(1.4, 1.1, 8);
  cam->SetViewUp(0, 1, 0);
  ren->ResetCameraClippingRange();
  auto window = plume::test::MakeOffscreenWindow(200, 160);
  window->AddRenderer(ren);
  auto frame = plume::test::ReadBack(window);
  if (stride)
  {
    *stride = mapper->GetEffectiveStride();
  }
  return frame;
}
}

int TestVelocityGlyphAutoScale(int, char*[])
{
  int failures = 0;
  auto image = MakeField();
  const double robust = ReferenceRobustSpeed(image);

  vtkNew<vtkPlumeVelocityGlyphMapper> mapper;
  mapper->SetInputData(image);
  mapper->SetVectorArrayName("v");
  mapper->SetScale(0.7);
  if (mapper->GetScaleMode() != vtkPlumeVelocityGlyphMapper::SCALE_AUTO)
  {
    std::printf("FAIL: the default mode is not auto\n");
    ++failures;
  }
  mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
  if (mapper->GetEffectiveScale() != 0.7)
  {
    std::printf("FAIL: fixed mode does not draw at Scale (%g)\n", mapper->GetEffectiveScale());
    ++failures;
  }
  mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_AUTO);
  const double speed = mapper->GetRobustMaximumSpeed();
  if (std::fabs(speed - robust) > 1e-6 * robust)
  {
    std::printf("FAIL: robust maximum speed %.9g, reference %.9g\n", speed, robust);
    ++failures;
  }
  // two grid cells (the largest spacing) at the robust speed per node of
  // root stride; screen roots before any render: stride 1
  const double screenScale = 2.0 * Spacing / robust;
  if (std::fabs(mapper->GetEffectiveScale() - screenScale) > 1e-6 * screenScale ||
    std::fabs(mapper->GetAutomaticScale(4) - 4.0 * screenScale) > 1e-6 * screenScale)
  {
    std::printf("FAIL: auto scale %.9g (stride 4: %.9g), expected %.9g per node of stride\n",
      mapper->GetEffectiveScale(), mapper->GetAutomaticScale(4), screenScale);
    ++failures;
  }
  mapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
  mapper->SetLatticeStride(3);
  const double latticeScale = 3.0 * screenScale;
  if (std::fabs(mapper->GetEffectiveScale() - latticeScale) > 1e-6 * latticeScale)
  {
    std::printf("FAIL: auto scale with stride 3 %.9g, expected %.9g\n", mapper->GetEffectiveScale(), latticeScale);
    ++failures;
  }
  std::printf("robust speed %.6g (reference %.6g), auto scale %.6g (stride 3: %.6g)\n", speed, robust,
    screenScale, latticeScale);

  // a speed given from outside (e.g. the percentile over MPI ranks) replaces the robust one
  mapper->SetAutomaticScaleSpeed(2.0 * robust);
  if (std::fabs(mapper->GetEffectiveScale() - 0.5 * latticeScale) > 1e-6 * latticeScale)
  {
    std::printf("FAIL: auto scale at AutomaticScaleSpeed 2 x robust %.9g, expected %.9g\n",
      mapper->GetEffectiveScale(), 0.5 * latticeScale);
    ++failures;
  }
  mapper->SetAutomaticScaleSpeed(std::numeric_limits<double>::quiet_NaN());
  // the piece-wise computation: whole image, then the nodes with x < 5 only
  const int half[6] = { 0, 4, 0, NY - 1, 0, NZ - 1 };
  const double whole = mapper->ComputeRobustMaximumSpeed(image, nullptr, {});
  const double piece = mapper->ComputeRobustMaximumSpeed(image, half, {});
  const double pieceReference = ReferenceRobustSpeed(image, 5);
  if (whole != speed || std::fabs(piece - pieceReference) > 1e-6 * pieceReference)
  {
    std::printf("FAIL: ComputeRobustMaximumSpeed whole %.9g (expected %.9g), x < 5 %.9g (reference %.9g)\n",
      whole, speed, piece, pieceReference);
    ++failures;
  }

  // the bounds are padded by the scale times the vector range: with the
  // outlier (10 along x) the padding along +x is auto scale x 10
  double bounds[6];
  mapper->GetBounds(bounds);
  const double padX = bounds[1] - (NX - 1) * Spacing;
  if (std::fabs(padX - latticeScale * 10.0) > 1e-6 * latticeScale * 10.0)
  {
    std::printf("FAIL: +x bounds padding %.9g, expected %.9g\n", padX, latticeScale * 10.0);
    ++failures;
  }

  // the drawn glyphs use the same scale
  const auto automatic = Draw(image, vtkPlumeVelocityGlyphMapper::SCALE_AUTO, 1.0);
  const auto fixedSame = Draw(image, vtkPlumeVelocityGlyphMapper::SCALE_FIXED, screenScale * 1.0);
  const auto fixedOne = Draw(image, vtkPlumeVelocityGlyphMapper::SCALE_FIXED, 1.0);
  const auto same = plume::test::Compare(automatic, fixedSame);
  const auto other = plume::test::Compare(automatic, fixedOne);
  std::printf("auto vs fixed at the auto scale: max %.4g; vs Scale 1: max %.4g\n", same.Max, other.Max);
  if (same.Max > 1e-6)
  {
    std::printf("FAIL: the auto render differs from a fixed render at the auto scale\n");
    ++failures;
  }
  if (other.Max < 0.1)
  {
    std::printf("FAIL: the auto render equals the Scale 1 render (the scale was not applied)\n");
    ++failures;
  }

  // screen-adaptive roots: two cells times the frame's stride
  int stride = 0;
  const auto screenAuto = Draw(image, vtkPlumeVelocityGlyphMapper::SCALE_AUTO, 1.0, true, &stride);
  const auto screenFixed = Draw(image, vtkPlumeVelocityGlyphMapper::SCALE_FIXED, stride * screenScale, true);
  const auto screenUnit = Draw(image, vtkPlumeVelocityGlyphMapper::SCALE_FIXED, screenScale, true);
  const auto screenSame = plume::test::Compare(screenAuto, screenFixed);
  const auto screenOther = plume::test::Compare(screenAuto, screenUnit);
  std::printf("screen roots, stride %d: auto vs fixed at %d x %.6g: max %.4g; vs fixed at one stride: max %.4g\n",
    stride, stride, screenScale, screenSame.Max, screenOther.Max);
  if (stride < 2)
  {
    std::printf("FAIL: the screen-adaptive stride is %d (the scene no longer tests a stride)\n", stride);
    ++failures;
  }
  if (screenSame.Max > 1e-6 || screenOther.Max < 0.1)
  {
    std::printf("FAIL: screen-adaptive auto glyphs are not two cells x the effective stride long\n");
    ++failures;
  }
  return failures == 0 ? 0 : 1;
}
