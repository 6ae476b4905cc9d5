//VTK::System::Dec

// vtkPlumeSmokeSolver GPU backend, fragment shader: one texel of one pass of
// the seed's step (GPU Gems ch. 38) on the solver's MAC grid. The pass is a
// feature (only the pass in use is compiled); every pass reads its inputs
// with texelFetch and writes one texel of the 3D target (layer gLayer):
//   ADVECT        semi-Lagrangian advection (midpoint back-trace, trilinear),
//                 then the decay towards Target
//   BUOYANCY      a face component += Factor * (Buoyancy (T - ambient) - SmokeWeight density)
//   SOURCE_CELLS  a cell quantity set where a source acts (SourceIndex, from the CPU)
//   SOURCE_FACES  a face component set where a velocity source acts
//   DIVERGENCE    (b, D) per cell: b = -div u, D the Poisson matrix's diagonal
//                 (0 in solid cells), so that Jacobi reads no obstacle texels
//   JACOBI        one damped Jacobi iteration of the pressure Poisson equation
//   GRADIENT      a face component -= the pressure gradient
//   CELL_VELOCITY the cell-centred velocity (RGBA32F, a = 1) for the glyph mapper
//   TRIVIAL       writes a constant (the bench's floor: the cost of a pass itself)
// The arithmetic follows the CPU backend (vtkPlumeSmokeSolver.cxx) step by
// step, in float instead of double; walls, solid cells and open sides as there.

//PLUME::Defines

flat in int gLayer;

uniform ivec3 Cells;   // the cell grid
uniform ivec3 OpenLo;  // 1 where the domain side at index 0 is open (free outflow)
uniform ivec3 OpenHi;  // 1 where the side past the last cell is open
uniform vec3 H;        // spacing
uniform sampler3D Solid; // cells: 1 = solid
uniform int Axis;      // face passes: the component (faces normal to Axis); cell passes: -1

//VTK::Output::Dec

bool IsSolid(ivec3 c)
{
  return texelFetch(Solid, c, 0).r > 0.5;
}

// vtkPlumeSmokeSolver::IsWallFace: a domain side that is not open, or a face touching a solid cell
bool IsWallFace(int axis, ivec3 f)
{
  ivec3 e = ivec3(0);
  e[axis] = 1;
  if (f[axis] == 0)
  {
    return OpenLo[axis] == 0 || IsSolid(f);
  }
  if (f[axis] == Cells[axis])
  {
    return OpenHi[axis] == 0 || IsSolid(f - e);
  }
  return IsSolid(f) || IsSolid(f - e);
}

//PLUME::IF ADVECT
uniform sampler3D Source; // the advected grid (cells, or the faces normal to Axis)
uniform sampler3D U0;     // faces normal to x, y, z
uniform sampler3D U1;
uniform sampler3D U2;
uniform float Dt;
uniform float Decay;  // exp(-rate dt)
uniform float Target; // value decayed towards; also that of solid cells

// Trilinear sample at index-space position g, clamped to the grid (CPU: Trilinear)
float Trilinear(sampler3D f, vec3 g)
{
  ivec3 m = textureSize(f, 0);
  ivec3 i0;
  vec3 t;
  for (int a = 0; a < 3; ++a)
  {
    float x = clamp(g[a], 0.0, float(m[a] - 1));
    int i = min(int(x), max(m[a] - 2, 0));
    i0[a] = i;
    t[a] = m[a] > 1 ? x - float(i) : 0.0;
  }
  ivec3 i1 = min(i0 + 1, m - 1);
  float c00 = texelFetch(f, ivec3(i0.x, i0.y, i0.z), 0).r * (1.0 - t.x) + texelFetch(f, ivec3(i1.x, i0.y, i0.z), 0).r * t.x;
  float c10 = texelFetch(f, ivec3(i0.x, i1.y, i0.z), 0).r * (1.0 - t.x) + texelFetch(f, ivec3(i1.x, i1.y, i0.z), 0).r * t.x;
  float c01 = texelFetch(f, ivec3(i0.x, i0.y, i1.z), 0).r * (1.0 - t.x) + texelFetch(f, ivec3(i1.x, i0.y, i1.z), 0).r * t.x;
  float c11 = texelFetch(f, ivec3(i0.x, i1.y, i1.z), 0).r * (1.0 - t.x) + texelFetch(f, ivec3(i1.x, i1.y, i1.z), 0).r * t.x;
  float c0 = c00 * (1.0 - t.y) + c10 * t.y;
  float c1 = c01 * (1.0 - t.y) + c11 * t.y;
  return c0 * (1.0 - t.z) + c1 * t.z;
}

