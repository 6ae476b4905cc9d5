// Image test: seed mode. A tilted plane of seed points in the vortex; left:
// straight wide (3 px) glyphs, right: RK4 streamlets, 1 px.
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkPlumeVortexSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "plumeGlyphTestUtil.h"

int TestVelocityGlyphSeeds(int argc, char* argv[])
{
  vtkNew<vtkPlumeVortexSource> vortex;
  vortex->SetDimensions(32, 32, 16);
  vortex->SetBounds(-1, 1, -1, 1, -0.5, 0.5);
  vortex->SetCenter(0.1, 0.15, 0);

  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-0.9, -0.8, -0.3);
  plane->SetPoint1(0.9, -0.8, 0.2);
  plane->SetPoint2(-0.9, 0.7, -0.1);
  plane->SetResolution(13, 11);

  auto window = plume::test::MakeOffscreenWindow(400, 220);
  for (int side = 0; side < 2; ++side)
  {
    vtkNew<vtkPlumeVelocityGlyphMapper> mapper;
    mapper->SetInputConnection(vortex->GetOutputPort());
    mapper->SetSeedConnection(plane->GetOutputPort());
    mapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_SEEDS);
    if (side == 0)
    {
      mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
      mapper->SetScale(0.3);
      mapper->SetLineWidth(3.0);
    }
    else
    {
      mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
      mapper->SetScale(0.9);
      mapper->SetIntegrator(vtkPlumeVelocityGlyphMapper::RK4);
      mapper->SetStreamletSegments(16);
    }
    mapper->SetRootAlpha(0.15);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);

    const double box[6] = { -1, 1, -1, 1, -0.5, 0.5 };
    auto outlineActor = plumetest::OutlineActor(box, 1.0);

    vtkNew<vtkRenderer> ren;
    ren->SetViewport(0.5 * side, 0, 0.5 * side + 0.5, 1);
    ren->SetBackground(0.1, 0.1, 0.1);
    ren->AddActor(outlineActor);
    ren->AddActor(actor);
    vtkCamera* cam = ren->GetActiveCamera();
    cam->SetFocalPoint(0, 0, 0);
    cam->SetPosition(-0.8, -2.4, 2.2);
    cam->SetViewUp(0, 0, 1);
    ren->ResetCamera();
    cam->Zoom(1.2);
    window->AddRenderer(ren);
  }
  return plumetest::RenderAndCompare(window, argc, argv);
}
