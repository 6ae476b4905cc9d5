//VTK::System::Dec

// vtkPlumeVelocityGlyphMapper geometry shader: extrudes one root point into a
// velocity glyph (seed 002, "Velocity Visualization").
//
// Positions are kept relative to the volume centre so that float never holds
// large world coordinates; MCDCRel maps centre-relative model coordinates to
// clip space and is built on the CPU in double precision.
//
// Variant blocks (kept or removed on the CPU; `//PLUME::IF A B` keeps a block if A or B is on):
//   STRAIGHT | RK2 | RK4  -- one segment p -> p + Scale v(p), or a streamlet of
//                            PLUME_SEGMENTS steps of length Scale/PLUME_SEGMENTS
//   THIN | WIDE           -- 1-pixel line strips, or screen-aligned triangle
//                            strips LineWidth pixels wide (core GL has no wide lines)
// PLUME_SEGMENTS and PLUME_POINTS (= PLUME_SEGMENTS + 1) come from the Defines tag.

//PLUME::Defines

layout(points) in;
//PLUME::IF THIN
layout(line_strip, max_vertices = PLUME_POINTS) out;
//PLUME::ENDIF
//PLUME::IF WIDE
layout(triangle_strip, max_vertices = PLUME_VERTICES_WIDE) out;
//PLUME::ENDIF

in vec3 rootIndex[];

out float glyphAlpha;
flat out vec4 glyphColor;

uniform sampler3D Velocity; // RGBA32F: xyz = velocity, a = valid mask (0 or 1)
uniform mat4 MCDCRel;       // centre-relative model coordinates -> clip
uniform mat4 IndexToRel;    // index space -> centre-relative model coordinates
uniform mat4 RelToIndex;    // inverse of IndexToRel
uniform vec3 Dims;          // grid dimensions (number of nodes per axis)
uniform float Scale;        // glyph length per unit velocity
uniform float MinimumSpeed; // roots with |v| <= MinimumSpeed emit nothing
uniform float RootAlpha;    // alpha at the root (1 at the tip)
uniform vec2 ColorRange;    // (minimum, 1 / (maximum - minimum)) of |v| for colouring
//PLUME::IF LUT
uniform sampler2D ColorLUT; // 1-row lookup table over ColorRange
uniform float LUTSize;      // its number of entries
//PLUME::ENDIF
//PLUME::IF SOLID
uniform vec3 SolidColor;
//PLUME::ENDIF
//PLUME::IF RK2 RK4
uniform vec3 StreamAxes;    // 0 along axes where the grid is one node thick, else 1
//PLUME::ENDIF
//PLUME::IF WIDE
uniform vec2 ViewportSize;  // pixels
uniform float HalfWidth;    // half the line width, pixels
//PLUME::ENDIF

vec4 SampleIndex(vec3 idx)
{
  return texture(Velocity, (idx + 0.5) / Dims);
}

bool InsideVolume(vec3 idx)
{
  return all(greaterThanEqual(idx, vec3(-1e-3))) && all(lessThanEqual(idx, Dims - 1.0 + 1e-3));
}

//PLUME::IF RK2 RK4
// velocity at a centre-relative position; false outside the volume or the valid mask
bool VelocityAt(vec3 p, out vec3 v)
{
  vec3 idx = (RelToIndex * vec4(p, 1.0)).xyz;
  vec4 s = SampleIndex(idx);
  v = s.xyz * StreamAxes;
  return InsideVolume(idx) && s.a >= 0.999;
}
//PLUME::ENDIF

bool AllFinite(vec4 c)
{
  return !any(isnan(c)) && !any(isinf(c));
}

