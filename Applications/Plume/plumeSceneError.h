// The one exception type of the plume command line: its message names the
// problem and the offending value, and main() prints it as the only error line.
#ifndef plumeSceneError_h
#define plumeSceneError_h

#include <stdexcept>
#include <string>

namespace plume
{
/** `message` on one line: VTK's reasons may span several (newlines become "; "). */
inline std::string OneLine(std::string message)
{
  while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
  {
    message.pop_back();
  }
  for (size_t at = message.find('\n'); at != std::string::npos; at = message.find('\n', at))
  {
    message.replace(at, 1, "; ");
  }
  return message;
}

class SceneError : public std::runtime_error
{
public:
  explicit SceneError(const std::string& message)
    : std::runtime_error(message)
  {
  }
};
}

#endif
