//VTK::System::Dec

// vtkPlumeSheetMapper vertex shader: one invocation per triangle corner
// (triangles are unrolled on the CPU). Positions arrive relative to the mesh
// centre; MCVCRel (composed in double on the CPU) takes them to eye space.

in vec3 sheetPosition;
in vec3 sheetDensity; // d times the RGB absorption (or d, d, d); 1 where the constant applies
in vec2 sheetSigma;   // (sigma_b, sigma_t) in model units; 1 where the constant applies

uniform mat4 MCVCRel;
uniform float ModelToEyeScale; // length scale of the actor matrix (sigmas are lengths)
// (density scale [x constant density], constant blur or 1, constant thickness
// or 1; thickness 0 for a thin sheet): a slider on a constant uploads nothing
uniform vec3 SheetFactors;

out vec3 cornerEye;
out vec3 cornerDensity;
out vec2 cornerSigma;
flat out int cornerTriangle; // the triangle's index in the whole mesh, whatever the draw it is in

void main()
{
  cornerEye = (MCVCRel * vec4(sheetPosition, 1.0)).xyz;
  cornerDensity = min(sheetDensity * SheetFactors.x, vec3(1e30));
  cornerSigma = min(sheetSigma * SheetFactors.yz, vec2(1e15)) * ModelToEyeScale; // vtkPlumeSheetMapper::MaximumSigma
  cornerTriangle = gl_VertexID / 3; // gl_VertexID includes the draw's first: the index in the whole buffer
  gl_Position = vec4(cornerEye, 1.0);
}
