// Velocity glyph lines of an analytic vortex, rendered offscreen; exits
// non-zero unless something was drawn. Built against an installed Plume.
#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPlumeVelocityGlyphMapper.h>
#include <vtkPlumeVortexSource.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <iostream>

int main()
{
  vtkNew<vtkPlumeVortexSource> vortex;
  vortex->SetDimensions(24, 24, 24);
  vortex->Update();

  vtkNew<vtkPlumeVelocityGlyphMapper> mapper;
  mapper->SetInputData(vortex->GetOutput());
  mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
  mapper->SetScale(0.3);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0, 0, 0);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(200, 150);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, 199, 149, 0, pixels);
  long lit = 0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfValues(); ++i)
  {
    lit += pixels->GetValue(i) > 20;
  }
  std::cout << "lit channel values: " << lit << "\n";
  return lit > 100 ? 0 : 1;
}
