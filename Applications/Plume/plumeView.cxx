#include "plumeView.h"

#include "plumeImageOutput.h"
#include "plumeRenderWindowFactory.h"
#include "plumeScene.h"
#include "plumeSceneError.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlumeSheetMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

namespace plume
{
const char* ViewKeys()
{
  return "keys in the window: left drag rotate, middle drag (or shift+left) pan, right drag (or wheel) zoom, "
         "ctrl+left spin; r back to the scene's camera; s save a screenshot (PREFIX_NNNN.png, the frame as "
         "shown); c save the camera (PREFIX_camera_NNNN.json: plume render SCENE --camera FILE shows the same "
         "view); n / p (or Right / Left) next / previous time step; 1-9 show/hide representation 1-9 (scene "
         "order, with its colour bar); q or Escape quit";
}

nlohmann::json CameraToJson(vtkCamera* camera)
{
  auto vector = [](const double* v) { return nlohmann::json::array({ v[0], v[1], v[2] }); };
  nlohmann::json out;
  out["position"] = vector(camera->GetPosition());
  out["focal_point"] = vector(camera->GetFocalPoint());
  out["view_up"] = vector(camera->GetViewUp());
  out["view_angle"] = camera->GetViewAngle();
  if (camera->GetParallelProjection())
  {
    out["parallel_projection"] = true;
    out["parallel_scale"] = camera->GetParallelScale();
  }
  return out;
}

namespace
{
/** The viewer's state: the scene, its renderer (rebuilt for another time step), the saved camera. */
struct Viewer
{
  nlohmann::json Scene;
  std::string Directory;
  ViewOptions Options;
  std::ostream* Out = nullptr;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkNew<vtkCamera> SceneCamera; // as the scene set it: what r restores and plume render shows
  SceneOptions Built;            // what the last Build reported (steps, props per representation)
  std::vector<bool> Hidden; // representations hidden with keys 1-9 (kept across time steps)
  int Screenshots = 0;
  int Cameras = 0;
  bool Quit = false;

  void Build(int timeStep, vtkCamera* keep)
  {
    SceneOptions options;
    options.Width = this->Options.Width;
    options.Height = this->Options.Height;
    options.TimeStep = timeStep;
    vtkNew<vtkRenderer> renderer;
    plume::Scene::Build(this->Scene, this->Directory, renderer, options);
    this->SceneCamera->DeepCopy(renderer->GetActiveCamera());
    if (keep)
    {
      renderer->GetActiveCamera()->DeepCopy(keep); // another step seen from where the user is
    }
    renderer->ResetCameraClippingRange();
    if (this->Renderer)
    {
      this->Window->RemoveRenderer(this->Renderer);
    }
    this->Renderer = renderer;
    this->Built = std::move(options);
    this->Hidden.resize(this->Built.RepresentationProps.size(), false);
    for (size_t i = 0; i < this->Hidden.size(); ++i)
    {
      for (auto& prop : this->Built.RepresentationProps[i])
      {
        prop->SetVisibility(this->Hidden[i] ? 0 : prop->GetVisibility());
      }
    }
    if (this->Window)
    {
      this->Window->AddRenderer(renderer);
    }
  }

  void Screenshot()
  {
    char name[32];
    std::snprintf(name, sizeof(name), "_%04d.png", this->Screenshots++);
    const std::string path = this->Options.ScreenshotPrefix + name;
    // the frame last shown (not rendered again: a frame taken while moving keeps its interactive look)
    plume::WriteImage(path, plume::ReadBack(this->Window, false), this->Renderer->GetActiveCamera());
    *this->Out << "wrote " << path << "\n";
  }

  /** The camera shown, as a scene "camera" object in PREFIX_camera_NNNN.json (for plume render --camera). */
  void SaveCamera()
  {
    char name[32];
    std::snprintf(name, sizeof(name), "_camera_%04d.json", this->Cameras++);
    const std::string path = this->Options.ScreenshotPrefix + name;
    const nlohmann::json camera = { { "camera", CameraToJson(this->Renderer->GetActiveCamera()) } };
    std::ofstream file(path);
    file << camera.dump(2) << "\n";
    file.close();
    if (!file)
    {
      *this->Out << "could not write " << path << "\n";
      return;
    }
    *this->Out << "wrote " << path << "\n";
  }

