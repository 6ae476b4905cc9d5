//VTK::System::Dec

// vtkPlumeSmokeSolver GPU backend, geometry shader: layered rendering into a
// 3D texture (the seed's full-screen quad, once per slice): the quad covering
// the whole viewport, routed to slice vLayer with gl_Layer.

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

flat in int vLayer[];
flat out int gLayer;

void main()
{
  const vec2 corners[4] = vec2[4](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));
  for (int c = 0; c < 4; ++c)
  {
    gl_Layer = vLayer[0];
    gLayer = vLayer[0];
    gl_Position = vec4(corners[c], 0.0, 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
