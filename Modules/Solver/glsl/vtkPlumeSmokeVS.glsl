//VTK::System::Dec

// vtkPlumeSmokeSolver GPU backend, vertex shader: one point per z slice of
// the 3D render target (glDrawArrays(GL_POINTS, 0, depth)); the geometry
// shader turns it into a full-slice quad on layer gl_VertexID.

flat out int vLayer;

void main()
{
  vLayer = gl_VertexID;
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0); // unused
}
