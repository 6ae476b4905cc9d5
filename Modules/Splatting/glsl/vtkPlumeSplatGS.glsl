//VTK::System::Dec

// vtkPlumeGaussianSplatter GPU backend, geometry shader: routes each
// (splat, slice) to its layer of the 3D target with gl_Layer (seed 002) and
// emits a quad covering the splat's x/y voxel box on that layer.
//
// Splats buffer, 3 texels per splat (floats hold integers exactly below 2^24):
//   SUM:      (lo.x, lo.y, lo.z, weight base) (n.x, n.y, n.z, -) (value.xyz, -)
//   DISTANCE: (lo.x, lo.y, lo.z, value)       (n.x, n.y, n.z, -) (centre in index units, R)
// Weights buffer (SUM): per splat n.x x-weights, n.y y-weights, n.z z-weights.

//PLUME::Defines

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

flat in int vSplat[];
flat in int vSlice[];

uniform samplerBuffer Splats;
//PLUME::IF SUM
uniform samplerBuffer Weights;
//PLUME::ENDIF
uniform vec2 GridXY; // nx, ny: the viewport

flat out ivec2 gLo;     // first voxel of the box (x, y)
//PLUME::IF SUM
flat out ivec2 gBase;   // first x and y weight in Weights
flat out vec3 gValue;   // the splat's value
flat out float gWz;     // the slice's z weight
//PLUME::ENDIF
//PLUME::IF DISTANCE
flat out vec4 gCenter;  // centre relative to this slice (index units; z = slice offset), w = R
flat out float gValue;
//PLUME::ENDIF

void main()
{
  int s = vSplat[0];
  vec4 t0 = texelFetch(Splats, 3 * s);
  vec4 t1 = texelFetch(Splats, 3 * s + 1);
  vec4 t2 = texelFetch(Splats, 3 * s + 2);
  ivec3 lo = ivec3(t0.xyz);
  ivec3 n = ivec3(t1.xyz);
  int layer = lo.z + vSlice[0];
  vec2 a = 2.0 * vec2(lo.xy) / GridXY - 1.0;
  vec2 b = 2.0 * vec2(lo.xy + n.xy) / GridXY - 1.0;
//PLUME::IF SUM
  int base = int(t0.w);
  float wz = texelFetch(Weights, base + n.x + n.y + vSlice[0]).r;
//PLUME::ENDIF
  for (int v = 0; v < 4; ++v)
  {
    // outputs are undefined after EmitVertex: set all of them each time
    gl_Layer = layer;
    gLo = lo.xy;
//PLUME::IF SUM
    gBase = ivec2(base, base + n.x);
    gValue = t2.xyz;
    gWz = wz;
//PLUME::ENDIF
//PLUME::IF DISTANCE
    gCenter = vec4(t2.xyz - vec3(0.0, 0.0, float(layer)), t2.w);
    gValue = t0.w;
//PLUME::ENDIF
    gl_Position = vec4((v & 1) == 0 ? a.x : b.x, (v & 2) == 0 ? a.y : b.y, 0.0, 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
