// An image split into two pieces that share their seam's nodes (as ParaView
// splits image data over MPI ranks), each drawn by its own mapper with
// WholeExtent, MovingNodeCount and AutomaticScaleSpeed set to the whole
// image's, draws the glyphs of one mapper on the whole image: the same
// screen-adaptive stride, roots on the whole image's lattice and the same
// automatic length; also for a fixed lattice stride of 3 that does not
// divide the seam's index. Pieces left to themselves choose other roots (their
// own stride and lattice start), which the comparison must tell apart.
// Opaque lines (RootAlpha 1) over a fixed colour range: the pieces' overlap
// is drawn twice, identically, and the depth test keeps one.
#include "plumeTestSupport.h"
#include "vtkPlumeVelocityGlyphMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkExtractVOI.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace
{
constexpr int PiecesNX = 40, PiecesNY = 30, PiecesNZ = 20;
constexpr int Seam = 17; // the last x node of piece 0, the first of piece 1

// a swirl about the z axis in a ball of radius 12 nodes, still air outside
vtkSmartPointer<vtkImageData> MakePiecesField()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(PiecesNX, PiecesNY, PiecesNZ);
  image->SetSpacing(0.1, 0.1, 0.1);
  image->SetOrigin(-2.0, -1.5, -1.0);
  vtkNew<vtkFloatArray> v;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  for (int k = 0; k < PiecesNZ; ++k)
  {
    for (int j = 0; j < PiecesNY; ++j)
    {
      for (int i = 0; i < PiecesNX; ++i)
      {
        const double x = i - 18.0, y = j - 14.0, z = k - 9.0;
        const double r = std::sqrt(x * x + y * y + z * z);
        const double s = r < 12.0 ? 1.0 + 0.1 * (i % 7) : 0.001;
        v->InsertNextTuple3(-s * y / 10.0, s * x / 10.0, 0.2 * s * std::sin(0.3 * k));
      }
    }
  }
  image->GetPointData()->SetVectors(v);
  return image;
}

struct PiecesDraw
{
  vtkNew<vtkRenderer> Renderer;
  vtkSmartPointer<vtkRenderWindow> Window = plume::test::MakeOffscreenWindow(320, 240);
  vtkNew<vtkLookupTable> Table;
  PiecesDraw()
  {
    this->Table->SetRange(0.0, 3.0);
    this->Table->Build();
    this->Renderer->SetBackground(0, 0, 0);
    vtkCamera* cam = this->Renderer->GetActiveCamera();
    cam->SetFocalPoint(0.0, 0.0, 0.0);
    cam->SetPosition(1.5, -2.0, 6.0);
    cam->SetViewUp(0, 1, 0);
    cam->SetClippingRange(0.5, 30.0);
    this->Window->AddRenderer(this->Renderer);
  }
  vtkPlumeVelocityGlyphMapper* Add(vtkImageData* image, int roots)
  {
    vtkNew<vtkPlumeVelocityGlyphMapper> mapper;
    mapper->SetInputData(image);
    mapper->SetRootMode(roots);
    mapper->SetLatticeStride(3);
    mapper->SetScreenSpacing(10.0);
    mapper->SetRootAlpha(1.0);
    mapper->SetLookupTable(this->Table);
    mapper->SetUseDataRange(false);
    mapper->SetScalarRange(0.0, 3.0);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    this->Renderer->AddActor(actor);
    return mapper;
  }
};

// share of pixels within 1/255 in every channel
double SameShare(const plume::test::FloatImage& a, const plume::test::FloatImage& b)
{
  size_t same = 0;
  const size_t n = static_cast<size_t>(a.Width) * a.Height;
  for (size_t p = 0; p < n; ++p)
  {
    bool equal = true;
    for (int c = 0; c < 3; ++c)
    {
      equal = equal && std::fabs(a.RGBA[4 * p + c] - b.RGBA[4 * p + c]) <= 1.0f / 255.0f;
    }
    same += equal ? 1 : 0;
  }
  return double(same) / double(n);
}
}

