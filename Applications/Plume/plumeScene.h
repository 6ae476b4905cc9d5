// A scene file (JSON) turned into a VTK renderer. The format is documented in
// Documentation/SceneFormat.md; every key is checked, unknown keys and bad
// values are errors that name the offending value (SceneError).
#ifndef plumeScene_h
#define plumeScene_h

#include "vtkProp.h"
#include "vtkSmartPointer.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <istream>
#include <map>
#include <string>
#include <vector>

class vtkDataObject;
class vtkImageData;
class vtkPlumeSmokeSolver;
class vtkRenderer;

namespace plume
{
class Parameters;

/**
 * One line for the user (a stated default, a warning) through VTK's output
 * window: plume prints these after a successful render, so a failure still
 * shows only its one error line. `line` has no "plume: " prefix or newline.
 */
void Note(const std::string& line);

/** Bytes a scene may allocate for one resampled grid: $PLUME_MEMORY_BUDGET_MB, else half the RAM. */
double MemoryBudgetBytes();

/** Datasets of a scene, loaded once each, by name. */
/** The shared data folder: $PLUME_DATA_DIR if set, else the configured default. */
std::string DataFolder();

class SceneDatasets
{
public:
  SceneDatasets(const nlohmann::json* datasets, std::string sceneDirectory, bool progress, int timeStep = -1);
  /** The dataset as read (composites merged unless the scene says otherwise). */
  vtkDataObject* Get(const std::string& name, const std::string& where);
  /** The dataset on an image grid (resampled if it is not one already). */
  vtkImageData* GetImage(const std::string& name, const std::string& where);
  /**
   * An "up" direction from the loaded datasets' gravity, if one says: a field
   * array "gravity" or "g" (3 components), or an OpenFOAM case's
   * constant/g; up is -g. `from` names the source. False without a hint.
   */
  bool GravityUp(double up[3], std::string& from) const;
  /** Resolve a path against the scene's folder, then the shared data folder. */
  std::string Resolve(const std::string& path) const;
  /** The most time steps of a dataset read so far (0 if none is a series). */
  int GetNumberOfTimeSteps() const { return this->TimeSteps; }
  /** "t = 2.5" for the first time series read (its step shown), "" if none is a series. */
  const std::string& GetTimeLabel() const { return this->TimeLabel; }
  /** The step index of that first time series (-1 if none is a series). */
  int GetTimeStepShown() const { return this->TimeStepShown; }
  /** Whether progress bars are drawn (plume render on a terminal). */
  bool ProgressEnabled() const { return this->Progress; }

private:
  struct Entry
  {
    nlohmann::json Spec;
    vtkSmartPointer<vtkDataObject> Data;
    vtkSmartPointer<vtkImageData> Image;
  };
  std::map<std::string, Entry> Entries;
  std::vector<std::string> Building; // datasets being built, outermost first (cycle detection)
  std::string SceneDirectory;
  bool Progress;
  int TimeStepOverride = -1; // --time-steps: this step of every time series, whatever the scene says
  int TimeSteps = 0;
  std::string TimeLabel;
  int TimeStepShown = -1;
};

/** Builds one representation (`"type": ...`) into props added to the renderer. */
using RepresentationBuilder = std::function<void(Parameters&, SceneDatasets&, vtkRenderer*)>;
/** All representation types the command line knows, by type name. */
const std::map<std::string, RepresentationBuilder>& Representations();

// Each file of builders adds its types (plumeRepresentationRegistry.cxx calls these).
void RegisterCoreRepresentations(std::map<std::string, RepresentationBuilder>& builders);
void RegisterVolumeRepresentations(std::map<std::string, RepresentationBuilder>& builders);
void RegisterSheetRepresentations(std::map<std::string, RepresentationBuilder>& builders);

/** The dataset `"source": "splat"` (plumeSplatSource.cxx). */
vtkSmartPointer<vtkDataObject> BuildSplatDataset(Parameters& p, SceneDatasets& datasets, const std::string& name);
/** Whether `source` names a derived dataset (contour, slice, streamlines, ...; plumeDerivedSource.cxx). */
bool IsDerivedSource(const std::string& source);
/** A dataset derived from another with VTK's filters (vtkPlumeDerivedGeometry; plumeDerivedSource.cxx). */
vtkSmartPointer<vtkDataObject> BuildDerivedDataset(Parameters& p, SceneDatasets& datasets, const std::string& name);
/** The dataset `"source": "smoke"` (plumeSmokeSource.cxx). */
vtkSmartPointer<vtkDataObject> BuildSmokeDataset(Parameters& p, SceneDatasets& datasets, const std::string& name);
/**
 * The solver of a `"source": "smoke"` dataset, configured from its keys but
 * not run; `step` receives the dataset's `step` key (plume simulate's default
 * number of steps).
 */
vtkSmartPointer<vtkPlumeSmokeSolver> ConfigureSmokeSolver(
  Parameters& p, SceneDatasets& datasets, const std::string& name, int& step);

struct SceneOptions
{
  int Width = 0;  // 0: from the scene's "size", else 800
  int Height = 0;
  bool Progress = false;
  /** >= 0: read this time step of every time series (plume render --time-steps). */
  int TimeStep = -1;
  /** Out: the most time steps of a dataset the scene read (0: no series). */
  int NumberOfTimeSteps = 0;
  /** Out: the step shown of the first time series (-1: no series). */
  int TimeStepShown = -1;
  /** Out: the props (actors, volumes, colour bars) each representation added, in scene order (plume view's toggles). */
  std::vector<std::vector<vtkSmartPointer<vtkProp>>> RepresentationProps;
};

class Scene
{
public:
  /** Deepest nesting of arrays/objects a scene may use (a scene needs about 6). */
  static constexpr int MaximumJsonDepth = 64;
  /** Parse and check a scene file (a regular file; FIFOs and devices are refused); throws SceneError. */
  static nlohmann::json ReadFile(const std::string& path);
  /** Parse JSON text with nesting bounded by MaximumJsonDepth; `what` names it in errors. */
  static nlohmann::json Parse(std::istream& in, const std::string& what);
  /** Build the renderer's content from a parsed scene; throws SceneError. */
  static void Build(const nlohmann::json& scene, const std::string& sceneDirectory, vtkRenderer* renderer,
    SceneOptions& options);
};
}

#endif
