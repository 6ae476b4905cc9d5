#include "vtkPlumeQuietExecutive.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkCompositeDataPipeline.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"

#include <string>

namespace
{
void ExecutiveError(vtkObject*, unsigned long, void*, void* callData)
{
  const char* message = static_cast<const char*>(callData);
  if (message && std::string(message).find("returned failure for request") != std::string::npos)
  {
    return;
  }
  vtkOutputWindowDisplayErrorText(message ? message : "");
}
}

namespace plume
{
vtkExecutive* NewQuietExecutive()
{
  vtkExecutive* executive = vtkCompositeDataPipeline::New();
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(&ExecutiveError);
  executive->AddObserver(vtkCommand::ErrorEvent, observer);
  return executive;
}
}
