#include "plumeOutputWindow.h"

#include "plumeSceneError.h"

#include <cstdlib>
#include <iostream>

#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(plumeOutputWindow);

void plumeOutputWindow::DisplayText(const char* text)
{
  if (text)
  {
    this->Messages += text;
    if (this->Messages.empty() || this->Messages.back() != '\n')
    {
      this->Messages += '\n';
    }
  }
}

void plumeOutputWindow::DisplayErrorText(const char* text)
{
  this->DisplayText(text);
}

void plumeOutputWindow::DisplayWarningText(const char* text)
{
  this->DisplayText(text);
}

void plumeOutputWindow::DisplayGenericWarningText(const char* text)
{
  this->DisplayText(text);
}

std::string plumeOutputWindow::TakeMessages()
{
  std::string out;
  out.swap(this->Messages);
  return out;
}

int plumeOutputWindow::Finish(int status, const std::string& error)
{
  const std::string messages = this->TakeMessages();
  if (!error.empty())
  {
    std::cerr << "plume: error: " << plume::OneLine(error) << "\n";
  }
  if (!messages.empty() && (status == 0 || std::getenv("PLUME_VERBOSE")))
  {
    std::cerr << messages;
  }
  return status;
}

plumeOutputWindow* plumeOutputWindow::Install()
{
  // vtkLogger would print errors to stderr on its own; the collector decides instead.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkNew<plumeOutputWindow> window;
  vtkOutputWindow::SetInstance(window);
  return window;
}