// velocity in cells per second at cell-index position x (each component from its face grid)
vec3 Velocity(vec3 x)
{
  return vec3(Trilinear(U0, x + vec3(0.5, 0.0, 0.0)), Trilinear(U1, x + vec3(0.0, 0.5, 0.0)),
           Trilinear(U2, x + vec3(0.0, 0.0, 0.5))) / H;
}
//PLUME::ENDIF

//PLUME::IF BUOYANCY
uniform sampler3D Source; // the face component being updated
uniform sampler3D Density;
uniform sampler3D Temperature;
uniform float Factor; // dt * up[Axis]
uniform float Buoyancy;
uniform float SmokeWeight;
uniform float Ambient;
//PLUME::ENDIF

//PLUME::IF SOURCE_CELLS SOURCE_FACES
#define MAX_SOURCES 16
uniform sampler3D Source;
uniform sampler3D SourceIndex; // covering source + 1 per texel (0: none), decided on the CPU
uniform float SourceValue[MAX_SOURCES];
//PLUME::ENDIF

//PLUME::IF DIVERGENCE CELL_VELOCITY
uniform sampler3D U0;
uniform sampler3D U1;
uniform sampler3D U2;
//PLUME::ENDIF

//PLUME::IF JACOBI
uniform sampler3D Pressure; // the current iterate
uniform sampler3D B;        // (right-hand side -div u, diagonal)
uniform vec3 InvH2;
uniform float Weight;       // damping
//PLUME::ENDIF

//PLUME::IF GRADIENT
uniform sampler3D Source;
uniform sampler3D Pressure;
//PLUME::ENDIF

