// Image test: carotid artery blood flow (shared data classic/carotid.vtk).
// Left: plain lines in the actor colour; right: coloured by |v|. Both views
// hold an opaque sphere and an outline to show depth compositing with
// ordinary VTK actors.
#include "vtkPlumeVelocityGlyphMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkStructuredPoints.h"
#include "vtkStructuredPointsReader.h"

#include "plumeGlyphTestUtil.h"

int TestVelocityGlyphCarotid(int argc, char* argv[])
{
  const std::string path = plume::test::DataPath("classic/carotid.vtk");
  vtkNew<vtkStructuredPointsReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  if (!reader->GetOutput() || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    std::cerr << "cannot read " << path << "\n";
    return EXIT_FAILURE;
  }

  auto window = plume::test::MakeOffscreenWindow(480, 260);
  for (int side = 0; side < 2; ++side)
  {
    vtkNew<vtkPlumeVelocityGlyphMapper> mapper;
    mapper->SetInputConnection(reader->GetOutputPort());
    mapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
    mapper->SetLatticeStride(3);
    mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
    mapper->SetScale(0.6);
    mapper->SetMinimumSpeed(0.5);
    mapper->SetColorByMagnitude(side == 1);
    mapper->SetRootAlpha(side == 0 ? 0.0 : 0.2);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetDiffuseColor(1.0, 0.85, 0.6);

    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(118, 104, 22);
    sphere->SetRadius(9);
    sphere->SetThetaResolution(32);
    sphere->SetPhiResolution(16);
    vtkNew<vtkPolyDataMapper> sphereMapper;
    sphereMapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> sphereActor;
    sphereActor->SetMapper(sphereMapper);
    sphereActor->GetProperty()->SetColor(0.35, 0.45, 0.9);

    auto outlineActor = plumetest::OutlineActor(reader->GetOutput()->GetBounds(), 0.8);

    vtkNew<vtkRenderer> ren;
    ren->SetViewport(0.5 * side, 0, 0.5 * side + 0.5, 1);
    ren->SetBackground(0.05, 0.05, 0.08);
    ren->AddActor(sphereActor);
    ren->AddActor(outlineActor);
    ren->AddActor(actor); // glyphs after the opaque actors (see the class documentation)
    vtkCamera* cam = ren->GetActiveCamera();
    cam->SetFocalPoint(137, 104, 23);
    cam->SetPosition(137 + 40, 104 - 130, 23 + 90);
    cam->SetViewUp(0, 0, 1);
    ren->ResetCamera();
    cam->Zoom(1.6);
    window->AddRenderer(ren);
  }
  return plumetest::RenderAndCompare(window, argc, argv);
}