int TestVelocityGlyphPieces(int, char*[])
{
  int failures = 0;
  auto whole = MakePiecesField();
  const int wholeExtent[6] = { 0, PiecesNX - 1, 0, PiecesNY - 1, 0, PiecesNZ - 1 };
  vtkSmartPointer<vtkImageData> pieces[2];
  for (int p = 0; p < 2; ++p)
  {
    vtkNew<vtkExtractVOI> voi;
    voi->SetInputData(whole);
    voi->SetVOI(p == 0 ? 0 : Seam, p == 0 ? Seam : PiecesNX - 1, 0, PiecesNY - 1, 0, PiecesNZ - 1);
    voi->Update();
    pieces[p] = voi->GetOutput();
    const int* e = pieces[p]->GetExtent();
    std::printf("piece %d: extent %d..%d along x\n", p, e[0], e[1]);
  }

  for (int roots : { vtkPlumeVelocityGlyphMapper::ROOTS_SCREEN_ADAPTIVE, vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE })
  {
    const char* name = roots == vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE ? "lattice stride 3" : "screen";
    PiecesDraw reference;
    vtkPlumeVelocityGlyphMapper* one = reference.Add(whole, roots);
    const auto wholeImage = plume::test::ReadBack(reference.Window);
    const int wholeStride = one->GetEffectiveStride();
    const double speed = one->GetRobustMaximumSpeed();

    // the whole image's numbers, as ParaView's representation reduces them
    // over the ranks: the robust speed, and the moving nodes with the seam
    // counted once (on the piece below it)
    vtkIdType moving = 0;
    for (int p = 0; p < 2; ++p)
    {
      int owned[6];
      pieces[p]->GetExtent(owned);
      owned[1] -= p == 0 ? 1 : 0;
      moving += one->ComputeMovingNodes(pieces[p], owned, speed, {});

      // the representation's one call (speeds collected once) gives what the
      // two calls give, bit for bit, with its collective sums in the same
      // order (recorded: a one-rank sum leaves the counts as they are)
      std::vector<size_t> sumsTwo, sumsOne;
      auto recorder = [](std::vector<size_t>& log) {
        return vtkPlumePercentile::Sum([&log](std::vector<vtkIdType>& counts) { log.push_back(counts.size()); });
      };
      const double pieceSpeed = one->ComputeRobustMaximumSpeed(pieces[p], owned, recorder(sumsTwo));
      const vtkIdType pieceMoving = one->ComputeMovingNodes(pieces[p], owned, pieceSpeed, recorder(sumsTwo));
      vtkIdType onceMoving = -1;
      const double onceSpeed = one->ComputeRobustMaximumSpeed(pieces[p], owned, recorder(sumsOne), &onceMoving);
      std::printf("piece %d: robust speed %.9g, moving %lld (two calls); %.9g, %lld (one call); %zu / %zu sums\n",
        p, pieceSpeed, static_cast<long long>(pieceMoving), onceSpeed, static_cast<long long>(onceMoving),
        sumsTwo.size(), sumsOne.size());
      PLUME_CHECK(pieceSpeed > 0 && pieceMoving > 0);
      PLUME_CHECK(std::memcmp(&onceSpeed, &pieceSpeed, sizeof(double)) == 0);
      PLUME_CHECK(onceMoving == pieceMoving);
      PLUME_CHECK(sumsOne == sumsTwo);
    }
    PiecesDraw together, alone;
    int strides[2] = { 0, 0 };
    vtkPlumeVelocityGlyphMapper* split[2];
    for (int p = 0; p < 2; ++p)
    {
      split[p] = together.Add(pieces[p], roots);
      split[p]->SetWholeExtent(wholeExtent);
      split[p]->SetMovingNodeCount(moving);
      split[p]->SetAutomaticScaleSpeed(speed);
      alone.Add(pieces[p], roots);
    }
    const auto togetherImage = plume::test::ReadBack(together.Window);
    const auto aloneImage = plume::test::ReadBack(alone.Window);
    for (int p = 0; p < 2; ++p)
    {
      strides[p] = split[p]->GetEffectiveStride();
    }
    const double togetherShare = SameShare(wholeImage, togetherImage);
    const double aloneShare = SameShare(wholeImage, aloneImage);
    const size_t drawn = plume::test::CountForeground(wholeImage, std::vector<double>{ 0, 0, 0 }.data());
    std::printf("%s: whole stride %d, pieces' strides %d %d (moving nodes %lld); pieces vs whole: %.4f %% of "
                "pixels within 1/255 with the whole's lattice, %.4f %% alone (%zu pixels drawn)\n",
      name, wholeStride, strides[0], strides[1], static_cast<long long>(moving), 100.0 * togetherShare,
      100.0 * aloneShare, drawn);
    PLUME_CHECK(drawn > 2000);
    PLUME_CHECK(strides[0] == wholeStride && strides[1] == wholeStride);
    PLUME_CHECK(wholeStride >= 2); // else there is no lattice to misplace
    PLUME_CHECK(togetherShare >= 0.9995);
    PLUME_CHECK(aloneShare < 0.99); // the scene tells
  }
  return failures == 0 ? 0 : 1;
}
