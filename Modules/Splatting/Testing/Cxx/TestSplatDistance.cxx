// DISTANCE_MAX mode (seed 002: MAX blending, linear falloff) against the
// analytic distance to a segment. A segment AB sampled every δ by a polyline
// splats max(0, 1 − r/R) per vertex; the distance to the nearest sample lies
// in [d, d + δ/2] where d is the exact distance to the segment, so the field
// lies in [1 − (d + δ/2)/R, 1 − d/R] (clamped at 0), for both backends.
#include "plumeSplatTestUtil.h"

#include "vtkCellArray.h"
#include "vtkLine.h"
#include "vtkMath.h"

#include <cstdio>

int TestSplatDistance(int, char*[])
{
  int failures = 0;
  const double A[3] = { -0.6, -0.3, -0.2 }, B[3] = { 0.5, 0.4, 0.25 };
  const int M = 400;
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  cells->InsertNextCell(M + 1);
  for (int i = 0; i <= M; ++i)
  {
    const double t = double(i) / M;
    cells->InsertCellPoint(pts->InsertNextPoint(A[0] + t * (B[0] - A[0]), A[1] + t * (B[1] - A[1]), A[2] + t * (B[2] - A[2])));
  }
  vtkNew<vtkPolyData> segment;
  segment->SetPoints(pts);
  segment->SetLines(cells);
  const double delta = std::sqrt(vtkMath::Distance2BetweenPoints(A, B)) / M;
  const double Rf = 0.35;

  vtkNew<vtkPlumeGaussianSplatter> splatter;
  splatter->SetLinesData(segment);
  splatter->SetMode(vtkPlumeGaussianSplatter::DISTANCE_MAX);
  splatter->SetRadius(Rf);
  splatter->SetDimensions(36, 30, 26);
  splatter->SetModelBounds(-1, 1, -0.8, 0.9, -0.7, 0.7);
  for (int backend : { vtkPlumeGaussianSplatter::BACKEND_CPU, vtkPlumeGaussianSplatter::BACKEND_GPU })
  {
    splatter->SetBackend(backend);
    splatter->Update();
    vtkImageData* out = splatter->GetOutput();
    vtkDataArray* f = out->GetPointData()->GetScalars();
    PLUME_CHECK(f && std::string(f->GetName()) == "distance");
    double worst = 0;
    int inside = 0;
    for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
    {
      double x[3], t, closest[3];
      out->GetPoint(id, x);
      const double d = std::sqrt(vtkLine::DistanceToLine(x, A, B, t, closest));
      const double hi = std::max(0.0, 1 - d / Rf);
      const double lo = std::max(0.0, 1 - (d + 0.5 * delta) / Rf);
      const double got = f->GetComponent(id, 0);
      worst = std::max(worst, std::max(got - hi, lo - got));
      inside += got > 0;
    }
    std::printf("backend %d: %d voxels inside, worst excursion outside [1-(d+delta/2)/R, 1-d/R]: %.3g (delta/2R = %.3g)\n",
      splatter->GetLastBackend(), inside, worst, 0.5 * delta / Rf);
    PLUME_CHECK(splatter->GetLastBackend() == backend);
    PLUME_CHECK(inside > 1000);
    PLUME_CHECK(worst <= 1e-5);
  }
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
