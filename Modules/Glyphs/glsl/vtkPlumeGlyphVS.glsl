//VTK::System::Dec

// vtkPlumeVelocityGlyphMapper vertex shader: one invocation per glyph root.
// The root is passed on in *index space* (i, j, k as floats); the geometry
// shader does the sampling, culling and extrusion.
//
// Variant blocks (kept or removed on the CPU, see vtkPlumeVelocityGlyphMapper.cxx):
//   LATTICE: roots generated from gl_VertexID (no vertex buffer, empty VAO)
//   SEEDS:   roots read from a buffer of positions relative to the volume centre

//PLUME::Defines

out vec3 rootIndex;

//PLUME::IF LATTICE
uniform ivec2 StridedDims; // lattice size after striding (x, y; z follows from the count)
uniform int Stride;        // lattice stride in grid nodes
uniform vec3 LatticeOffset; // node of the first root (integers: the whole grid's lattice)
//PLUME::ENDIF
//PLUME::IF SEEDS
in vec3 seedPosition;      // seed point minus the volume centre (model units)
uniform mat4 RelToIndex;   // centre-relative model coordinates -> index space
//PLUME::ENDIF

void main()
{
//PLUME::IF LATTICE
  int id = gl_VertexID;
  int i = id % StridedDims.x;
  int rest = id / StridedDims.x;
  int j = rest % StridedDims.y;
  int k = rest / StridedDims.y;
  rootIndex = LatticeOffset + vec3(ivec3(i, j, k) * Stride);
//PLUME::ENDIF
//PLUME::IF SEEDS
  rootIndex = (RelToIndex * vec4(seedPosition, 1.0)).xyz;
//PLUME::ENDIF
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0); // unused: the GS computes positions
}
