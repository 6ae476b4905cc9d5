// GPU hand-over: with GPUHandOver on and the glyph mapper's render window
// given to the splatter, the mapper binds the splatter's texture instead of
// uploading the velocity array, and the image is the one an upload gives.
// The hand-over must not be used once it is stale: after the array is
// modified, in another window, for a deep copy, or for an array kept while the
// splatter wrote a new result into the texture.
#include "plumeSplatTestUtil.h"

#include "vtkPlumeVelocityGlyphMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkMath.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <cstdlib>

namespace
{
vtkSmartPointer<vtkPolyData> Circle(int n)
{
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> cells;
  cells->InsertNextCell(n + 1);
  for (int i = 0; i < n; ++i)
  {
    const double t = 2 * vtkMath::Pi() * i / n;
    cells->InsertCellPoint(pts->InsertNextPoint(std::cos(t), 0.8 * std::sin(t), 0.1 * std::sin(3 * t)));
  }
  cells->InsertCellPoint(0);
  auto circle = vtkSmartPointer<vtkPolyData>::New();
  circle->SetPoints(pts);
  circle->SetLines(cells);
  return circle;
}

struct View
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkPlumeVelocityGlyphMapper> Mapper;
  View()
  {
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(160, 120);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->AddActor(this->Actor);
    this->Actor->SetMapper(this->Mapper);
    this->Mapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
    this->Mapper->SetLatticeStride(2);
    this->Mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
    this->Mapper->SetScale(0.06);
    this->Mapper->SetRootAlpha(1.0);
    this->Renderer->GetActiveCamera()->SetPosition(0.3, -2.5, 2.0);
    this->Renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);
    this->Renderer->GetActiveCamera()->SetViewUp(0, 0, 1);
  }
  std::vector<unsigned char> Image()
  {
    this->Renderer->ResetCameraClippingRange();
    this->Window->Render();
    vtkNew<vtkUnsignedCharArray> pixels;
    this->Window->GetRGBACharPixelData(0, 0, 159, 119, 0, pixels);
    return std::vector<unsigned char>(pixels->GetPointer(0), pixels->GetPointer(0) + pixels->GetNumberOfValues());
  }
};

int MaxDifference(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  int worst = a.size() == b.size() ? 0 : 256;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
  {
    worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
  }
  return worst;
}

int Lit(const std::vector<unsigned char>& image)
{
  int lit = 0;
  for (size_t i = 0; i < image.size(); i += 4)
  {
    lit += image[i] + image[i + 1] + image[i + 2] > 0;
  }
  return lit;
}
}

