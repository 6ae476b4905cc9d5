// GPU hand-over: with the GPU backend, GPUHandOver on and the render window
// given to the solver, vtkPlumeVolumeMapper binds the solver's density
// texture and vtkPlumeVelocityGlyphMapper its cell-velocity texture instead
// of uploading the output arrays, and the image is the one rendering the
// read-back arrays (a deep copy, uploaded) gives, pixel for pixel. A step
// revokes the textures: an output kept from before it is uploaded from its
// own values (the old image), the new output is handed over again.
#include "plumeSolverTestUtilities.h"
#include "vtkPlumePressureSolver.h"
#include "vtkPlumeSmokeSolver.h"
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkPlumeVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cstdlib>
#include <string>

using namespace plume_solver_test;

namespace
{
const int Width = 240, Height = 200;

struct View
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkPlumeVolumeMapper> VolumeMapper;
  vtkNew<vtkActor> Glyphs;
  vtkNew<vtkPlumeVelocityGlyphMapper> GlyphMapper;
  View()
  {
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(Width, Height);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.0, 0.9, 0.9, 0.95);
    color->AddRGBPoint(1.0, 1.0, 0.6, 0.2);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(1.0, 0.8);
    this->Volume->GetProperty()->SetColor(color);
    this->Volume->GetProperty()->SetScalarOpacity(opacity);
    this->Volume->GetProperty()->SetScalarOpacityUnitDistance(0.05);
    this->Volume->SetMapper(this->VolumeMapper);
    this->Renderer->AddVolume(this->Volume);
    this->GlyphMapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
    this->GlyphMapper->SetLatticeStride(3);
    this->GlyphMapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
    this->GlyphMapper->SetScale(0.4);
    this->GlyphMapper->SetRootAlpha(1.0);
    this->Glyphs->SetMapper(this->GlyphMapper);
    this->Renderer->AddActor(this->Glyphs);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(1.9, -1.6, 1.2);
    camera->SetFocalPoint(0.5, 0.45, 0.45);
    camera->SetViewUp(0, 0, 1);
  }
  void SetInput(vtkPlumeSmokeSolver* solver)
  {
    this->VolumeMapper->SetInputConnection(solver->GetOutputPort());
    this->GlyphMapper->SetInputConnection(solver->GetOutputPort());
  }
  void SetInput(vtkImageData* image)
  {
    this->VolumeMapper->SetInputData(image);
    this->GlyphMapper->SetInputData(image);
  }
  std::vector<unsigned char> Image()
  {
    this->Renderer->ResetCameraClippingRange();
    this->Window->Render();
    vtkNew<vtkUnsignedCharArray> pixels;
    this->Window->GetRGBACharPixelData(0, 0, Width - 1, Height - 1, 0, pixels);
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

// pixels that are not the background
int Lit(const std::vector<unsigned char>& image, const std::vector<unsigned char>& empty)
{
  int lit = 0;
  for (size_t i = 0; i + 3 < image.size(); i += 4)
  {
    lit += std::abs(int(image[i]) - int(empty[i])) + std::abs(int(image[i + 1]) - int(empty[i + 1])) +
        std::abs(int(image[i + 2]) - int(empty[i + 2])) >
      6;
  }
  return lit;
}

void Save(const std::vector<unsigned char>& rgba, const std::string& path)
{
  vtkNew<vtkImageData> out;
  out->SetDimensions(Width, Height, 1);
  vtkNew<vtkUnsignedCharArray> px;
  px->SetNumberOfComponents(4); // alpha is 0 on the background: viewers show it transparent
  px->SetNumberOfTuples(vtkIdType(Width) * Height);
  std::copy(rgba.begin(), rgba.end(), px->GetPointer(0));
  out->GetPointData()->SetScalars(px);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(out);
  writer->SetFileName(path.c_str());
  writer->Write();
}
}

