// `plume view SCENE|FILE`: the scene `plume render` would render, in an
// on-screen VTK window with trackball interaction (X display needed).
#ifndef plumeView_h
#define plumeView_h

#include <nlohmann/json.hpp>

class vtkCamera;

#include <ostream>
#include <string>

namespace plume
{
struct ViewOptions
{
  int Width = 0; ///< 0: the scene's size (as plume render)
  int Height = 0;
  /** Frames per second asked for while the camera moves (VTK's interactive DesiredUpdateRate). */
  double DesiredUpdateRate = 15;
  /**
   * Screenshots (key s) are PREFIX_0000.png, PREFIX_0001.png, ...; saved
   * cameras (key c) PREFIX_camera_0000.json, ... (for plume render --camera).
   */
  std::string ScreenshotPrefix = "plume_view";
  /**
   * > 0: no event loop; drive the interactor with this many scripted mouse
   * drags (a screenshot after each), release, screenshot, c (save the
   * camera), r, screenshot, q
   * (what the tests run under Xvfb).
   */
  int ScriptedMoves = 0;
  /** Scripted mode: these keys pressed after the script's r and its screenshot, before q (e.g. "ps1s"). */
  std::string ScriptedKeys;
};

/** The key bindings, for --help and the window's start-up line. */
const char* ViewKeys();

/**
 * A camera as the scene's "camera" object: position, focal point, view up,
 * view angle (and parallel projection and scale), with every double written
 * to round trip, so plume render --camera reproduces the view exactly.
 */
nlohmann::json CameraToJson(vtkCamera* camera);

/** Opens the window and runs until q (or the script ends). Throws SceneError / std::runtime_error. */
int View(const nlohmann::json& scene, const std::string& sceneDirectory, const ViewOptions& options,
  std::ostream& out);
}

#endif