  void Step(int delta)
  {
    const int steps = this->Built.NumberOfTimeSteps;
    if (steps < 2)
    {
      *this->Out << "no time series in this scene\n";
      return;
    }
    const int step = std::max(0, std::min(steps - 1, this->Built.TimeStepShown + delta));
    if (step == this->Built.TimeStepShown)
    {
      return;
    }
    vtkNew<vtkCamera> keep;
    keep->DeepCopy(this->Renderer->GetActiveCamera());
    this->Build(step, keep);
    *this->Out << "time step " << step << " of 0.." << steps - 1 << "\n";
    this->Window->Render();
  }

  void Toggle(size_t index)
  {
    if (index >= this->Built.RepresentationProps.size())
    {
      return;
    }
    this->Hidden[index] = !this->Hidden[index];
    for (auto& prop : this->Built.RepresentationProps[index])
    {
      prop->SetVisibility(!this->Hidden[index]);
    }
    *this->Out << "representation " << index + 1 << (this->Hidden[index] ? " hidden" : " shown") << "\n";
    this->Window->Render();
  }
};

/** Trackball camera with plume's keys (the keys VTK's style binds otherwise — wireframe, stereo, pick — are off). */
class plumeViewStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static plumeViewStyle* New();
  vtkTypeMacro(plumeViewStyle, vtkInteractorStyleTrackballCamera);
  Viewer* View = nullptr;

  void OnChar() override
  {
    vtkRenderWindowInteractor* iren = this->Interactor;
    const std::string sym = iren->GetKeySym() ? iren->GetKeySym() : "";
    const char key = iren->GetKeyCode();
    if (key == 'q' || key == 'Q' || sym == "Escape")
    {
      this->View->Quit = true;
      iren->ExitCallback();
    }
    else if (key == 'r' || key == 'R')
    {
      this->View->Renderer->GetActiveCamera()->DeepCopy(this->View->SceneCamera);
      this->View->Renderer->ResetCameraClippingRange();
      iren->Render();
    }
    else if (key == 's' || key == 'S')
    {
      this->View->Screenshot();
    }
    else if (key == 'c' || key == 'C')
    {
      this->View->SaveCamera();
    }
    else if (key == 'n' || key == 'N' || sym == "Right")
    {
      this->View->Step(1);
    }
    else if (key == 'p' || key == 'P' || sym == "Left")
    {
      this->View->Step(-1);
    }
    else if (key >= '1' && key <= '9')
    {
      this->View->Toggle(static_cast<size_t>(key - '1'));
    }
  }
};
vtkStandardNewMacro(plumeViewStyle);

/** A key press as X would deliver it: KeyPress, then Char (the style's OnChar). */
void PressKey(vtkRenderWindowInteractor* iren, char key)
{
  const char sym[2] = { key, 0 };
  iren->SetKeyEventInformation(0, 0, key, 1, sym);
  iren->InvokeEvent(vtkCommand::KeyPressEvent, nullptr);
  iren->InvokeEvent(vtkCommand::CharEvent, nullptr);
  iren->InvokeEvent(vtkCommand::KeyReleaseEvent, nullptr);
}

/** The smallest render time VTK allocated to a volume in the last frame (what the volume mapper reads). */
std::string VolumeAllocated(vtkRenderer* renderer)
{
  vtkVolumeCollection* volumes = renderer->GetVolumes();
  volumes->InitTraversal();
  double least = -1;
  while (vtkVolume* v = volumes->GetNextVolume())
  {
    least = least < 0 ? v->GetAllocatedRenderTime() : std::min(least, v->GetAllocatedRenderTime());
  }
  if (least < 0)
  {
    return "no volume";
  }
  std::ostringstream out;
  out << "volume allocated " << least << " s (" << (least < 1.0 ? "interactive" : "still") << " settings)";
  return out.str();
}

/**
 * VolumeAllocated, and how each grid-mode sheet drew the last frame (its
 * interactive or still raycast settings).
 */
std::string VolumeTimes(vtkRenderer* renderer)
{
  std::ostringstream sheets;
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
  {
    auto* sheet = vtkPlumeSheetMapper::SafeDownCast(actor->GetMapper());
    if (sheet && sheet->GetRenderMode() == vtkPlumeSheetMapper::RENDER_GRID && actor->GetVisibility())
    {
      sheets << ", sheet grid " << (sheet->GetLastInteractive() ? "interactive" : "still") << " (step "
             << sheet->GetLastGridSampleDistance() << " spacings, 1 ray per " << sheet->GetLastImageSampleDistance()
             << " px)";
    }
  }
  return VolumeAllocated(renderer) + sheets.str();
}
}

