// The refined cells of a screen lattice (the volume mapper's ray lattice, the
// airlight pass's levels) drawn by the shared vertex shader
// vtkPlumeLatticeCellsVS, so that only their pixels run the fragment shader.
#ifndef vtkPlumeLatticeCellsDraw_h
#define vtkPlumeLatticeCellsDraw_h

#include "PlumeRenderingCoreModule.h" // For export macro

class vtkShaderProgram;

namespace plume
{
/**
 * Draws the cells of a `cellCount[0]` x `cellCount[1]` lattice of
 * `cellSize`-pixel cells on a target of `targetSize` pixels (the viewport
 * set by the caller) with `program`, bound, whose vertex shader is
 * vtkPlumeLatticeCellsVS; `cellsUnit` is the texture unit of the cells'
 * flags (R: 0 interpolated, else refined), one texel per cell. The caller
 * binds a vertex array (the shader reads none) and sets the fragment
 * shader's own uniforms. The cells of the last row and column reach the
 * target's edge. Two draws: the other cells as points of size `cellSize`
 * (GL_PROGRAM_POINT_SIZE is enabled for it and restored), the last row and
 * column as quads. Each pixel of a refined cell is covered once.
 */
PLUMERENDERINGCORE_EXPORT void DrawLatticeCells(
  vtkShaderProgram* program, int cellsUnit, int cellSize, const int cellCount[2], const int targetSize[2]);
}

#endif
