// Ghost points are not splatted: 80 random points, and the same points plus a
// copy of the first 30 flagged DUPLICATEPOINT in the vtkGhostType point
// array (what another piece owns, as ParaView ranks and D3 hand them over).
// In vector and scalar modes, on the CPU and GPU backends and in
// vtkPlumeSplatReference, the ghosted input gives exactly the field of the
// points alone (same splats in the same order: bit-identical), and a larger
// one once the ghost array is removed (so the copies really are counted then).
#include "plumeSplatTestUtil.h"

#include "vtkDataSetAttributes.h"
#include "vtkUnsignedCharArray.h"

#include <cstdio>

namespace
{
vtkSmartPointer<vtkPolyData> WithGhosts(vtkPolyData* points, vtkIdType copies)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->DeepCopy(points);
  vtkPointData* pd = poly->GetPointData();
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfValues(points->GetNumberOfPoints());
  ghosts->FillValue(0);
  for (vtkIdType i = 0; i < copies; ++i)
  {
    poly->GetPoints()->InsertNextPoint(points->GetPoint(i));
    for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
    {
      pd->GetArray(a)->InsertNextTuple(i, points->GetPointData()->GetArray(a));
    }
    ghosts->InsertNextValue(vtkDataSetAttributes::DUPLICATEPOINT);
  }
  pd->AddArray(ghosts);
  return poly;
}

vtkSmartPointer<vtkImageData> Splat(vtkPolyData* input, int mode, int backend)
{
  vtkNew<vtkPlumeGaussianSplatter> splatter;
  splatter->SetInputData(input);
  splatter->SetDimensions(20, 18, 16);
  splatter->SetModelBounds(-1, 1, -1.1, 0.9, -0.9, 1.0);
  splatter->SetRadiusArrayName("sigma");
  splatter->SetMode(mode);
  splatter->SetBackend(backend);
  splatter->Update();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->DeepCopy(splatter->GetOutput());
  return out;
}

vtkSmartPointer<vtkImageData> Reference(vtkPolyData* input, int mode, vtkIdType& count)
{
  vtkNew<vtkPlumeGaussianSplatter> splatter;
  splatter->SetInputData(input);
  splatter->SetDimensions(20, 18, 16);
  splatter->SetModelBounds(-1, 1, -1.1, 0.9, -0.9, 1.0);
  splatter->SetRadiusArrayName("sigma");
  splatter->SetMode(mode);
  splatter->SetBackend(vtkPlumeGaussianSplatter::BACKEND_CPU);
  splatter->Update(); // the reference takes the output grid from it
  vtkNew<vtkPlumeSplatReference> reference;
  reference->Configure(splatter);
  count = reference->GetNumberOfSplats();
  return reference->Compute();
}

double MaxDiff(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* x = a->GetPointData()->GetArray(0);
  vtkDataArray* y = b->GetPointData()->GetArray(0);
  if (!x || !y || x->GetNumberOfValues() != y->GetNumberOfValues() || x->GetNumberOfValues() == 0)
  {
    return HUGE_VAL;
  }
  double m = 0;
  for (vtkIdType i = 0; i < x->GetNumberOfValues(); ++i)
  {
    m = std::max(m, std::fabs(x->GetVariantValue(i).ToDouble() - y->GetVariantValue(i).ToDouble()));
  }
  return m;
}
}

int TestSplatGhostPoints(int, char*[])
{
  int failures = 0;
  auto alone = splattest::RandomPoints(80, -0.8, 0.8, 0.05, 0.2);
  auto ghosted = WithGhosts(alone, 30);
  auto unflagged = vtkSmartPointer<vtkPolyData>::New();
  unflagged->DeepCopy(ghosted);
  unflagged->GetPointData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());

  for (int mode : { vtkPlumeGaussianSplatter::VECTOR_SUM, vtkPlumeGaussianSplatter::SCALAR_SUM })
  {
    const char* name = mode == vtkPlumeGaussianSplatter::VECTOR_SUM ? "vector" : "scalar";
    for (int backend : { vtkPlumeGaussianSplatter::BACKEND_CPU, vtkPlumeGaussianSplatter::BACKEND_GPU })
    {
      auto a = Splat(alone, mode, backend);
      const double same = MaxDiff(a, Splat(ghosted, mode, backend));
      const double diff = MaxDiff(a, Splat(unflagged, mode, backend));
      std::printf("%s %s: alone vs ghosted max %.3g, vs unflagged max %.3g\n", name,
        backend == vtkPlumeGaussianSplatter::BACKEND_CPU ? "CPU" : "GPU", same, diff);
      PLUME_CHECK(same == 0.0);
      PLUME_CHECK(diff > 0.1);
    }
    vtkIdType nAlone = 0, nGhosted = 0, nUnflagged = 0;
    auto ra = Reference(alone, mode, nAlone);
    auto rg = Reference(ghosted, mode, nGhosted);
    auto ru = Reference(unflagged, mode, nUnflagged);
    const double same = MaxDiff(ra, rg), diff = MaxDiff(ra, ru);
    std::printf("%s reference: splats %lld / %lld / %lld, alone vs ghosted max %.3g, vs unflagged max %.3g\n", name,
      (long long)nAlone, (long long)nGhosted, (long long)nUnflagged, same, diff);
    PLUME_CHECK(nAlone == 80 && nGhosted == 80 && nUnflagged == 110);
    PLUME_CHECK(same == 0.0);
    PLUME_CHECK(diff > 0.1);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
