//VTK::System::Dec

// vtkPlumeGaussianSplatter GPU backend, vertex shader. One instance per
// splat, one vertex (a point) per z slice the splat touches: all splats of a
// draw touch the same number of slices (the CPU groups them), so the slice
// is just gl_VertexID. The geometry shader does the rest.

uniform int FirstSplat; // index of the draw's first splat in the Splats buffer

flat out int vSplat;
flat out int vSlice;

void main()
{
  vSplat = FirstSplat + gl_InstanceID;
  vSlice = gl_VertexID;
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0); // unused
}