void main()
{
  ivec3 p = ivec3(ivec2(gl_FragCoord.xy), gLayer);
//PLUME::IF ADVECT
  bool fixedValue = Axis >= 0 ? IsWallFace(Axis, p) : IsSolid(p);
  float value;
  if (fixedValue)
  {
    value = Axis >= 0 ? 0.0 : Target;
  }
  else
  {
    vec3 shift = vec3(0.0);
    if (Axis >= 0)
    {
      shift[Axis] = 0.5;
    }
    vec3 x = vec3(p) - shift;
    vec3 mid = x - 0.5 * Dt * Velocity(x);
    vec3 from = x - Dt * Velocity(mid);
    value = Trilinear(Source, from + shift);
  }
  gl_FragData[0] = vec4(Target + Decay * (value - Target), 0.0, 0.0, 0.0);
//PLUME::ENDIF
//PLUME::IF BUOYANCY
  float u = texelFetch(Source, p, 0).r;
  if (!IsWallFace(Axis, p))
  {
    ivec3 e = ivec3(0);
    e[Axis] = 1;
    float t = 0.0, s = 0.0, cells = 0.0;
    if (p[Axis] < Cells[Axis])
    {
      t += texelFetch(Temperature, p, 0).r;
      s += texelFetch(Density, p, 0).r;
      cells += 1.0;
    }
    if (p[Axis] > 0)
    {
      t += texelFetch(Temperature, p - e, 0).r;
      s += texelFetch(Density, p - e, 0).r;
      cells += 1.0;
    }
    t /= cells;
    s /= cells;
    u += Factor * (Buoyancy * (t - Ambient) - SmokeWeight * s);
  }
  gl_FragData[0] = vec4(u, 0.0, 0.0, 0.0);
//PLUME::ENDIF
//PLUME::IF SOURCE_CELLS SOURCE_FACES
  float value = texelFetch(Source, p, 0).r;
  int source = int(texelFetch(SourceIndex, p, 0).r + 0.5);
  if (source > 0)
  {
    value = SourceValue[source - 1];
  }
  gl_FragData[0] = vec4(value, 0.0, 0.0, 0.0);
//PLUME::ENDIF
//PLUME::IF DIVERGENCE
  float b = 0.0;
  float diagonal = 0.0;
  if (!IsSolid(p))
  {
    float div = (texelFetch(U0, p + ivec3(1, 0, 0), 0).r - texelFetch(U0, p, 0).r) / H.x +
      (texelFetch(U1, p + ivec3(0, 1, 0), 0).r - texelFetch(U1, p, 0).r) / H.y +
      (texelFetch(U2, p + ivec3(0, 0, 1), 0).r - texelFetch(U2, p, 0).r) / H.z;
    b = -div;
    // vtkPlumePressureSolver's diagonal: a fluid neighbour or an open side (ghost q = 0) per face
    for (int d = 0; d < 3; ++d)
    {
      ivec3 e = ivec3(0);
      e[d] = 1;
      float invH2 = 1.0 / (H[d] * H[d]);
      if (p[d] > 0 ? !IsSolid(p - e) : OpenLo[d] != 0)
      {
        diagonal += invH2;
      }
      if (p[d] < Cells[d] - 1 ? !IsSolid(p + e) : OpenHi[d] != 0)
      {
        diagonal += invH2;
      }
    }
  }
  gl_FragData[0] = vec4(b, diagonal, 0.0, 0.0);
//PLUME::ENDIF
//PLUME::IF JACOBI
  // Solid cells (diagonal 0) hold q = 0 in every iterate (cleared, then
  // written 0 here), so a solid neighbour adds exactly 0 and needs no test;
  // a ghost beyond an open side is 0 too, and beyond a wall no term at all.
  vec2 bd = texelFetch(B, p, 0).rg;
  float next = 0.0;
  if (bd.y > 0.0)
  {
    float sum = bd.x;
    for (int d = 0; d < 3; ++d)
    {
      ivec3 e = ivec3(0);
      e[d] = 1;
      if (p[d] > 0)
      {
        sum += InvH2[d] * texelFetch(Pressure, p - e, 0).r;
      }
      if (p[d] < Cells[d] - 1)
      {
        sum += InvH2[d] * texelFetch(Pressure, p + e, 0).r;
      }
    }
    next = (1.0 - Weight) * texelFetch(Pressure, p, 0).r + Weight * sum / bd.y;
  }
  gl_FragData[0] = vec4(next, 0.0, 0.0, 0.0);
//PLUME::ENDIF
//PLUME::IF GRADIENT
  float u = texelFetch(Source, p, 0).r;
  if (!IsWallFace(Axis, p))
  {
    ivec3 e = ivec3(0);
    e[Axis] = 1;
    float qPlus = p[Axis] < Cells[Axis] ? texelFetch(Pressure, p, 0).r : 0.0;
    float qMinus = p[Axis] > 0 ? texelFetch(Pressure, p - e, 0).r : 0.0;
    u -= (qPlus - qMinus) / H[Axis];
  }
  gl_FragData[0] = vec4(u, 0.0, 0.0, 0.0);
//PLUME::ENDIF
//PLUME::IF TRIVIAL
  gl_FragData[0] = vec4(1.0, 0.0, 0.0, 0.0);
//PLUME::ENDIF
//PLUME::IF CELL_VELOCITY
  gl_FragData[0] = vec4(0.5 * (texelFetch(U0, p, 0).r + texelFetch(U0, p + ivec3(1, 0, 0), 0).r),
    0.5 * (texelFetch(U1, p, 0).r + texelFetch(U1, p + ivec3(0, 1, 0), 0).r),
    0.5 * (texelFetch(U2, p, 0).r + texelFetch(U2, p + ivec3(0, 0, 1), 0).r), 1.0);
//PLUME::ENDIF
}
