//VTK::System::Dec

// vtkPlumeGaussianSplatter GPU backend, fragment shader: one voxel of one
// slice of one splat. SUM: value·((wz·wy)·wx) from the splat's separable
// weights (normalised 1D factors computed once per splat on the CPU, erf cell
// averages or point samples), in the CPU backend's order of float operations;
// additive blending. DISTANCE: value·(1 − r/R), MAX blending.

//PLUME::Defines

flat in ivec2 gLo;
//PLUME::IF SUM
flat in ivec2 gBase;
flat in vec3 gValue;
flat in float gWz;
uniform samplerBuffer Weights;
//PLUME::ENDIF
//PLUME::IF DISTANCE
flat in vec4 gCenter;
flat in float gValue;
uniform vec3 Spacing;
//PLUME::ENDIF

//VTK::Output::Dec

void main()
{
  ivec2 ij = ivec2(gl_FragCoord.xy);
//PLUME::IF SUM
  float wx = texelFetch(Weights, gBase.x + ij.x - gLo.x).r;
  float wy = texelFetch(Weights, gBase.y + ij.y - gLo.y).r;
  float w = (gWz * wy) * wx;
  gl_FragData[0] = vec4(gValue * w, 0.0);
//PLUME::ENDIF
//PLUME::IF DISTANCE
  vec3 d = (vec3(ij, 0.0) - gCenter.xyz) * Spacing;
  float r = length(d);
  if (r >= gCenter.w)
  {
    discard;
  }
  gl_FragData[0] = vec4(gValue * (1.0 - r / gCenter.w), 0.0, 0.0, 0.0);
//PLUME::ENDIF
}
