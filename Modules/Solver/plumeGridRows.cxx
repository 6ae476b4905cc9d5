#include "plumeGridRows.h"

#include "vtkSMPTools.h"

namespace plume
{
namespace smoke
{
void ForRows(const int n[3], const std::function<void(int, int)>& f)
{
  vtkSMPTools::For(0, vtkIdType(n[1]) * n[2], [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType r = begin; r < end; ++r)
    {
      f(int(r % n[1]), int(r / n[1]));
    }
  });
}
}
}
