// Image geometry every renderer shares (vtkPlumeImageFrame.h): an image with
// a direction matrix R and an extent that does not start at 0 must draw the
// same glyphs as the axis-aligned, 0-based image of the same nodes rotated by
// an actor matrix [R | t]. The oriented image's vectors are the rotated ones
// (VTK keeps vectors in physical coordinates). Straight glyphs and RK4
// streamlets (which sample the texture along the way) are both checked; the
// oriented image drawn as if axis-aligned must differ (the test can fail).
#include "plumeTestSupport.h"
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkPlumeVortexSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"

#include <cmath>
#include <cstdio>

namespace
{
using plume::test::FloatImage;

FloatImage Draw(vtkImageData* image, vtkMatrix4x4* actorMatrix, int integrator)
{
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.0, 0.7);
  lut->Build();
  vtkNew<vtkPlumeVelocityGlyphMapper> mapper;
  mapper->SetInputData(image);
  mapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
  mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
  mapper->SetScale(0.3);
  mapper->SetIntegrator(integrator);
  mapper->SetRootAlpha(1.0);
  mapper->SetLookupTable(lut);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  if (actorMatrix)
  {
    actor->SetUserMatrix(actorMatrix);
  }
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0, 0, 0);
  ren->AddActor(actor);
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetPosition(1.5, -1.0, 6.0);
  cam->SetFocalPoint(1.0, 0.5, 0.3);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(40);
  ren->ResetCameraClippingRange();
  auto window = plume::test::MakeOffscreenWindow(240, 200);
  window->AddRenderer(ren);
  return plume::test::ReadBack(window);
}
}

int TestVelocityGlyphDirection(int, char*[])
{
  int failures = 0;
  vtkNew<vtkPlumeVortexSource> vortex;
  vortex->SetDimensions(9, 7, 2);
  vortex->SetBounds(-1.2, 1.2, -1, 1, -0.1, 0.1);
  vortex->SetCenter(0.2, -0.1, 0);
  vortex->SetCoreRadius(0.6);
  vortex->Update();
  vtkImageData* base = vortex->GetOutput();

  // R: 30 degrees about z then 20 about x; t: a translation
  vtkNew<vtkTransform> rotation;
  rotation->RotateX(20);
  rotation->RotateZ(30);
  const double t[3] = { 1.0, 0.5, 0.3 };
  vtkNew<vtkMatrix4x4> actorMatrix;
  actorMatrix->DeepCopy(rotation->GetMatrix());
  for (int r = 0; r < 3; ++r)
  {
    actorMatrix->SetElement(r, 3, t[r]);
  }
  double R[9];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      R[3 * r + c] = actorMatrix->GetElement(r, c);

  // the oriented image: same nodes, extent starting at (5, -3, 2), origin so
  // that node (5 + i, -3 + j, 2 + k) lands at R (o + s (i, j, k)) + t
  const int start[3] = { 5, -3, 2 };
  int dims[3];
  double spacing[3], o[3];
  base->GetDimensions(dims);
  base->GetSpacing(spacing);
  base->GetOrigin(o);
  vtkNew<vtkImageData> oriented;
  oriented->SetExtent(start[0], start[0] + dims[0] - 1, start[1], start[1] + dims[1] - 1, start[2], start[2] + dims[2] - 1);
  oriented->SetSpacing(spacing);
  oriented->SetDirectionMatrix(R);
  double origin[3];
  for (int r = 0; r < 3; ++r)
  {
    origin[r] = t[r];
    for (int c = 0; c < 3; ++c)
    {
      origin[r] += R[3 * r + c] * (o[c] - spacing[c] * start[c]);
    }
  }
  oriented->SetOrigin(origin);
  vtkDataArray* v = base->GetPointData()->GetVectors();
  vtkNew<vtkFloatArray> rotated;
  rotated->SetName("velocity");
  rotated->SetNumberOfComponents(3);
  rotated->SetNumberOfTuples(v->GetNumberOfTuples());
  for (vtkIdType i = 0; i < v->GetNumberOfTuples(); ++i)
  {
    const double* a = v->GetTuple3(i);
    double b[3];
    vtkMatrix3x3::MultiplyPoint(R, a, b);
    rotated->SetTuple(i, b);
  }
  oriented->GetPointData()->SetVectors(rotated);
  // the same, its geometry lost (axis-aligned, 0-based)
  vtkNew<vtkImageData> flat;
  flat->SetDimensions(dims);
  flat->SetSpacing(spacing);
  flat->SetOrigin(origin);
  flat->GetPointData()->SetVectors(rotated);

  for (int integrator : { int(vtkPlumeVelocityGlyphMapper::STRAIGHT), int(vtkPlumeVelocityGlyphMapper::RK4) })
  {
    const char* name = integrator == vtkPlumeVelocityGlyphMapper::STRAIGHT ? "straight" : "rk4";
    const FloatImage expected = Draw(base, actorMatrix, integrator);
    const FloatImage got = Draw(oriented, nullptr, integrator);
    const FloatImage wrong = Draw(flat, nullptr, integrator);
    const double bg[3] = { 0, 0, 0 };
    const size_t drawn = plume::test::CountForeground(expected, bg, 0.05);
    const auto e = plume::test::Compare(expected, got);
    const auto w = plume::test::Compare(expected, wrong);
    std::printf("%s: %zu glyph pixels; oriented image vs rotated actor RMS %.4f max %.3f; "
                "direction ignored RMS %.4f\n",
      name, drawn, e.RMS, e.Max, w.RMS);
    PLUME_CHECK(drawn > 100);
    // float rounding may move a line by a pixel in places: RMS bounds the rest
    PLUME_CHECK(e.RMS < 0.01);
    PLUME_CHECK(w.RMS > 5 * std::max(e.RMS, 0.005));
    PLUME_CHECK(!plume::test::HasNonFinite(got));
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
