// Collects VTK's error and warning text instead of printing it as it comes:
// when plume fails, its own one-line message (which carries the reader's
// explanation) is what the user sees; when plume succeeds, what VTK said is
// printed afterwards, once, so nothing is hidden.
#ifndef plumeOutputWindow_h
#define plumeOutputWindow_h

#include "vtkOutputWindow.h"

#include <string>

class plumeOutputWindow : public vtkOutputWindow
{
public:
  static plumeOutputWindow* New();
  vtkTypeMacro(plumeOutputWindow, vtkOutputWindow);

  void DisplayText(const char* text) override;
  void DisplayErrorText(const char* text) override;
  void DisplayWarningText(const char* text) override;
  void DisplayGenericWarningText(const char* text) override;
  void DisplayDebugText(const char*) override {}

  /** Everything collected so far (errors and warnings), then cleared. */
  std::string TakeMessages();

  /**
   * A front door's last step: prints "plume: error: <error>" when `error` is
   * not empty, then what VTK said (on success always, on failure only with
   * PLUME_VERBOSE=1: the one line says what went wrong); returns `status`.
   */
  int Finish(int status, const std::string& error);

  /** Install a collector as VTK's output window; returns it. */
  static plumeOutputWindow* Install();

protected:
  plumeOutputWindow() = default;
  ~plumeOutputWindow() override = default;

private:
  plumeOutputWindow(const plumeOutputWindow&) = delete;
  void operator=(const plumeOutputWindow&) = delete;

  std::string Messages;
};

#endif