int TestSmokeSolverHandOver(int, char*[])
{
  View view;
  vtkNew<vtkPlumeSmokeSolver> solver;
  solver->SetBackend(vtkPlumeSmokeSolver::BACKEND_GPU);
  solver->SetRenderWindow(view.Window);
  solver->GPUHandOverOn();
  solver->SetDimensions(24, 22, 28);
  solver->SetSpacing(0.04, 0.04, 0.035);
  solver->SetTimeStep(0.04);
  solver->SetOpenFaces("zmax");
  solver->SetPressureMaximumIterations(40); // the seed's
  const double c[3] = { 0.35, 0.4, 0.1 }, v[3] = { 0.8, 0.0, 0.3 };
  solver->AddSource(c, 0.09, 1.0, 1.0, v);
  const double sphere[3] = { 0.55, 0.45, 0.55 };
  solver->AddObstacleSphere(sphere, 0.15);
  for (int i = 0; i < 20; ++i)
  {
    PLUME_CHECK(solver->Step(), solver->GetLastError());
  }
  view.SetInput(solver);
  view.Volume->VisibilityOff();
  view.Glyphs->VisibilityOff();
  const auto empty = view.Image(); // the background alone
  view.Volume->VisibilityOn();
  view.Glyphs->VisibilityOn();

  // 1. the hand-over replaces both uploads
  const auto handed = view.Image();
  std::cout << "volume mapper: hand-overs " << view.VolumeMapper->GetHandOverCount() << ", uploads "
            << view.VolumeMapper->GetUploadCount() << "; glyph mapper: hand-overs "
            << view.GlyphMapper->GetHandOverCount() << ", uploads " << view.GlyphMapper->GetUploadCount()
            << "; lit pixels " << Lit(handed, empty) << "\n";
  PLUME_CHECK(view.VolumeMapper->GetHandOverCount() == 1 && view.VolumeMapper->GetUploadCount() == 0,
    "volume mapper uploaded");
  PLUME_CHECK(view.GlyphMapper->GetHandOverCount() == 1 && view.GlyphMapper->GetUploadCount() == 0,
    "glyph mapper uploaded");
  PLUME_CHECK(Lit(handed, empty) > 2000, "little drawn: " << Lit(handed, empty)); // smoke and glyphs, not an empty frame
  if (const char* dump = std::getenv("PLUME_SOLVER_DUMP")) // a folder: look at the image
  {
    Save(handed, std::string(dump) + "/TestSmokeSolverHandOver.png");
  }

  // 2. the read-back arrays, uploaded (a deep copy carries no valid hand-over), draw the same image
  vtkNew<vtkImageData> copy;
  copy->DeepCopy(solver->GetOutput());
  view.SetInput(copy);
  const auto uploaded = view.Image();
  PLUME_CHECK(view.VolumeMapper->GetUploadCount() == 1 && view.GlyphMapper->GetUploadCount() == 1,
    "the copy was not uploaded");
  const int diff = MaxDifference(handed, uploaded);
  std::cout << "hand-over vs read-back upload: max channel difference " << diff << "\n";
  PLUME_CHECK(diff == 0, "the handed-over textures draw another image: " << diff);

  // 3. a step revokes: the kept output (same arrays) is uploaded from its own values and draws the old image
  vtkNew<vtkImageData> kept;
  kept->ShallowCopy(solver->GetOutput());
  PLUME_CHECK(solver->Step(), solver->GetLastError());
  view.SetInput(kept);
  PLUME_CHECK(MaxDifference(view.Image(), handed) == 0, "the kept output drew the new textures");
  PLUME_CHECK(view.VolumeMapper->GetHandOverCount() == 1 && view.VolumeMapper->GetUploadCount() == 2,
    "kept output: volume hand-overs " << view.VolumeMapper->GetHandOverCount() << ", uploads "
                                      << view.VolumeMapper->GetUploadCount());
  // 4. the new output is handed over again, and differs from the old
  view.SetInput(solver);
  const auto next = view.Image();
  PLUME_CHECK(view.VolumeMapper->GetHandOverCount() == 2 && view.GlyphMapper->GetHandOverCount() == 2,
    "new step not handed over");
  PLUME_CHECK(MaxDifference(next, handed) > 0, "the step changed nothing");

  // 5. off: the arrays are uploaded
  solver->GPUHandOverOff();
  PLUME_CHECK(solver->Step(), solver->GetLastError());
  view.Image();
  PLUME_CHECK(view.VolumeMapper->GetHandOverCount() == 2 && view.VolumeMapper->GetUploadCount() == 3,
    "hand-over off: volume hand-overs " << view.VolumeMapper->GetHandOverCount());
  solver->ReleaseGraphicsResources();
  return Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
