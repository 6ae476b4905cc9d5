// Numeric test (no baseline): RK4 streamlets of a rigid rotation end on the
// circle through their root, where a double-precision CPU integration says.
#include "vtkPlumeVelocityGlyphMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "plumeGlyphTestUtil.h"

namespace
{
const double Omega = 1.3;
const double Centre[3] = { 0.07, -0.05, 0.0 };

void Rotation(const double p[3], double v[3])
{
  v[0] = -Omega * (p[1] - Centre[1]);
  v[1] = Omega * (p[0] - Centre[0]);
  v[2] = 0.0;
}

// classical RK4, `segments` steps of h = scale / segments; returns the last two points
void IntegrateRK4(const double root[3], double scale, int segments, double prev[3], double tip[3])
{
  const double h = scale / segments;
  double p[3] = { root[0], root[1], root[2] };
  for (int s = 0; s < segments; ++s)
  {
    double k1[3], k2[3], k3[3], k4[3], q[3];
    Rotation(p, k1);
    for (int a = 0; a < 3; ++a)
      q[a] = p[a] + 0.5 * h * k1[a];
    Rotation(q, k2);
    for (int a = 0; a < 3; ++a)
      q[a] = p[a] + 0.5 * h * k2[a];
    Rotation(q, k3);
    for (int a = 0; a < 3; ++a)
      q[a] = p[a] + h * k3[a];
    Rotation(q, k4);
    std::copy(p, p + 3, prev);
    for (int a = 0; a < 3; ++a)
      p[a] += h / 6.0 * (k1[a] + 2 * k2[a] + 2 * k3[a] + k4[a]);
  }
  std::copy(p, p + 3, tip);
}
}

int TestVelocityGlyphStreamlet(int, char*[])
{
  int failures = 0;
  vtkNew<vtkImageData> image;
  image->SetDimensions(25, 25, 1); // a single slab: streamlets do not overlap on screen
  image->SetOrigin(-1.2, -1.2, 0.0);
  image->SetSpacing(0.1, 0.1, 0.1);
  vtkNew<vtkDoubleArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double v[3];
    Rotation(image->GetPoint(i), v);
    velocity->SetTuple(i, v);
  }
  image->GetPointData()->SetVectors(velocity);

  const double scale = 0.8; // 1.04 rad of arc per glyph
  const int segments = 8;
  vtkNew<vtkPlumeVelocityGlyphMapper> mapper;
  mapper->SetInputData(image);
  mapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
  mapper->SetLatticeStride(4);
  mapper->SetIntegrator(vtkPlumeVelocityGlyphMapper::RK4);
  mapper->SetStreamletSegments(segments);
  mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
  mapper->SetScale(scale);
  mapper->SetRootAlpha(1.0);
  mapper->SetLineWidth(2.0);
  mapper->ColorByMagnitudeOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetDiffuseColor(1, 1, 0.5);

  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0, 0, 0);
  ren->AddActor(actor);
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetPosition(0.3, -0.8, 3.6);
  cam->SetFocalPoint(0, 0, 0);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(40);
  ren->ResetCameraClippingRange();
  auto window = plume::test::MakeOffscreenWindow(300, 300);
  window->AddRenderer(ren);

  const plume::test::FloatImage img = plume::test::ReadBack(window);
  plumetest::DumpPNG(window, "TestVelocityGlyphStreamlet");
  PLUME_CHECK(!plume::test::HasNonFinite(img));
  PLUME_CHECK(plume::test::GLErrors(window).empty());
  const double bg[3] = { 0, 0, 0 };
  int checked = 0, bad = 0;
  double worst = 0, worstRadius = 0;
  for (int j = 0; j < 25; j += 4)
  {
    for (int i = 0; i < 25; i += 4)
    {
      double root[3] = { -1.2 + 0.1 * i, -1.2 + 0.1 * j, 0.0 };
      const double r = std::hypot(root[0] - Centre[0], root[1] - Centre[1]);
      // skip streamlets whose circle leaves the volume (they stop early) or are tiny
      if (r < 0.25 || r > 1.05)
      {
        continue;
      }
      double prev[3], tip[3];
      IntegrateRK4(root, scale, segments, prev, tip);
      // skip a streamlet whose tip region is covered by another one on (nearly) the same circle
      bool crowded = false;
      const double tipAngle = std::atan2(tip[1] - Centre[1], tip[0] - Centre[0]);
      for (int jj = 0; jj < 25; jj += 4)
      {
        for (int ii = 0; ii < 25; ii += 4)
        {
          const double x = -1.2 + 0.1 * ii - Centre[0], y = -1.2 + 0.1 * jj - Centre[1];
          double ahead = std::atan2(y, x) - tipAngle;
          ahead = std::remainder(ahead, 2 * vtkMath::Pi());
          crowded |= (ii != i || jj != j) && std::fabs(std::hypot(x, y) - r) < 0.03 &&
            ahead > -Omega * scale - 0.05 && ahead < 0.3;
        }
      }
      if (crowded)
      {
        continue;
      }
      const double rt = std::hypot(tip[0] - Centre[0], tip[1] - Centre[1]);
      worstRadius = std::max(worstRadius, std::fabs(rt - r));
      // the last segment decides where the drawn streamlet ends
      const plumetest::TipResult res = plumetest::MeasureTip(ren, img, prev, tip, bg, 4);
      if (!res.Valid)
      {
        continue;
      }
      ++checked;
      worst = std::max(worst, std::fabs(res.Reach));
      if (std::fabs(res.Reach) > 1.0 || res.Beyond > 0)
      {
        ++bad;
        std::cerr << "streamlet from (" << root[0] << ", " << root[1] << "): ends " << res.Reach
                  << " px from the CPU tip, " << res.Beyond << " pixels beyond\n";
      }
    }
  }
  std::cout << "checked " << checked << " streamlets, worst tip error " << worst
            << " px; CPU RK4 radius drift " << worstRadius << "\n";
  PLUME_CHECK(worstRadius < 1e-4); // the reference itself stays on the circle
  PLUME_CHECK(checked >= 10);
  PLUME_CHECK(bad == 0);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
