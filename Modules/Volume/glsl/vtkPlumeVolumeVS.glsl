//VTK::System::Dec

// vtkPlumeVolumeMapper vertex shader: the 12 triangles of the volume's box,
// generated from gl_VertexID (no vertex buffer). Corners are in index space.
// (The ray lattice's refined cells are drawn by the shared
// vtkPlumeLatticeCellsVS instead.)

uniform mat4 IndexToClip;
uniform vec3 DrawMin; // the box drawn: the volume, or only its non-transparent blocks
uniform vec3 DrawMax;
uniform vec2 ClipScale;  // (1, 1); the ray lattice's pass: with ClipOffset, maps the viewport onto the
uniform vec2 ClipOffset; // (0, 0)   lattice texture (lattice ray i is the ray through pixel i L)

// corner c of the unit cube is (c & 1, (c >> 1) & 1, (c >> 2) & 1);
// triangles wind counter-clockwise seen from outside
const int Corners[36] = int[36](0, 6, 2, 0, 4, 6, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
  2, 7, 3, 2, 6, 7, 0, 3, 1, 0, 2, 3, 4, 5, 7, 4, 7, 6);


void main()
{
//PLUME::IF CLASSIFY LIGHT_VOLUME
  // the cell classification covers the whole lattice texture, a light-volume
  // slice the whole slice: one triangle
  gl_Position = vec4(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID >> 1) * 4 - 1), 0.0, 1.0);
  return;
//PLUME::ENDIF
  int c = Corners[gl_VertexID];
  vec3 f = vec3(float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1));
  gl_Position = IndexToClip * vec4(mix(DrawMin, DrawMax, f), 1.0);
  // ndc' = ndc s + o, in clip space
  gl_Position.xy = gl_Position.xy * ClipScale + ClipOffset * gl_Position.w;
}
