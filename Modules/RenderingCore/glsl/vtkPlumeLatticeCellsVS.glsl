//VTK::System::Dec

// A lattice's refined cells as quads (no vertex buffer: draw 6 vertices per
// cell, DrawCellCount.x * DrawCellCount.y cells) on a target of
// DrawTargetSize pixels: the viewport (the cells' pixels) or a finer
// lattice level's cell texture (its cells inside the refined ones). Cell
// (i, j) covers the target's pixels [i S, (i + 1) S) x [j S, (j + 1) S)
// (S = DrawCellSize), the last cell of a row or column up to the target's
// edge. A cell whose DrawCells texel is 0 (interpolated) collapses to a
// point outside the view, so its pixels never run the fragment shader;
// llvmpipe would run it for the whole quad otherwise. (Uniform names of its
// own: the fragment shader may describe another level of the same lattice.)

uniform sampler2D DrawCells; // per cell: 0 interpolated, else refined
uniform int DrawCellSize;    // S, target pixels per cell side
uniform ivec2 DrawCellCount;
uniform vec2 DrawTargetSize;

out vec2 texCoord; // (0, 0): for fragment shaders written for VTK's full-screen quad

const ivec2 QuadCorners[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));

void main()
{
  texCoord = vec2(0.0);
  int k = gl_VertexID / 6;
  ivec2 cell = ivec2(k % DrawCellCount.x, k / DrawCellCount.x);
  if (texelFetch(DrawCells, cell, 0).r == 0.0)
  {
    gl_Position = vec4(2.0, 2.0, 0.0, 1.0);
    return;
  }
  ivec2 c = cell + QuadCorners[gl_VertexID % 6];
  vec2 corner = mix(vec2(c * DrawCellSize), DrawTargetSize, bvec2(equal(c, DrawCellCount)));
  gl_Position = vec4(2.0 * min(corner, DrawTargetSize) / DrawTargetSize - 1.0, 0.0, 1.0);
}
