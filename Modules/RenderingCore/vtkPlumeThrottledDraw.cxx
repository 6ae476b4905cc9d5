#include "vtkPlumeThrottledDraw.h"

#include "vtk_glew.h"

#include <algorithm>
#include <vector>

namespace plume
{
int DrawArraysThrottled(unsigned int mode, int perPrimitive, vtkIdType count, vtkIdType chunk, int inFlight)
{
  int draws = 0;
  if (chunk <= 0)
  {
    chunk = std::max<vtkIdType>(count, 1);
  }
  std::vector<GLsync> fences;
  for (vtkIdType first = 0; first < count; first += chunk)
  {
    const vtkIdType n = std::min(chunk, count - first);
    glDrawArrays(static_cast<GLenum>(mode), static_cast<GLint>(first * perPrimitive),
      static_cast<GLsizei>(n * perPrimitive));
    ++draws;
    if (inFlight > 0 && first + n < count)
    {
      fences.push_back(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0));
      if (fences.size() > static_cast<size_t>(inFlight))
      {
        glClientWaitSync(fences.front(), GL_SYNC_FLUSH_COMMANDS_BIT, GL_TIMEOUT_IGNORED);
        glDeleteSync(fences.front());
        fences.erase(fences.begin());
      }
    }
  }
  for (GLsync fence : fences)
  {
    glDeleteSync(fence);
  }
  return draws;
}
}
