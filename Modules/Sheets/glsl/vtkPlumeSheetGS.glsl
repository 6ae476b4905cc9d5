//VTK::System::Dec

// vtkPlumeSheetMapper geometry shader (seed 000, Appendix A): per triangle,
// the screen-space box that covers every view ray reaching the triangle's
// Gaussian support, plus the flat data the fragment shader integrates with.
// Everything is in eye space (camera at the origin for perspective views).

//PLUME::Defines

layout(triangles) in;
layout(triangle_strip, max_vertices = 4) out;

in vec3 cornerEye[];
in vec3 cornerDensity[];
in vec2 cornerSigma[];
flat in int cornerTriangle[];

uniform mat4 Projection;      // eye -> clip
uniform vec2 ViewportSize;    // pixels
uniform float Cutoff;         // Lambda: support radius in standard deviations
uniform float MinSigmaPixels; // lower bound on sigma, in pixels at the corner's depth
uniform int Parallel;         // 1 for a parallel projection

flat out vec3 triOrigin;  // p1 (eye space)
flat out vec3 triAxisI;   // first in-plane axis (towards p2)
flat out vec3 triAxisU;   // second in-plane axis
flat out vec3 triNormal;
flat out vec3 triCorners; // (p2'.x, p3'.x, p3'.y) in triangle space; p1' = 0, p2'.y = 0
flat out vec3 triD0;
flat out vec3 triD1;
flat out vec3 triD2;
flat out vec3 triSigmaB;  // sigma_b at the three corners
flat out vec3 triSigmaT;  // sigma_t at the three corners (0: thin sheet)

struct Flat
{
  vec3 origin;
  vec3 axisI;
  vec3 axisU;
  vec3 normal;
  vec3 corners;
  vec3 sigmaB;
  vec3 sigmaT;
};

void EmitCorner(Flat f, vec2 ndc)
{
  triOrigin = f.origin;
  triAxisI = f.axisI;
  triAxisU = f.axisU;
  triNormal = f.normal;
  triCorners = f.corners;
  triD0 = cornerDensity[0];
  triD1 = cornerDensity[1];
  triD2 = cornerDensity[2];
  triSigmaB = f.sigmaB;
  triSigmaT = f.sigmaT;
  gl_PrimitiveID = cornerTriangle[0]; // not gl_PrimitiveIDIn: it restarts with every draw
  gl_Position = vec4(ndc, 0.0, 1.0);
  EmitVertex();
}

void main()
{
  vec3 p[3] = vec3[3](cornerEye[0], cornerEye[1], cornerEye[2]);
  vec3 e1 = p[1] - p[0];
  vec3 e2 = p[2] - p[0];
  vec3 n = cross(e1, e2);
  float l1 = length(e1);
  float nl = length(n);
  // zero-area triangles integrate to zero: emit nothing
  if (!(l1 > 0.0) || !(nl > 1e-12 * (dot(e1, e1) + dot(e2, e2))))
  {
    return;
  }
  vec3 axisI = e1 / l1;
  vec3 normal = n / nl;
  vec3 axisU = cross(normal, axisI);

  float sb[3];
  float st[3];
  bool full = false;
  vec2 lo = vec2(1e30);
  vec2 hi = vec2(-1e30);
  for (int i = 0; i < 3; ++i)
  {
    // the 1/3-pixel lower bound (pixel size at the corner's depth: 2 w / (P11 H))
    float w = (Projection * vec4(p[i], 1.0)).w;
    float floorSigma = w > 0.0 ? MinSigmaPixels * 2.0 * w / (Projection[1][1] * ViewportSize.y) : 0.0;
    sb[i] = max(cornerSigma[i].x, floorSigma);
//PLUME::IF THIN
    st[i] = 0.0;
//PLUME::ENDIF
//PLUME::IF THICK
    st[i] = max(cornerSigma[i].y, floorSigma);
//PLUME::ENDIF
    float r = Cutoff * max(sb[i], st[i]);
    // the face of the sphere's bounding cube that faces the viewer
    vec3 toEye = Parallel == 1 ? vec3(0.0, 0.0, 1.0) : -p[i];
    float dist = length(toEye);
    if (Parallel == 0 && !(dist > 1.7321 * r * 1.0001))
    {
      full = true; // the eye is inside (or at) the cube: every ray may see it
      continue;
    }
    toEye /= dist;
    vec3 helper = abs(toEye.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 a1 = normalize(cross(toEye, helper));
    vec3 a2 = cross(toEye, a1);
    vec3 face = p[i] + r * toEye;
    for (int c = 0; c < 4; ++c)
    {
      vec3 corner = face + r * ((c & 1) == 1 ? a1 : -a1) + r * ((c & 2) == 2 ? a2 : -a2);
      vec4 clip = Projection * vec4(corner, 1.0);
      if (!(clip.w > 1e-20))
      {
        full = true;
        continue;
      }
      vec2 ndc = clip.xy / clip.w;
      lo = min(lo, ndc);
      hi = max(hi, ndc);
    }
  }
  if (full)
  {
    lo = vec2(-1.0);
    hi = vec2(1.0);
  }
  // off-screen boxes emit nothing
  if (hi.x < -1.0 || hi.y < -1.0 || lo.x > 1.0 || lo.y > 1.0 || any(isnan(lo)) || any(isnan(hi)))
  {
    return;
  }
  lo = max(lo, vec2(-1.0));
  hi = min(hi, vec2(1.0));

  Flat f;
  f.origin = p[0];
  f.axisI = axisI;
  f.axisU = axisU;
  f.normal = normal;
  f.corners = vec3(l1, dot(e2, axisI), dot(e2, axisU));
  f.sigmaB = vec3(sb[0], sb[1], sb[2]);
  f.sigmaT = vec3(st[0], st[1], st[2]);
  // outputs are undefined after EmitVertex: set them for every corner
  EmitCorner(f, vec2(lo.x, lo.y));
  EmitCorner(f, vec2(hi.x, lo.y));
  EmitCorner(f, vec2(lo.x, hi.y));
  EmitCorner(f, vec2(hi.x, hi.y));
  EndPrimitive();
}
