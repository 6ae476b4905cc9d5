// The one exception type of the plume command line: its message names the
// problem and the offending value, and main() prints it as the only error line.
#ifndef plumeSceneError_h
#define plumeSceneError_h

#include <stdexcept>
#include <string>

namespace plume
{
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
