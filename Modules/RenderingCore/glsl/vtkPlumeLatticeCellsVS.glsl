//VTK::System::Dec

// A lattice's refined cells as quads (no vertex buffer: draw 6 vertices per
// cell, LatticeCellCount.x * LatticeCellCount.y cells). Cell (i, j) covers
// the viewport pixels [i L, (i + 1) L) x [j L, (j + 1) L), the last cell of a
// row or column up to the viewport's edge. A cell whose LatticeCells texel is
// 0 (interpolated) collapses to a point outside the view, so its pixels never
// run the fragment shader; llvmpipe would run it for the whole quad otherwise.

uniform sampler2D LatticeCells; // per cell: 0 interpolated, else refined
uniform int Lattice;            // L, pixels per cell side
uniform ivec2 LatticeCellCount;
uniform vec2 ViewportSize;

out vec2 texCoord; // (0, 0): for fragment shaders written for VTK's full-screen quad

const ivec2 QuadCorners[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));

void main()
{
  texCoord = vec2(0.0);
  int k = gl_VertexID / 6;
  ivec2 cell = ivec2(k % LatticeCellCount.x, k / LatticeCellCount.x);
  if (texelFetch(LatticeCells, cell, 0).r == 0.0)
  {
    gl_Position = vec4(2.0, 2.0, 0.0, 1.0);
    return;
  }
  ivec2 c = cell + QuadCorners[gl_VertexID % 6];
  vec2 corner = mix(vec2(c * Lattice), ViewportSize, bvec2(equal(c, LatticeCellCount)));
  gl_Position = vec4(2.0 * min(corner, ViewportSize) / ViewportSize - 1.0, 0.0, 1.0);
}
