// Flow lines cut into pieces splat as the uncut lines do: three open helices
// (40 vertices each) splatted whole, and the same lines as pieces the way
// ranks or partitioners leave them:
//  - "shared": each line cut at vertex 17 into two cells that both hold the
//    cut vertex (its own copy of the point, no ghost flags: "owned by both");
//  - "ghost point": the same, with the first piece's copy of the cut vertex
//    flagged DUPLICATEPOINT;
//  - "ghost cell": the whole lines plus a second copy of each flagged
//    DUPLICATECELL (what another piece owns).
// Vector and scalar modes, CPU and GPU backends and vtkPlumeSplatReference:
// every cut input gives the whole lines' field (max difference 1e-6 of the
// peak: the same splats in the same order), and the "shared" cut without the
// rule would differ (checked: the same input with the cut vertex moved off the
// start by 1e-9 differs by > 1 % of the peak, the double splat).
#include "plumeSplatTestUtil.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkUnsignedCharArray.h"

#include <cstdio>
#include <vector>

namespace
{
const int Lines = 3, N = 40, Cut = 17;

void Vertex(int line, int i, double p[3])
{
  const double t = 0.12 * i;
  p[0] = 0.6 * std::cos(t + 2.0 * line) - 0.1 * line;
  p[1] = 0.6 * std::sin(t + 2.0 * line);
  p[2] = -0.8 + 0.04 * i + 0.05 * line;
}

// kind: 0 whole, 1 shared cut vertex, 2 cut vertex ghost in the first piece,
// 3 ghost-cell copies, 4 shared but the second piece starts 1e-9 off
vtkSmartPointer<vtkPolyData> MakeLines(int kind)
{
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkUnsignedCharArray> pointGhosts, cellGhosts;
  pointGhosts->SetName(vtkDataSetAttributes::GhostArrayName());
  cellGhosts->SetName(vtkDataSetAttributes::GhostArrayName());
  auto piece = [&](int line, int from, int to, unsigned char lastFlag, double startShift, unsigned char cellFlag) {
    std::vector<vtkIdType> ids;
    for (int i = from; i <= to; ++i)
    {
      double p[3];
      Vertex(line, i, p);
      if (i == from)
      {
        p[0] += startShift;
      }
      ids.push_back(pts->InsertNextPoint(p));
      pointGhosts->InsertNextValue(i == to ? lastFlag : 0);
    }
    cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    cellGhosts->InsertNextValue(cellFlag);
  };
  for (int line = 0; line < Lines; ++line)
  {
    switch (kind)
    {
      case 0:
        piece(line, 0, N - 1, 0, 0, 0);
        break;
      case 1:
      case 2:
      case 4:
        piece(line, 0, Cut, kind == 2 ? vtkDataSetAttributes::DUPLICATEPOINT : 0, 0, 0);
        piece(line, Cut, N - 1, 0, kind == 4 ? 1e-9 : 0, 0);
        break;
      case 3:
        piece(line, 0, N - 1, 0, 0, 0);
        piece(line, 0, N - 1, 0, 0, vtkDataSetAttributes::DUPLICATECELL);
        break;
    }
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(pts);
  poly->SetLines(cells);
  if (kind == 2)
  {
    poly->GetPointData()->AddArray(pointGhosts);
  }
  if (kind == 3)
  {
    poly->GetCellData()->AddArray(cellGhosts);
  }
  return poly;
}

vtkSmartPointer<vtkPlumeGaussianSplatter> Splatter(vtkPolyData* lines, int mode, int backend)
{
  auto splatter = vtkSmartPointer<vtkPlumeGaussianSplatter>::New();
  vtkNew<vtkPolyData> none; // no points
  splatter->SetInputData(none);
  splatter->SetLinesData(lines);
  splatter->SetDimensions(24, 22, 20);
  splatter->SetModelBounds(-1, 1, -1, 1, -1, 1);
  splatter->SetRadius(0.08);
  splatter->SetMode(mode);
  splatter->SetBackend(backend);
  splatter->Update();
  return splatter;
}

// max |a - b| relative to max |a|
double RelDiff(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* x = a->GetPointData()->GetArray(0);
  vtkDataArray* y = b->GetPointData()->GetArray(0);
  if (!x || !y || x->GetNumberOfValues() != y->GetNumberOfValues() || x->GetNumberOfValues() == 0)
  {
    return HUGE_VAL;
  }
  double m = 0, peak = 0;
  for (vtkIdType i = 0; i < x->GetNumberOfValues(); ++i)
  {
    const double u = x->GetVariantValue(i).ToDouble(), w = y->GetVariantValue(i).ToDouble();
    m = std::max(m, std::fabs(u - w));
    peak = std::max(peak, std::fabs(u));
  }
  return peak > 0 ? m / peak : HUGE_VAL;
}
}

int TestSplatLinePieces(int, char*[])
{
  int failures = 0;
  const char* kinds[] = { "whole", "shared", "ghost point", "ghost cell", "shared, shifted 1e-9" };
  for (int mode : { vtkPlumeGaussianSplatter::VECTOR_SUM, vtkPlumeGaussianSplatter::SCALAR_SUM })
  {
    const char* name = mode == vtkPlumeGaussianSplatter::VECTOR_SUM ? "vector" : "scalar";
    for (int backend : { vtkPlumeGaussianSplatter::BACKEND_CPU, vtkPlumeGaussianSplatter::BACKEND_GPU })
    {
      const char* bname = backend == vtkPlumeGaussianSplatter::BACKEND_CPU ? "CPU" : "GPU";
      auto whole = Splatter(MakeLines(0), mode, backend);
      for (int kind = 1; kind <= 4; ++kind)
      {
        auto cut = Splatter(MakeLines(kind), mode, backend);
        const double d = RelDiff(whole->GetOutput(), cut->GetOutput());
        std::printf("%s %s: whole vs %s: max difference %.3g of the peak, splats %lld / %lld\n", name, bname,
          kinds[kind], d, (long long)whole->GetSplatCount(), (long long)cut->GetSplatCount());
        if (kind < 4)
        {
          PLUME_CHECK(d <= 1e-6);
          PLUME_CHECK(cut->GetSplatCount() == whole->GetSplatCount());
        }
        else
        {
          PLUME_CHECK(d > 0.01); // a cut vertex splatted twice (and backward once) shows
        }
      }
    }
    // the reference: the same rules, written on its own
    std::vector<vtkSmartPointer<vtkImageData>> fields;
    for (int kind = 0; kind <= 4; ++kind)
    {
      auto splatter = Splatter(MakeLines(kind), mode, vtkPlumeGaussianSplatter::BACKEND_CPU);
      vtkNew<vtkPlumeSplatReference> reference;
      reference->Configure(splatter);
      fields.push_back(reference->Compute());
      std::printf("%s reference %s: %lld splats\n", name, kinds[kind], (long long)reference->GetNumberOfSplats());
      PLUME_CHECK(reference->GetNumberOfSplats() == (kind == 4 ? Lines * (N + 1) : Lines * N));
    }
    for (int kind = 1; kind <= 3; ++kind)
    {
      const double d = RelDiff(fields[0], fields[kind]);
      std::printf("%s reference: whole vs %s: %.3g\n", name, kinds[kind], d);
      PLUME_CHECK(d <= 1e-12);
    }
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
