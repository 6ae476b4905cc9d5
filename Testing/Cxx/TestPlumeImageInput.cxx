// vtkPlumeImageInput (the ParaView plugin's input adapter, compiled here
// against VTK 9.1): cell arrays of image pieces survive the resample.
//
// Each case builds pieces whose cell values are a known function of the
// cell's centre, and checks every sample of the resampled image against that
// function evaluated here, in double precision, at the cell that holds the
// sample in the finest piece covering it (no code shared with the adapter):
// - an AMR-like pair (coarse block, a nested block at half the spacing), as a
//   multiblock and as a vtkOverlappingAMR, cell data only: the samples are the
//   centres of the fine lattice's cells over the union, each the exact cell
//   value of the finest piece there;
// - the same pair with a point array too: both arrays in the result, the
//   point array trilinear at the centres;
// - one image with cell data only: its cell values at its cell centres;
// - point data only (the former path): unchanged, samples at the lattice's
//   points.
#include "vtkAMRBox.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOverlappingAMR.h"
#include "vtkPlumeImageInput.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUniformGrid.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

namespace
{
int failures = 0;

void Check(bool ok, const char* what)
{
  if (!ok)
  {
    std::printf("FAILED: %s\n", what);
    ++failures;
  }
}

// the cell field of a piece: distinct per level (offset) so a sample taken
// from the wrong level is caught
double CellField(const double c[3], double offset)
{
  return offset + std::sin(1.3 * c[0]) + 0.5 * c[1] * c[1] - 0.25 * c[2];
}

double PointField(const double x[3])
{
  return 2.0 * x[0] - 3.0 * x[1] + 0.5 * x[2]; // linear: trilinear interpolation is exact
}

// An image with the given origin, spacing and cell counts, "cells" = CellField(centre, offset),
// and (if withPoints) "points" = PointField.
vtkSmartPointer<vtkUniformGrid> Piece(
  const double origin[3], double h, const int cells[3], double offset, bool withPoints)
{
  auto image = vtkSmartPointer<vtkUniformGrid>::New();
  image->SetOrigin(origin[0], origin[1], origin[2]);
  image->SetSpacing(h, h, h);
  image->SetDimensions(cells[0] + 1, cells[1] + 1, cells[2] + 1);
  vtkNew<vtkDoubleArray> values;
  values->SetName("cells");
  values->SetNumberOfTuples(image->GetNumberOfCells());
  for (int k = 0; k < cells[2]; ++k)
    for (int j = 0; j < cells[1]; ++j)
      for (int i = 0; i < cells[0]; ++i)
      {
        const double c[3] = { origin[0] + (i + 0.5) * h, origin[1] + (j + 0.5) * h, origin[2] + (k + 0.5) * h };
        values->SetValue(i + cells[0] * (j + cells[1] * k), CellField(c, offset));
      }
  image->GetCellData()->SetScalars(values);
  if (withPoints)
  {
    vtkNew<vtkDoubleArray> points;
    points->SetName("points");
    points->SetNumberOfTuples(image->GetNumberOfPoints());
    for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
    {
      double x[3];
      image->GetPoint(p, x);
      points->SetValue(p, PointField(x));
    }
    image->GetPointData()->AddArray(points);
  }
  return image;
}

// coarse: origin 0, spacing 1, 6x4x5 cells; fine: origin (2,1,1), spacing 0.5, 4x4x6 cells (nested)
const double coarseOrigin[3] = { 0, 0, 0 };
const int coarseCells[3] = { 6, 4, 5 };
const double fineOrigin[3] = { 2, 1, 1 };
const int fineCells[3] = { 4, 4, 6 };

// The expected cell value at x: the fine piece's cell if x is inside it, else the coarse one's.
double ExpectedCell(const double x[3])
{
  bool inFine = true;
  for (int a = 0; a < 3; ++a)
  {
    inFine = inFine && x[a] > fineOrigin[a] && x[a] < fineOrigin[a] + 0.5 * fineCells[a];
  }
  const double h = inFine ? 0.5 : 1.0;
  const double* o = inFine ? fineOrigin : coarseOrigin;
  double c[3];
  for (int a = 0; a < 3; ++a)
  {
    c[a] = o[a] + (std::floor((x[a] - o[a]) / h) + 0.5) * h; // centre of the cell holding x
  }
  return CellField(c, inFine ? 100.0 : 0.0);
}

// Every sample of `out` checked: geometry (cell centres of the 0.5 lattice over [0,6]x[0,4]x[0,5]),
// "cells" exactly (float), and "points" if expected.
void CheckCentres(vtkImageData* out, bool withPoints, const char* label)
{
  std::printf("%s\n", label);
  Check(out != nullptr, "an image");
  if (!out)
  {
    return;
  }
  const int* d = out->GetDimensions();
  const double* o = out->GetOrigin();
  const double* h = out->GetSpacing();
  std::printf("  %dx%dx%d, origin %g %g %g, spacing %g %g %g\n", d[0], d[1], d[2], o[0], o[1], o[2], h[0], h[1],
    h[2]);
  Check(d[0] == 12 && d[1] == 8 && d[2] == 10, "12x8x10 samples: the fine lattice's cells over the union");
  Check(std::abs(o[0] - 0.25) < 1e-12 && std::abs(o[1] - 0.25) < 1e-12 && std::abs(o[2] - 0.25) < 1e-12,
    "origin at the first fine cell's centre");
  Check(std::abs(h[0] - 0.5) < 1e-12 && std::abs(h[1] - 0.5) < 1e-12 && std::abs(h[2] - 0.5) < 1e-12,
    "the finest spacing");
  vtkDataArray* cells = out->GetPointData()->GetArray("cells");
  Check(cells != nullptr, "the cell array kept, as point data");
  vtkDataArray* points = out->GetPointData()->GetArray("points");
  Check(withPoints == (points != nullptr), "the point array kept when the pieces have one");
  if (!cells)
  {
    return;
  }
  Check(out->GetPointData()->GetScalars() == cells, "the cell scalars are the active scalars");
  double worstCell = 0, worstPoint = 0;
  int fineSamples = 0;
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    double x[3];
    out->GetPoint(p, x);
    const double expected = ExpectedCell(x);
    fineSamples += expected > 50;
    worstCell = std::max(worstCell, std::abs(cells->GetTuple1(p) - expected) / (1 + std::abs(expected)));
    if (points)
    {
      worstPoint = std::max(worstPoint, std::abs(points->GetTuple1(p) - PointField(x)));
    }
  }
  std::printf("  cell values: max relative error %.3g (%d samples from the fine piece); point values: max "
              "error %.3g\n",
    worstCell, fineSamples, worstPoint);
  Check(fineSamples == 4 * 4 * 6, "the fine piece's 4x4x6 cells each give one sample");
  Check(worstCell < 1e-6, "every cell value exact (float)");
  Check(worstPoint < 1e-4, "the point array trilinear (a linear field: exact)");
}
}

