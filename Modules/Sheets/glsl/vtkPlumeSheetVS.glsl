//VTK::System::Dec

// vtkPlumeSheetMapper vertex shader: one invocation per triangle corner
// (triangles are unrolled on the CPU). Positions arrive relative to the mesh
// centre; MCVCRel (composed in double on the CPU) takes them to eye space.

in vec3 sheetPosition;
in vec3 sheetDensity; // d times the RGB absorption (or d, d, d)
in vec2 sheetSigma;   // (sigma_b, sigma_t) in model units

uniform mat4 MCVCRel;
uniform float ModelToEyeScale; // length scale of the actor matrix (sigmas are lengths)

out vec3 cornerEye;
out vec3 cornerDensity;
out vec2 cornerSigma;

void main()
{
  cornerEye = (MCVCRel * vec4(sheetPosition, 1.0)).xyz;
  cornerDensity = sheetDensity;
  cornerSigma = sheetSigma * ModelToEyeScale;
  gl_Position = vec4(cornerEye, 1.0);
}
