// Image test: the analytic Lamb-Oseen vortex drawn as a plain lattice of
// straight glyphs (left) and as RK4 streamlets (right), coloured by |v|.
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkPlumeVortexSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "plumeGlyphTestUtil.h"

int TestVelocityGlyphVortex(int argc, char* argv[])
{
  vtkNew<vtkPlumeVortexSource> vortex;
  vortex->SetDimensions(24, 24, 12);
  vortex->SetBounds(-1, 1, -1, 1, -0.5, 0.5);
  vortex->SetCenter(0.15, -0.1, 0);

  auto window = plume::test::MakeOffscreenWindow(400, 200);
  for (int side = 0; side < 2; ++side)
  {
    vtkNew<vtkPlumeVelocityGlyphMapper> mapper;
    mapper->SetInputConnection(vortex->GetOutputPort());
    mapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
    mapper->SetLatticeStride(side == 0 ? 2 : 3);
    mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
    mapper->SetScale(side == 0 ? 0.35 : 0.8);
    mapper->SetIntegrator(side == 0 ? vtkPlumeVelocityGlyphMapper::STRAIGHT
                                    : vtkPlumeVelocityGlyphMapper::RK4);
    mapper->SetStreamletSegments(12);
    mapper->SetRootAlpha(0.1);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);

    const double box[6] = { -1, 1, -1, 1, -0.5, 0.5 };
    auto outlineActor = plumetest::OutlineActor(box, 0.9);

    vtkNew<vtkRenderer> ren;
    ren->SetViewport(0.5 * side, 0, 0.5 * side + 0.5, 1);
    ren->SetBackground(0.08, 0.08, 0.12);
    ren->AddActor(outlineActor);
    ren->AddActor(actor);
    ren->GetActiveCamera()->SetPosition(0.6, -2.2, 2.6);
    ren->GetActiveCamera()->SetFocalPoint(0, 0, 0);
    ren->GetActiveCamera()->SetViewUp(0, 0, 1);
    ren->ResetCamera();
    ren->GetActiveCamera()->Zoom(1.3);
    window->AddRenderer(ren);
  }
  return plumetest::RenderAndCompare(window, argc, argv);
}
