#include "vtkPlumeLatticeCellsDraw.h"

#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <algorithm>

namespace plume
{
void DrawLatticeCells(
  vtkShaderProgram* program, int cellsUnit, int cellSize, const int cellCount[2], const int targetSize[2])
{
  const float target[2] = { static_cast<float>(targetSize[0]), static_cast<float>(targetSize[1]) };
  program->SetUniformi("DrawCells", cellsUnit);
  program->SetUniformi("DrawCellSize", cellSize);
  program->SetUniform2i("DrawCellCount", cellCount);
  program->SetUniform2f("DrawTargetSize", target);
  // the cells S x S and inside the target: points; the others: quads
  // (all quads if the driver's points cannot be that large)
  GLfloat sizes[2] = { 1.0f, 1.0f };
  glGetFloatv(GL_POINT_SIZE_RANGE, sizes);
  const bool asPoints = cellSize >= 1 && static_cast<float>(cellSize) <= sizes[1];
  int points[2];
  for (int a = 0; a < 2; ++a)
  {
    points[a] = asPoints ? std::max(std::min(cellCount[a] - 1, targetSize[a] / cellSize), 0) : 0;
  }
  program->SetUniform2i("DrawPointCells", points);
  if (points[0] * points[1] > 0)
  {
    const GLboolean pointSize = glIsEnabled(GL_PROGRAM_POINT_SIZE);
    glEnable(GL_PROGRAM_POINT_SIZE);
    program->SetUniformi("DrawEdgeCells", 0);
    glDrawArrays(GL_POINTS, 0, points[0] * points[1]);
    if (!pointSize)
    {
      glDisable(GL_PROGRAM_POINT_SIZE);
    }
  }
  program->SetUniformi("DrawEdgeCells", 1);
  const int edges = cellCount[0] * cellCount[1] - points[0] * points[1];
  if (edges > 0)
  {
    glDrawArrays(GL_TRIANGLES, 0, 6 * edges);
  }
}
}
