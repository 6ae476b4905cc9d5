//VTK::System::Dec

// vtkPlumeVolumeMapper vertex shader: the 12 triangles of the volume's box,
// generated from gl_VertexID (no vertex buffer). Corners are in index space.

uniform mat4 IndexToClip;
uniform vec3 DrawMin; // the box drawn: the volume, or only its non-transparent blocks
uniform vec3 DrawMax;
uniform vec2 ClipScale; // (1, 1); the ray lattice's pass: maps the viewport onto the lattice texture

// corner c of the unit cube is (c & 1, (c >> 1) & 1, (c >> 2) & 1);
// triangles wind counter-clockwise seen from outside
const int Corners[36] = int[36](0, 6, 2, 0, 4, 6, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
  2, 7, 3, 2, 6, 7, 0, 3, 1, 0, 2, 3, 4, 5, 7, 4, 7, 6);

void main()
{
  int c = Corners[gl_VertexID];
  vec3 f = vec3(float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1));
  gl_Position = IndexToClip * vec4(mix(DrawMin, DrawMax, f), 1.0);
  // ndc' = (ndc + 1) s - 1, in clip space
  gl_Position.xy = gl_Position.xy * ClipScale + (ClipScale - 1.0) * gl_Position.w;
}
