//VTK::System::Dec

// A lattice's refined cells (no vertex buffer; drawn by
// plume::DrawLatticeCells, vtkPlumeLatticeCellsDraw.h) on a target of
// DrawTargetSize pixels: the viewport (the cells' pixels) or a finer
// lattice level's cell texture (its cells inside the refined ones). Cell
// (i, j) of DrawCellCount.x * DrawCellCount.y covers the target's pixels
// [i S, (i + 1) S) x [j S, (j + 1) S) (S = DrawCellSize), clipped to the
// target; the last cell of a row or column reaches the target's edge. Two
// draws:
// - DrawEdgeCells 0: the cells i < DrawPointCells.x and j < DrawPointCells.y,
//   S x S and inside the target, one point of size S each (a vertex per
//   cell). llvmpipe rasterizes a point as one square; a quad's two triangles
//   would shade the 4 x 4 blocks on their diagonal twice (the airlight's
//   refine pass took 1.5x the time with quads);
// - DrawEdgeCells 1: the others (the columns from DrawPointCells.x on, then
//   the rows from DrawPointCells.y on left of them), whose size may differ
//   from S, as quads (6 vertices a cell).
// A cell whose DrawCells texel is 0 (interpolated) is moved outside the
// view, so its pixels never run the fragment shader; llvmpipe would run it
// for the whole cell otherwise. (Uniform names of its own: the fragment
// shader may describe another level of the same lattice.)

uniform sampler2D DrawCells; // per cell: 0 interpolated, else refined
uniform int DrawCellSize;    // S, target pixels per cell side
uniform ivec2 DrawCellCount;
uniform vec2 DrawTargetSize;
uniform int DrawEdgeCells;   // 0: the S x S cells as points; 1: the others as quads
uniform ivec2 DrawPointCells; // the cells drawn as points: i < x and j < y

out vec2 texCoord; // (0, 0): for fragment shaders written for VTK's full-screen quad

const ivec2 QuadCorners[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));

void main()
{
  texCoord = vec2(0.0);
  ivec2 n = DrawCellCount;
  ivec2 m = max(DrawPointCells, ivec2(1)); // (no integer division by 0 on either side of a select)
  int k = DrawEdgeCells == 1 ? gl_VertexID / 6 : gl_VertexID;
  int right = (n.x - DrawPointCells.x) * n.y; // the edge cells right of the points' block
  int columns = max(n.x - DrawPointCells.x, 1);
  ivec2 cell = DrawEdgeCells == 0 ? ivec2(k % m.x, k / m.x)
    : k < right ? ivec2(DrawPointCells.x + k % columns, k / columns)
                : ivec2((k - right) % m.x, DrawPointCells.y + (k - right) / m.x);
  gl_PointSize = float(DrawCellSize);
  if (texelFetch(DrawCells, cell, 0).r == 0.0)
  {
    gl_Position = vec4(2.0, 2.0, 0.0, 1.0);
    return;
  }
  if (DrawEdgeCells == 0)
  {
    // the point's centre: pixel centres inside [i S, (i + 1) S) are covered
    gl_Position = vec4(2.0 * (vec2(cell) + 0.5) * float(DrawCellSize) / DrawTargetSize - 1.0, 0.0, 1.0);
    return;
  }
  ivec2 c = cell + QuadCorners[gl_VertexID % 6];
  vec2 corner = mix(vec2(c * DrawCellSize), DrawTargetSize, bvec2(equal(c, n)));
  gl_Position = vec4(2.0 * min(corner, DrawTargetSize) / DrawTargetSize - 1.0, 0.0, 1.0);
}