int TestSplatHandOver(int, char*[])
{
  int failures = 0;
  View view;
  vtkNew<vtkPlumeGaussianSplatter> splatter;
  splatter->SetLinesData(Circle(128));
  splatter->SetRadius(0.12);
  splatter->SetDimensions(40, 36, 16);
  splatter->SetBackend(vtkPlumeGaussianSplatter::BACKEND_GPU);
  splatter->SetRenderWindow(view.Window);
  splatter->GPUHandOverOn();
  view.Mapper->SetInputConnection(splatter->GetOutputPort());
  view.Renderer->ResetCamera();

  // 1. the hand-over replaces the upload
  const auto handed = view.Image();
  PLUME_CHECK(splatter->GetLastBackend() == vtkPlumeGaussianSplatter::BACKEND_GPU);
  PLUME_CHECK(view.Mapper->GetHandOverCount() == 1);
  PLUME_CHECK(view.Mapper->GetUploadCount() == 0);
  PLUME_CHECK(Lit(handed) > 500); // the torus is drawn, not an empty frame
  view.Image(); // a re-render neither uploads nor counts a new hand-over
  PLUME_CHECK(view.Mapper->GetHandOverCount() == 1 && view.Mapper->GetUploadCount() == 0);

  // 2. the same field uploaded from the CPU (a deep copy carries no valid
  // hand-over) gives the same image
  vtkNew<vtkImageData> copy;
  copy->DeepCopy(splatter->GetOutput());
  view.Mapper->SetInputData(copy);
  const auto uploaded = view.Image();
  PLUME_CHECK(view.Mapper->GetUploadCount() == 1);
  PLUME_CHECK(view.Mapper->GetHandOverCount() == 1);
  const int diff = MaxDifference(handed, uploaded);
  std::cout << "hand-over vs upload: max channel difference " << diff << ", lit pixels " << Lit(handed) << "\n";
  PLUME_CHECK(diff == 0);

  // 3. an array modified after the hand-over is uploaded, not taken from the stale texture
  view.Mapper->SetInputConnection(splatter->GetOutputPort());
  PLUME_CHECK(MaxDifference(view.Image(), handed) == 0);
  PLUME_CHECK(view.Mapper->GetHandOverCount() == 1 && view.Mapper->GetUploadCount() == 1); // same data: not a new hand-over
  vtkDataArray* velocity = splatter->GetOutput()->GetPointData()->GetVectors();
  for (vtkIdType i = 0; i < velocity->GetNumberOfTuples(); ++i)
  {
    velocity->SetComponent(i, 2, velocity->GetComponent(i, 2) + 5.0); // every glyph now points up
  }
  velocity->Modified();
  const auto modified = view.Image();
  PLUME_CHECK(view.Mapper->GetUploadCount() == 2);
  PLUME_CHECK(MaxDifference(modified, handed) > 0);

  // 4. a new execution hands over again: the new result is drawn
  splatter->SetRadius(0.2);
  const auto wider = view.Image();
  PLUME_CHECK(view.Mapper->GetHandOverCount() == 2 && view.Mapper->GetUploadCount() == 2);
  vtkNew<vtkImageData> widerCopy;
  widerCopy->DeepCopy(splatter->GetOutput());
  View other; // 5. another window (context) never takes the texture
  other.Mapper->SetInputData(widerCopy);
  other.Renderer->GetActiveCamera()->DeepCopy(view.Renderer->GetActiveCamera());
  const auto widerUploaded = other.Image();
  PLUME_CHECK(MaxDifference(wider, widerUploaded) == 0);
  other.Mapper->SetInputConnection(splatter->GetOutputPort());
  other.Image();
  PLUME_CHECK(other.Mapper->GetHandOverCount() == 0 && other.Mapper->GetUploadCount() == 2);

  // 6. an output kept (shallow copy: same array, same MTime) while the
  // splatter executes again: the texture now holds the new field, so the kept
  // array must be uploaded from its own values, giving the old image
  vtkNew<vtkImageData> kept;
  kept->ShallowCopy(splatter->GetOutput());
  splatter->SetRadius(0.3);
  view.Image();
  PLUME_CHECK(view.Mapper->GetHandOverCount() == 3 && view.Mapper->GetUploadCount() == 2);
  view.Mapper->SetInputData(kept);
  PLUME_CHECK(MaxDifference(view.Image(), wider) == 0);
  PLUME_CHECK(view.Mapper->GetHandOverCount() == 3 && view.Mapper->GetUploadCount() == 3);

  // 7. off by default; and never for the splatter's own offscreen window
  vtkNew<vtkPlumeGaussianSplatter> plain;
  plain->SetLinesData(Circle(64));
  plain->SetBackend(vtkPlumeGaussianSplatter::BACKEND_GPU);
  plain->SetRenderWindow(view.Window);
  view.Mapper->SetInputConnection(plain->GetOutputPort());
  view.Image();
  PLUME_CHECK(view.Mapper->GetHandOverCount() == 3 && view.Mapper->GetUploadCount() == 4);
  plain->SetRenderWindow(nullptr);
  plain->GPUHandOverOn();
  view.Image();
  PLUME_CHECK(view.Mapper->GetHandOverCount() == 3 && view.Mapper->GetUploadCount() == 5);

  splatter->ReleaseGraphicsResources();
  plain->ReleaseGraphicsResources();
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