int TestPlumeImageInput(int, char*[])
{
  for (bool withPoints : { false, true })
  {
    auto coarse = Piece(coarseOrigin, 1.0, coarseCells, 0.0, withPoints);
    auto fine = Piece(fineOrigin, 0.5, fineCells, 100.0, withPoints);
    vtkNew<vtkMultiBlockDataSet> group;
    group->SetBlock(0, coarse); // coarse first: the adapter must still prefer the finer piece
    group->SetBlock(1, fine);
    CheckCentres(vtkPlumeImageInput::Extract(group, nullptr),
      withPoints, withPoints ? "multiblock, cell + point arrays" : "multiblock, cell arrays only");
  }
  {
    // the same two levels as a vtkOverlappingAMR (what ParaView's AMR sources give)
    auto coarse = Piece(coarseOrigin, 1.0, coarseCells, 0.0, false);
    auto fine = Piece(fineOrigin, 0.5, fineCells, 100.0, false);
    vtkNew<vtkOverlappingAMR> amr;
    const int blocksPerLevel[2] = { 1, 1 };
    amr->Initialize(2, blocksPerLevel);
    amr->SetOrigin(coarseOrigin);
    amr->SetGridDescription(VTK_XYZ_GRID);
    const double h0[3] = { 1, 1, 1 };
    const double h1[3] = { 0.5, 0.5, 0.5 };
    amr->SetSpacing(0, h0);
    amr->SetSpacing(1, h1);
    amr->SetRefinementRatio(0, 2);
    amr->SetAMRBox(0, 0, vtkAMRBox(coarse->GetOrigin(), coarse->GetDimensions(), h0, amr->GetOrigin()));
    amr->SetAMRBox(1, 0, vtkAMRBox(fine->GetOrigin(), fine->GetDimensions(), h1, amr->GetOrigin()));
    amr->SetDataSet(0, 0, coarse);
    amr->SetDataSet(1, 0, fine);
    CheckCentres(vtkPlumeImageInput::Extract(amr, nullptr), false, "vtkOverlappingAMR, cell arrays only");
  }
  {
    // one image, cell data only: its cell values at its cell centres
    std::printf("one image, cell arrays only\n");
    auto coarse = Piece(coarseOrigin, 1.0, coarseCells, 0.0, false);
    vtkSmartPointer<vtkImageData> out = vtkPlumeImageInput::Extract(coarse, nullptr);
    Check(out && out->GetDimensions()[0] == 6 && out->GetDimensions()[1] == 4 && out->GetDimensions()[2] == 5,
      "6x4x5 samples, one per cell");
    vtkDataArray* cells = out ? out->GetPointData()->GetArray("cells") : nullptr;
    Check(cells != nullptr, "the cell array as point data");
    double worst = 0;
    for (vtkIdType p = 0; cells && p < out->GetNumberOfPoints(); ++p)
    {
      double x[3];
      out->GetPoint(p, x);
      worst = std::max(worst, std::abs(cells->GetTuple1(p) - CellField(x, 0.0)));
    }
    std::printf("  max error %.3g\n", worst);
    Check(cells && worst < 1e-6, "each sample its cell's value");
  }
  {
    // point data only (the former path, TestPlumeVolumeMixedSpacing's): samples at the lattice's points
    std::printf("multiblock, point arrays only\n");
    auto coarse = Piece(coarseOrigin, 1.0, coarseCells, 0.0, true);
    auto fine = Piece(fineOrigin, 0.5, fineCells, 100.0, true);
    coarse->GetCellData()->Initialize();
    fine->GetCellData()->Initialize();
    vtkNew<vtkMultiBlockDataSet> group;
    group->SetBlock(0, coarse);
    group->SetBlock(1, fine);
    vtkSmartPointer<vtkImageData> out = vtkPlumeImageInput::Extract(group, nullptr);
    Check(out && out->GetDimensions()[0] == 13 && out->GetDimensions()[1] == 9 && out->GetDimensions()[2] == 11 &&
        out->GetOrigin()[0] == 0.0,
      "13x9x11 points from the union's corner");
    vtkDataArray* points = out ? out->GetPointData()->GetArray("points") : nullptr;
    double worst = 0;
    for (vtkIdType p = 0; points && p < out->GetNumberOfPoints(); ++p)
    {
      double x[3];
      out->GetPoint(p, x);
      worst = std::max(worst, std::abs(points->GetTuple1(p) - PointField(x)));
    }
    std::printf("  max error %.3g\n", worst);
    Check(points && worst < 1e-4, "the point array trilinear");
  }
  std::printf(failures ? "%d check(s) failed\n" : "all checks passed\n", failures);
  return failures ? 1 : 0;
}

int main(int argc, char* argv[])
{
  return TestPlumeImageInput(argc, argv);
}