void main()
{
  vec3 idx0 = rootIndex[0];
  if (!InsideVolume(idx0))
  {
    return;
  }
  vec4 s0 = SampleIndex(idx0);
  float speed = length(s0.xyz);
  if (s0.a < 0.999 || !(speed > MinimumSpeed))
  {
    return;
  }

  // ---- build the glyph polyline in centre-relative model coordinates
  vec3 pts[PLUME_POINTS];
  int n = 1;
  pts[0] = (IndexToRel * vec4(idx0, 1.0)).xyz;
//PLUME::IF STRAIGHT
  pts[1] = pts[0] + Scale * s0.xyz;
  n = 2;
//PLUME::ENDIF
//PLUME::IF RK2
  {
    float h = Scale / float(PLUME_SEGMENTS);
    vec3 p = pts[0];
    vec3 k1 = s0.xyz * StreamAxes;
    for (int step = 0; step < PLUME_SEGMENTS; ++step)
    {
      vec3 k2;
      if (!VelocityAt(p + 0.5 * h * k1, k2)) break;
      vec3 q = p + h * k2;
      if (!VelocityAt(q, k1)) break; // stop at the volume edge or the mask; k1 for the next step
      p = q;
      pts[n++] = p;
    }
  }
//PLUME::ENDIF
//PLUME::IF RK4
  {
    float h = Scale / float(PLUME_SEGMENTS);
    vec3 p = pts[0];
    vec3 k1 = s0.xyz * StreamAxes;
    for (int step = 0; step < PLUME_SEGMENTS; ++step)
    {
      vec3 k2, k3, k4;
      if (!VelocityAt(p + 0.5 * h * k1, k2)) break;
      if (!VelocityAt(p + 0.5 * h * k2, k3)) break;
      if (!VelocityAt(p + h * k3, k4)) break;
      vec3 q = p + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      if (!VelocityAt(q, k1)) break; // stop at the volume edge or the mask; k1 for the next step
      p = q;
      pts[n++] = p;
    }
  }
//PLUME::ENDIF
  if (n < 2)
  {
    return;
  }

  // ---- to clip space; cull if every point lies outside the same clip plane
  vec4 clip[PLUME_POINTS];
  float alpha[PLUME_POINTS];
  bvec3 allLow = bvec3(true);
  bvec3 allHigh = bvec3(true);
  for (int i = 0; i < n; ++i)
  {
    vec4 c = MCDCRel * vec4(pts[i], 1.0);
    if (!AllFinite(c))
    {
      return; // overflow (e.g. absurd velocities): draw nothing rather than garbage
    }
    clip[i] = c;
    alpha[i] = mix(RootAlpha, 1.0, float(i) / float(n - 1));
    allLow = bvec3(allLow.x && c.x < -c.w, allLow.y && c.y < -c.w, allLow.z && c.z < -c.w);
    allHigh = bvec3(allHigh.x && c.x > c.w, allHigh.y && c.y > c.w, allHigh.z && c.z > c.w);
  }
  if (any(allLow) || any(allHigh))
  {
    return;
  }

//PLUME::IF LUT
  // exact table entries at texel centres, linear in between
  float colorCoord = clamp((speed - ColorRange.x) * ColorRange.y, 0.0, 1.0);
  vec4 color = textureLod(ColorLUT, vec2((colorCoord * (LUTSize - 1.0) + 0.5) / LUTSize, 0.5), 0.0);
//PLUME::ENDIF
//PLUME::IF SOLID
  vec4 color = vec4(SolidColor, 1.0);
//PLUME::ENDIF

//PLUME::IF THIN
  for (int i = 0; i < n; ++i)
  {
    glyphAlpha = alpha[i];
    glyphColor = color; // outputs are undefined after EmitVertex: set all of them each time
    gl_Position = clip[i];
    EmitVertex();
  }
  EndPrimitive();
//PLUME::ENDIF
//PLUME::IF WIDE
  // Keep the first run of the polyline in front of the near plane (z >= -w),
  // so the perspective division below is safe; GL clips the rest.
  vec4 kc[PLUME_POINTS];
  float ka[PLUME_POINTS];
  int m = 0;
  float dPrev = 0.0;
  for (int i = 0; i < n; ++i)
  {
    float d = clip[i].z + clip[i].w;
    if (d >= 0.0)
    {
      if (i > 0 && dPrev < 0.0)
      {
        if (m > 0) break;
        float t = dPrev / (dPrev - d);
        kc[m] = mix(clip[i - 1], clip[i], t);
        ka[m] = mix(alpha[i - 1], alpha[i], t);
        ++m;
      }
      kc[m] = clip[i];
      ka[m] = alpha[i];
      ++m;
    }
    else if (i > 0 && dPrev >= 0.0)
    {
      float t = dPrev / (dPrev - d);
      kc[m] = mix(clip[i - 1], clip[i], t);
      ka[m] = mix(alpha[i - 1], alpha[i], t);
      ++m;
      break;
    }
    dPrev = d;
  }
  if (m < 2)
  {
    return;
  }
  // screen positions (pixels) and a miter-free offset along the local normal
  vec2 scr[PLUME_POINTS];
  for (int i = 0; i < m; ++i)
  {
    kc[i].w = max(kc[i].w, 1e-30);
    scr[i] = kc[i].xy / kc[i].w * 0.5 * ViewportSize;
  }
  for (int i = 0; i < m; ++i)
  {
    vec2 d = scr[min(i + 1, m - 1)] - scr[max(i - 1, 0)];
    float len = length(d);
    vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 offset = vec2(-dir.y, dir.x) * HalfWidth * 2.0 / ViewportSize * kc[i].w;
    glyphAlpha = ka[i];
    glyphColor = color;
    gl_Position = vec4(kc[i].xy + offset, kc[i].zw);
    EmitVertex();
    glyphAlpha = ka[i];
    glyphColor = color;
    gl_Position = vec4(kc[i].xy - offset, kc[i].zw);
    EmitVertex();
  }
  EndPrimitive();
//PLUME::ENDIF
}