int View(const nlohmann::json& scene, const std::string& sceneDirectory, const ViewOptions& options, std::ostream& out)
{
  Viewer viewer;
  viewer.Scene = scene;
  viewer.Directory = sceneDirectory;
  viewer.Options = options;
  viewer.Out = &out;
  viewer.Build(-1, nullptr); // before the window: a bad scene fails without opening one
  viewer.Window = plume::RequireInteractiveWindow(viewer.Built.Width, viewer.Built.Height);
  viewer.Window->SetWindowName("plume view");
  viewer.Window->AddRenderer(viewer.Renderer);

  vtkNew<vtkRenderWindowInteractor> iren;
  iren->SetRenderWindow(viewer.Window);
  // VTK's interactive convention: the window asks for DesiredUpdateRate frames
  // per second while the camera moves (the renderer shares 1/rate seconds among
  // its props; the volume mapper takes its interactive ray lattice below 1 s)
  // and StillUpdateRate (VTK's default 0.0001, as plume render) when it stops.
  iren->SetDesiredUpdateRate(options.DesiredUpdateRate);
  iren->SetStillUpdateRate(0.0001);
  vtkNew<plumeViewStyle> style;
  style->View = &viewer;
  iren->SetInteractorStyle(style);
  iren->Initialize();
  viewer.Window->Render();

  if (options.ScriptedMoves <= 0)
  {
    out << ViewKeys() << "\n";
    out.flush();
    iren->Start();
    return 0;
  }

  // Scripted (tests): the same events X delivers, through the same interactor and style.
  const int* size = viewer.Window->GetSize();
  const int x0 = size[0] / 2;
  const int y0 = size[1] / 2;
  iren->SetEventInformationFlipY(x0, y0, 0, 0);
  iren->InvokeEvent(vtkCommand::LeftButtonPressEvent, nullptr);
  for (int k = 1; k <= options.ScriptedMoves; ++k)
  {
    iren->SetEventInformationFlipY(x0 + 6 * k, y0 + 2 * k, 0, 0);
    iren->InvokeEvent(vtkCommand::MouseMoveEvent, nullptr); // the style rotates and renders
    out << "move " << k << "/" << options.ScriptedMoves << ": update rate " << viewer.Window->GetDesiredUpdateRate()
        << " per s, " << VolumeTimes(viewer.Renderer) << "\n";
    PressKey(iren, 's');
  }
  iren->InvokeEvent(vtkCommand::LeftButtonReleaseEvent, nullptr); // stops: a still frame
  out << "released: update rate " << viewer.Window->GetDesiredUpdateRate() << " per s, "
      << VolumeTimes(viewer.Renderer) << "\n";
  PressKey(iren, 's');
  PressKey(iren, 'c'); // the moved camera: plume render --camera must show this still frame
  PressKey(iren, 'r');
  out << "camera reset: update rate " << viewer.Window->GetDesiredUpdateRate() << " per s, "
      << VolumeTimes(viewer.Renderer) << "\n";
  PressKey(iren, 's');
  for (char key : options.ScriptedKeys)
  {
    PressKey(iren, key);
  }
  PressKey(iren, 'q');
  out << (viewer.Quit ? "quit\n" : "q did not quit\n");
  return viewer.Quit ? 0 : 1;
}
}
