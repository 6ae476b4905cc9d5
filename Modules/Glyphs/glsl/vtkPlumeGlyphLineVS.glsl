//VTK::System::Dec

// vtkPlumeVelocityGlyphMapper vertex shader for straight 1-pixel glyphs
// without a geometry shader: drawn as glDrawArrays(GL_LINES, 2 * first,
// 2 * count) with no vertex attributes (lattice roots only; seeds always take
// the geometry shader), so vertex 2r is the root
// of glyph r and vertex 2r + 1 its tip. Both invocations of a glyph compute
// the whole glyph (one texture fetch, two matrix products) and keep their end.
//
// The result is the geometry shader's STRAIGHT/THIN output, vertex for vertex:
// the same root, tip, alpha and colour, and a culled glyph puts both
// vertices at one point outside the clip volume, which the clipper drops.
// Glyphs the geometry shader culls for lying outside one clip plane are
// dropped by GL clipping instead (same pixels).
//
// Variant blocks (see vtkPlumeVelocityGlyphMapper.cxx):
//   LUT | SOLID: colour by |v| through a 1-row lookup texture, or one colour
//   FADE | OPAQUE: alpha varying from RootAlpha to 1, or none (opaque glyphs)

//PLUME::Defines

//PLUME::IF FADE
out float glyphAlpha;
//PLUME::ENDIF
flat out vec4 glyphColor;

uniform sampler3D Velocity; // xyz = velocity, a = valid mask (0 or 1)
uniform mat4 MCDCRel;       // centre-relative model coordinates -> clip
uniform mat4 IndexToRel;    // index space -> centre-relative model coordinates
uniform vec3 Dims;          // grid dimensions (number of nodes per axis)
uniform float Scale;        // glyph length per unit velocity
uniform float MinimumSpeed; // roots with |v| <= MinimumSpeed emit nothing
uniform float RootAlpha;    // alpha at the root (1 at the tip)
uniform vec2 ColorRange;    // (minimum, 1 / (maximum - minimum)) of |v| for colouring
//PLUME::IF LUT
uniform sampler2D ColorLUT;
uniform float LUTSize;
//PLUME::ENDIF
//PLUME::IF SOLID
uniform vec3 SolidColor;
//PLUME::ENDIF
uniform ivec2 StridedDims;  // lattice size after striding (x, y; z follows from the count)
uniform int Stride;         // lattice stride in grid nodes
uniform vec3 LatticeOffset; // node of the first root (integers: the whole grid's lattice)

bool AllFinite(vec4 c)
{
  return !any(isnan(c)) && !any(isinf(c));
}

void main()
{
  const vec4 culled = vec4(2.0, 2.0, 2.0, 1.0); // outside the clip volume
  bool tipEnd = (gl_VertexID & 1) == 1;
//PLUME::IF FADE
  glyphAlpha = 1.0;
//PLUME::ENDIF
  glyphColor = vec4(0.0);
  gl_Position = culled;

  int id = gl_VertexID >> 1; // the glyph (root) index
  int i = id % StridedDims.x;
  int rest = id / StridedDims.x;
  int j = rest % StridedDims.y;
  int k = rest / StridedDims.y;
  ivec3 node = ivec3(LatticeOffset) + ivec3(i, j, k) * Stride;
  vec3 idx0 = vec3(node);
  // a lattice root is a node, always inside the volume, where the geometry
  // shader's trilinear sample at the texel centre equals the texel itself
  vec4 s0 = texelFetch(Velocity, node, 0);
  float speed = length(s0.xyz);
  if (s0.a < 0.999 || !(speed > MinimumSpeed))
  {
    return;
  }
  vec3 p0 = (IndexToRel * vec4(idx0, 1.0)).xyz;
  vec4 c0 = MCDCRel * vec4(p0, 1.0);
  vec4 c1 = MCDCRel * vec4(p0 + Scale * s0.xyz, 1.0);
  if (!AllFinite(c0) || !AllFinite(c1))
  {
    return; // overflow (e.g. absurd velocities): draw nothing rather than garbage
  }
//PLUME::IF LUT
  float colorCoord = clamp((speed - ColorRange.x) * ColorRange.y, 0.0, 1.0);
  glyphColor = textureLod(ColorLUT, vec2((colorCoord * (LUTSize - 1.0) + 0.5) / LUTSize, 0.5), 0.0);
//PLUME::ENDIF
//PLUME::IF SOLID
  glyphColor = vec4(SolidColor, 1.0);
//PLUME::ENDIF
//PLUME::IF FADE
  glyphAlpha = tipEnd ? 1.0 : RootAlpha;
//PLUME::ENDIF
  gl_Position = tipEnd ? c1 : c0;
}
