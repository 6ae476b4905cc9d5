#include "plumeProgress.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace plume
{

bool ProgressEnabled()
{
  // on a terminal; PLUME_PROGRESS=1 forces the bar (logs, tests), 0 turns it off
  static const bool enabled = [] {
    const char* forced = std::getenv("PLUME_PROGRESS");
    if (forced && *forced)
    {
      return std::string(forced) != "0";
    }
    return isatty(fileno(stderr)) != 0;
  }();
  return enabled;
}

void DrawProgress(const std::string& label, double fraction)
{
  if (!ProgressEnabled())
  {
    return;
  }
  constexpr int width = 30;
  fraction = fraction < 0 ? 0 : (fraction > 1 ? 1 : fraction);
  const int filled = static_cast<int>(fraction * width + 0.5);
  std::string bar(filled, '#');
  bar.resize(width, ' ');
  std::fprintf(stderr, "\r%-24.24s [%s] %3d%%", label.c_str(), bar.c_str(), static_cast<int>(fraction * 100 + 0.5));
  if (fraction >= 1)
  {
    std::fputc('\n', stderr);
  }
  std::fflush(stderr);
}

namespace
{
struct ProgressLabel
{
  std::string Label;
  bool Done = false;
};

void OnProgress(vtkObject*, unsigned long event, void* clientData, void* callData)
{
  auto* label = static_cast<ProgressLabel*>(clientData);
  if (event == vtkCommand::StartEvent)
  {
    label->Done = false;
    DrawProgress(label->Label, 0);
  }
  else if (event == vtkCommand::ProgressEvent && !label->Done)
  {
    DrawProgress(label->Label, *static_cast<double*>(callData));
  }
  else if (event == vtkCommand::EndEvent && !label->Done)
  {
    label->Done = true;
    DrawProgress(label->Label, 1);
  }
}

void DeleteLabel(void* clientData)
{
  delete static_cast<ProgressLabel*>(clientData);
}
}

void AttachProgress(vtkAlgorithm* algorithm, const std::string& label)
{
  if (!ProgressEnabled() || !algorithm)
  {
    return;
  }
  vtkNew<vtkCallbackCommand> command;
  command->SetCallback(OnProgress);
  command->SetClientData(new ProgressLabel{ label });
  command->SetClientDataDeleteCallback(DeleteLabel);
  algorithm->AddObserver(vtkCommand::StartEvent, command);
  algorithm->AddObserver(vtkCommand::ProgressEvent, command);
  algorithm->AddObserver(vtkCommand::EndEvent, command);
}

}
