//VTK::System::Dec

// vtkPlumeAirlightPass: one full-screen pass over the delegate's colour and
// depth. Per pixel and channel: C * exp(-kt ds) + sum of the lights' single
// scattering, in the closed form of Documentation/Airlight.md:
//   integral over [a, b] = P_head(b) - P_head(a)   (the part with t <= 0)
//                        + P_tail(a) - P_tail(b)   (the part with t >= 0)
//   P_head = ks I0/(2 pi) exp(-kt tc) H(m, tau) / (d - t),  tau = h/(d - t), m = kt h^2/(d - t)
//   P_tail = ks I0/(2 pi) exp(-kt (x + d)) G(m, eps) / (t + d), eps = h/(t + d), m = kt (t + d)
// t = x - tc: position along the ray from the foot of the perpendicular from
// the light; h: the light's distance from the ray's line; d = sqrt(t^2 + h^2).
// Everything is computed in eye coordinates (VTK's view transform is rigid).

//PLUME::Defines

in vec2 texCoord;

uniform sampler2D SceneColor;
uniform sampler2D SceneDepth;
uniform sampler2D Table;      // RG32F, TableSize^2: (1+m) H and (1+m) G (times row weights), see vtkPlumeAirlightPass.h
uniform int TableSize;
uniform vec2 PhaseStretch;    // (k of H, k of G): 0 for the isotropic phase
uniform vec4 PhaseRows;       // (row warp of H, of G, row weight of H, of G): 0 for the isotropic phase
uniform float Anisotropy;     // Henyey-Greenstein g (the brute-force march only)
uniform vec2 ViewportOrigin;  // window pixels of the viewport's lower-left corner
uniform mat4 InverseProjection; // NDC -> eye coordinates
uniform int Perspective;      // 1: rays start at the eye; 0: at the near plane
uniform vec2 ViewportSize;    // w, h of the full-resolution viewport
// The airlight lattice (vtkPlumeAirlightPass::Downsampling D > 1), four
// passes per light group (see main): LATTICE_NODES evaluates the airlight on
// the rays through pixels (i D, j D) (the last node of a row or column at the
// viewport's last pixel); LATTICE_CLASSIFY marks each cell of D x D pixels
// between four nodes that must be refined; LATTICE_RESOLVE (no light code)
// writes the frame with the nodes' bilinear interpolation in the other cells
// and no airlight in refined ones; LATTICE_REFINE (drawn by the lattice cells'
// vertex shader over refined cells only) adds their exact airlight. The
// second level (spacing D/2, vtkPlumeAirlightPass::LatticeLevels) runs NODES
// on its listed nodes (see nodeAirlight) and CLASSIFY inside level 0's
// refined cells (drawn there by the same vertex shader), LATTICE_INTERPOLATE
// adds its interpolation in its interpolated cells, and LATTICE_REFINE runs
// in its refined cells only. The uniforms below describe the level drawn.
uniform int Lattice;               // D
uniform ivec2 LatticeCellCount;    // cells per row and column (nodes: one more)
uniform sampler2D LatticeNodes;    // RGB: the nodes' airlight
uniform sampler2D LatticeCells;    // R: 0 interpolated, 1 refined
uniform float LatticeTolerance;    // the largest estimated interpolation error (absolute)
uniform float LatticeDepthTolerance; // relative eye-depth mismatch that marks a surface edge
uniform sampler2D LatticeCoarseNodes; // a finer level: its parent level's nodes
uniform sampler2D LatticeNodeMap;  // a finer level: per node, its texel index in LatticeNodes (see nodeAirlight)
uniform sampler2D LatticeNodeList; // a finer level's nodes pass: per texel of LatticeNodes, its node (RG)
// A finer level's passes are compiled with LATTICE_FINE: llvmpipe runs both
// sides of a branch on a uniform, so level 0 paid for a finer level's node
// look-ups (four fetches a node) in its classify and resolve passes.
#ifdef PLUME_FEATURE_LATTICE_FINE
const int LatticeParentBlock = 2;  // a finer level's cells per parent cell side
#endif
// A pixel's lattice coordinate (see latticeCoordinate), in float: llvmpipe
// runs an integer division by a uniform one lane at a time.
uniform float LatticeInverse;      // 1 / D
uniform vec2 LatticeLastSlope;     // 1 / the last cell's width in pixels (one per axis)
uniform vec2 LatticeLastOffset;    // (cells - 1) - the last cell's first pixel / its width
uniform vec2 LatticeInverseNodes;  // 1 / (cells + 1)
//PLUME::IF LATTICE_CLASSIFY
uniform vec3 LightPixel[NUMBER_OF_LIGHTS]; // the lights' viewport pixel and 1 if in front of the eye
uniform vec4 LightShaft[NUMBER_OF_LIGHTS]; // a narrow spot's axis on the viewport: pixels (x0, y0), (x1, y1)
//PLUME::ENDIF
// 0: the frame (surface attenuated + airlight); 1: the airlight alone, for a
// light group after the first, blended additively onto the frame.
uniform int AirlightOnly;

uniform vec3 KappaS;
uniform vec3 KappaT;

uniform int NumberOfLights;
uniform vec3 LightPosition[NUMBER_OF_LIGHTS]; // eye coordinates
uniform vec3 LightI0[NUMBER_OF_LIGHTS];       // RGB radiant intensity
//PLUME::IF SPOT
uniform vec3 LightAxis[NUMBER_OF_LIGHTS];     // spot direction (unit, eye coordinates)
uniform float LightCosCone[NUMBER_OF_LIGHTS]; // cos(cone angle); -2 for point lights
uniform float LightExponent[NUMBER_OF_LIGHTS];
uniform int SpotSteps;
//PLUME::ENDIF
//PLUME::IF TEXTURE
// Textured spot lights: the images of a frame's textured lights stacked in one
// RGBA32F atlas, read texel by texel (bilinear by hand, clamped to the
// light's own rectangle: no bleeding from a neighbour, exact in float).
uniform sampler2D LightTextures;
uniform vec4 LightTextureRect[NUMBER_OF_LIGHTS];  // atlas texels x0, y0, width, height; width 0: untextured
uniform vec3 LightTextureRight[NUMBER_OF_LIGHTS]; // the image's u axis / tan(cone), eye coordinates
uniform vec3 LightTextureUp[NUMBER_OF_LIGHTS];    // the image's v axis / tan(cone)
//PLUME::ENDIF
//PLUME::IF SHADOW
// Shadowed lights: LightShadow[l] is the light's shadow map (-1: none).
// ShadowMatrixK[f]: eye coordinates -> the light camera's clip coordinates of
// face f; ShadowFacesK: 1 for a spot light (face 0, the whole map), 6 for a
// point light (faces +x, -x, +y, -y, +z, -z of the world, tiles (f % 3, f / 3)
// of a 3 x 2 atlas); ShadowLightK: the light's eye position; ShadowRangeK:
// near and far distances; ShadowMapK: window depth.
uniform int LightShadow[NUMBER_OF_LIGHTS];
uniform int ShadowSteps;
uniform int ShadowMinMax;     // 1: runs of 8 steps decided from the min-max mip chain
uniform int ShadowRunStatistics; // 1: the output is (runs decided, all runs) of the marches
float RunsDecided = 0.0;
float RunsTotal = 0.0;
uniform mat3 EyeToWorld;
// Per shadow map, one set of uniforms and one case in lit() and runState():
// GLSL cannot index samplers by a computed value. SHADOW_MAPS(M) expands to
// M(1) ... M(NUMBER_OF_SHADOWS - 1) (map 0 is the default case), and ##
// pastes the map's number into the names.
#if NUMBER_OF_SHADOWS > 1
#define SHADOW_MAP_1(M) M(1)
#else
#define SHADOW_MAP_1(M)
#endif
#if NUMBER_OF_SHADOWS > 2
#define SHADOW_MAP_2(M) M(2)
#else
#define SHADOW_MAP_2(M)
#endif
#if NUMBER_OF_SHADOWS > 3
#define SHADOW_MAP_3(M) M(3)
#else
#define SHADOW_MAP_3(M)
#endif
#if NUMBER_OF_SHADOWS > 4
#define SHADOW_MAP_4(M) M(4)
#else
#define SHADOW_MAP_4(M)
#endif
#if NUMBER_OF_SHADOWS > 5
#define SHADOW_MAP_5(M) M(5)
#else
#define SHADOW_MAP_5(M)
#endif
#if NUMBER_OF_SHADOWS > 6
#define SHADOW_MAP_6(M) M(6)
#else
#define SHADOW_MAP_6(M)
#endif
#if NUMBER_OF_SHADOWS > 7
#define SHADOW_MAP_7(M) M(7)
#else
#define SHADOW_MAP_7(M)
#endif
#define SHADOW_MAPS(M) SHADOW_MAP_1(M) SHADOW_MAP_2(M) SHADOW_MAP_3(M) SHADOW_MAP_4(M) SHADOW_MAP_5(M) SHADOW_MAP_6(M) SHADOW_MAP_7(M)
#define SHADOW_UNIFORMS(i) uniform sampler2D ShadowMap##i; uniform mat4 ShadowMatrix##i[6]; \
  uniform vec2 ShadowRange##i; uniform int ShadowFaces##i; uniform vec3 ShadowLight##i; \
  uniform ivec2 ShadowSize##i; uniform int ShadowTop##i;
SHADOW_UNIFORMS(0)
SHADOW_MAPS(SHADOW_UNIFORMS)
//PLUME::ENDIF

//VTK::Output::Dec

const float INV_2PI = 0.15915494309189535;
const float HUGE = 1e20;

// Bilinear look-up of one table at (m, tau or eps): one filtered fetch, texel
// centres at (i + 0.5)/N (GL_LINEAR on the RG32F texture). The coordinates
// are p = sqrt(m' / (1 + m')), m' = m * mScale, and u = tau (1 + k) / (1 + k tau);
// the texel holds (1 + m') (1 + w tau) times the function (k = w = 0 and
// mScale = 1 for the isotropic phase; for Henyey-Greenstein they follow the
// phase's peak, see vtkPlumeAirlightPass.h). Returns the function itself:
// `channel` 0 the table's H, 1 its G.
float lookup(float m, float tau, float mScale, float k, float w, int channel)
{
  float ms = m * mScale;
  float p = sqrt(ms / (1.0 + ms)); // m in [0, inf) -> p in [0, 1], finer near m = 0
  float u = tau * (1.0 + k) / (1.0 + k * tau);
  float n1 = float(TableSize - 1);
  vec2 c = (clamp(vec2(p, u), 0.0, 1.0) * n1 + 0.5) / float(TableSize);
  return texture(Table, c)[channel] / ((1.0 + ms) * (1.0 + w * tau));
}

// H(m, tau) and G(m, eps) of the header; m's scale follows the peak row by
// row (1 for the isotropic phase).
float lookupH(float m, float tau)
{
  return lookup(m, tau, 1.0 / (1.0 + PhaseStretch.x * tau), PhaseRows.x, PhaseRows.z, 0);
}
float lookupG(float m, float eps)
{
  return lookup(m, eps, 1.0 + PhaseStretch.y * eps, PhaseRows.y, PhaseRows.w, 1);
}

// P_head(t) without the factor ks I0/(2 pi) exp(-kt tc), for t <= 0, per channel.
vec3 headPotential(float t, float h)
{
  float d = sqrt(t * t + h * h);
  float dm = max(d - t, 1e-30); // = d + |t| >= d: no cancellation
  float tau = min(h / dm, 1.0);
  float hh = h * (h / dm);      // = t + d without cancellation
#ifdef PLUME_FEATURE_GREY
  // kt is the same in R, G and B: one look-up serves the three channels.
  return vec3(lookupH(KappaT.x * hh, tau) / dm);
#else
  vec3 r;
  for (int c = 0; c < 3; ++c)
  {
    r[c] = lookupH(KappaT[c] * hh, tau) / dm;
  }
  return r;
#endif
}

// P_tail(t) without the factor ks I0/(2 pi), for t >= 0, per channel; x = t + tc.
vec3 tailPotential(float t, float h, float x)
{
  if (isinf(t))
  {
    return vec3(0.0);
  }
  float d = sqrt(t * t + h * h);
  float dp = max(t + d, 1e-30);
  float eps = min(h / dp, 1.0);
#ifdef PLUME_FEATURE_GREY
  return vec3(exp(-KappaT.x * (x + d)) * lookupG(KappaT.x * dp, eps) / dp);
#else
  vec3 r;
  for (int c = 0; c < 3; ++c)
  {
    r[c] = exp(-KappaT[c] * (x + d)) * lookupG(KappaT[c] * dp, eps) / dp;
  }
  return r;
#endif
}

// A running integral Phi(x) of the unit airlight along the ray, so that the
// integral over [a, b] is Phi(b) - Phi(a): the head potential before the foot,
// then the foot's value minus the tail's decrease. `footPhi` = Phi(tc) (0 if
// the foot lies behind the origin), `footTail` = P_tail(foot) (or at x = 0).
// One table fetch per channel: the head reads H at (kt (t + d), tau), the tail
// G at (kt (t + d), eps), and with q = d + |t| (d - t before the foot, t + d
// past it) both are at rho = h / q (tau or eps), so the side is a per-pixel
// select of the coordinates, the channel and the exponent, not a branch
// (llvmpipe runs both sides of a divergent `if`: headPotential and
// tailPotential would cost two fetches per channel).
vec3 runningIntegral(float x, float tc, float h, vec3 footPhi, vec3 footTail)
{
  bool infinite = isinf(x);
  float t = infinite ? 0.0 : x - tc;
  bool head = !infinite && t <= 0.0;
  float d = sqrt(t * t + h * h);
  float q = max(d + abs(t), 1e-30);
  float rho = min(h / q, 1.0);
  float len = head ? h * rho : q; // t + d (before the foot h^2 / (d - t): no cancellation)
  // lookupH's or lookupG's arguments, selected
  float mScale = head ? 1.0 / (1.0 + PhaseStretch.x * rho) : 1.0 + PhaseStretch.y * rho;
  float k = head ? PhaseRows.x : PhaseRows.y;
  float w = head ? PhaseRows.z : PhaseRows.w;
  int table = head ? 0 : 1;
  float path = head ? tc : x + d; // the exponent's optical length over kt
#ifdef PLUME_FEATURE_GREY
  const int CHANNELS = 1;
#else
  const int CHANNELS = 3;
#endif
  vec3 P;
  for (int c = 0; c < CHANNELS; ++c)
  {
    P[c] = exp(-KappaT[c] * path) * lookup(KappaT[c] * len, rho, mScale, k, w, table) / q;
  }
#ifdef PLUME_FEATURE_GREY
  P = vec3(P[0]);
#endif
  P = infinite ? vec3(0.0) : P; // the tail potential vanishes at infinity
  return head ? P : footPhi + footTail - P;
}

// Phi's constants for the ray: the head potential at the foot times its
// exponential (0 if the foot is behind the origin), and the tail potential at
// the foot or, if that is behind the origin, at x = 0. (A foot at the origin,
// tc = 0, has a head side: runningIntegral(0) takes it, so footPhi must too.)
void footPotentials(float tc, float h, out vec3 footPhi, out vec3 footTail)
{
  footPhi = tc >= 0.0 ? exp(-KappaT * tc) * headPotential(0.0, h) : vec3(0.0);
  float tStart = max(-tc, 0.0);
  footTail = tailPotential(tStart, h, tStart + tc);
}

//PLUME::IF SPOT
bool insideCone(vec3 p, vec3 apex, vec3 axis, float cosCone)
{
  vec3 v = p - apex;
  return dot(v, axis) >= cosCone * length(v);
}

// The interval of the ray o + x r (x in [0, xs]) inside the cone; empty if lo >= hi.
// The cone (half-angle <= 90 degrees) is convex, so it is one interval; its ends
// are among the roots of (v.a)^2 - c^2 |v|^2 = 0 and the segment's ends. Each piece
// between consecutive candidates is classified by the exact test at its middle.
vec2 coneInterval(vec3 o, vec3 r, float xs, vec3 apex, vec3 axis, float c)
{
  vec3 v = o - apex;
  float ra = dot(r, axis);
  float va = dot(v, axis);
  float A = ra * ra - c * c;
  float B = va * ra - c * c * dot(v, r);
  float C = va * va - c * c * dot(v, v);
  float roots[2];
  int nroots = 0;
  if (abs(A) > 1e-12)
  {
    float disc = B * B - A * C;
    if (disc >= 0.0)
    {
      // stable quadratic roots
      float q = -(B + (B >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
      float x1 = q / A;
      float x2 = (q != 0.0) ? C / q : x1;
      roots[0] = min(x1, x2);
      roots[1] = max(x1, x2);
      nroots = 2;
    }
  }
  else if (abs(B) > 1e-20)
  {
    roots[0] = -C / (2.0 * B);
    nroots = 1;
  }
  float bounds[4];
  int nb = 0;
  bounds[nb++] = 0.0;
  for (int k = 0; k < nroots; ++k)
  {
    if (roots[k] > 0.0 && roots[k] < xs)
    {
      bounds[nb++] = roots[k];
    }
  }
  bounds[nb++] = xs;
  float lo = HUGE;
  float hi = -HUGE;
  for (int k = 0; k + 1 < nb; ++k)
  {
    float a = bounds[k];
    float b = bounds[k + 1];
    float mid = isinf(b) ? a + 1.0 + abs(a) : 0.5 * (a + b);
    if (b > a && insideCone(o + mid * r, apex, axis, c))
    {
      lo = min(lo, a);
      hi = max(hi, b);
    }
  }
  return vec2(lo, hi);
}
//PLUME::ENDIF

//PLUME::IF TEXTURE
bool textured(int l)
{
  return LightTextureRect[l].z > 0.0;
}

//PLUME::LightTexture

// Where the direction v (from the light) meets light l's image.
vec2 lightTextureCoordinates(int l, vec3 v)
{
  return plumeLightTextureCoordinates(v, LightAxis[l], LightTextureRight[l], LightTextureUp[l]);
}

// Light l's image (RGB) in direction v.
vec3 lightTexture(int l, vec3 v)
{
  return plumeLightTexel(LightTextures, LightTextureRect[l], lightTextureCoordinates(l, v));
}

// Sub-intervals for a textured light over the ray's span in its cone: two per
// texel the ray's image crosses (a straight line: the projection is
// perspective), at least `steps`, at most 1024.
int textureSteps(int l, vec3 o, vec3 r, vec2 span, int steps)
{
  vec3 L = LightPosition[l];
  vec2 a = lightTextureCoordinates(l, o + span.x * r - L);
  vec2 b = lightTextureCoordinates(l, isinf(span.y) ? r : o + span.y * r - L);
  float texels = length((b - a) * LightTextureRect[l].zw);
  return clamp(int(ceil(2.0 * texels)), steps, 1024);
}
//PLUME::ENDIF

//PLUME::IF SHADOW
// The cube face of a point light for the eye-space offset v from the light:
// the world axis of v's largest component (+x 0, -x 1, +y 2, -y 3, +z 4, -z 5).
int cubeFace(vec3 v)
{
  vec3 w = EyeToWorld * v;
  vec3 a = abs(w);
  if (a.x >= a.y && a.x >= a.z)
  {
    return w.x >= 0.0 ? 0 : 1;
  }
  if (a.y >= a.z)
  {
    return w.y >= 0.0 ? 2 : 3;
  }
  return w.z >= 0.0 ? 4 : 5;
}

// 1 if the eye-space point p is lit in the shadow map (outside its frustum: lit).
// faces 6: p's face f is the tile (f % 3, f / 3) of the 3 x 2 atlas.
float litIn(sampler2D map, ivec2 size, mat4 toLight, vec2 range, vec3 p, int face, int faces)
{
  vec4 clip = toLight * vec4(p, 1.0);
  if (clip.w <= range.x)
  {
    return 1.0; // behind the light or nearer than its near plane
  }
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))))
  {
    return 1.0;
  }
  if (faces == 6)
  {
    // Half a texel inside the tile: no depth from the neighbouring face.
    vec2 inset = 0.5 / vec2(size) * vec2(3.0, 2.0);
    uv = (vec2(float(face % 3), float(face / 3)) + clamp(uv, inset, 1.0 - inset)) / vec2(3.0, 2.0);
  }
  // Nearest texel, clamped to the map's edge (the atlas's level 0: the depth).
  float depth = texelFetch(map, clamp(ivec2(floor(uv * vec2(size))), ivec2(0), size - 1), 0).r;
  if (depth >= 1.0)
  {
    return 1.0; // nothing drawn there
  }
  // The map's depth as a distance along the light's axis; clip.w is the point's.
  float n = range.x;
  float f = range.y;
  float zMap = 2.0 * n * f / ((f + n) - (2.0 * depth - 1.0) * (f - n));
  return clip.w <= zMap * 1.002 ? 1.0 : 0.0;
}

// Map i's test of point p (on p's cube face for a point light).
#define LIT_IN(i) { int f = ShadowFaces##i == 6 ? cubeFace(p - ShadowLight##i) : 0; \
  return litIn(ShadowMap##i, ShadowSize##i, ShadowMatrix##i[f], ShadowRange##i, p, f, ShadowFaces##i); }
#define LIT_CASE(i) if (s == i) LIT_IN(i)
float lit(int s, vec3 p)
{
  SHADOW_MAPS(LIT_CASE)
  LIT_IN(0)
}

// Min-max shadow mipmaps (Chen et al. 2011). Whether every point of the
// eye-space segment [pa, pb] is shadowed (0) or lit (1) in the map, by
// litIn's rule, or mixed or undecided (2). The segment projects to a straight
// segment in the map (both ends in front of the light) and its distance along
// the light's axis (clip.w) is affine along it, so the texels nearest
// sampling can read lie in the ends' bounding box (one texel wider for
// rounding) and the distances between the ends' ones. The box is covered by
// at most 2 x 2 texels of the first level where it spans at most two; each
// holds (min, max) of the depth under it.
int runIn(sampler2D map, ivec2 size, int top, mat4 toLight, vec2 range, vec3 pa, vec3 pb, int face, int faces)
{
  vec4 ca = toLight * vec4(pa, 1.0);
  vec4 cb = toLight * vec4(pb, 1.0);
  if (min(ca.w, cb.w) <= range.x * 1.0001)
  {
    return 2; // near the light: litIn calls it lit
  }
  vec2 ua = ca.xy / ca.w * 0.5 + 0.5;
  vec2 ub = cb.xy / cb.w * 0.5 + 0.5;
  vec2 lo = min(ua, ub);
  vec2 hi = max(ua, ub);
  if (any(lessThan(lo, vec2(0.0))) || any(greaterThan(hi, vec2(1.0))))
  {
    return 2; // partly outside the frustum: litIn calls that part lit
  }
  if (top == 0)
  {
    return 2; // no pyramid for this map
  }
  if (faces == 6)
  {
    vec2 inset = 0.5 / vec2(size) * vec2(3.0, 2.0);
    vec2 tile = vec2(float(face % 3), float(face / 3));
    lo = (tile + clamp(lo, inset, 1.0 - inset)) / vec2(3.0, 2.0);
    hi = (tile + clamp(hi, inset, 1.0 - inset)) / vec2(3.0, 2.0);
  }
  ivec2 i0 = clamp(ivec2(floor(lo * vec2(size))) - 1, ivec2(0), size - 1);
  ivec2 i1 = clamp(ivec2(floor(hi * vec2(size))) + 1, ivec2(0), size - 1);
  // The first level with 2^level > the box's span in texels: there i >> level
  // of the box's ends differ by at most 1.
  int span = max(i1.x - i0.x, i1.y - i0.y);
  int level = span > 0 ? int(floor(log2(float(span)))) + 1 : 0;
  level += ((i1.x >> level) - (i0.x >> level) > 1 || (i1.y >> level) - (i0.y >> level) > 1) ? 1 : 0;
  level = min(level, top);
  ivec2 last = max(size >> level, ivec2(1)) - 1;
  ivec2 a = min(i0 >> level, last);
  ivec2 b = min(i1 >> level, last);
  if (b.x - a.x > 1 || b.y - a.y > 1)
  {
    return 2; // wider than the top level (a map wider than twice its height)
  }
  // Level L > 0 sits right of level 0, at height size.y - (size.y >> (L - 1)).
  ivec2 origin = level == 0 ? ivec2(0) : ivec2(size.x, size.y - (size.y >> (level - 1)));
  vec2 t00 = texelFetch(map, origin + a, 0).rg;
  vec2 t10 = texelFetch(map, origin + ivec2(b.x, a.y), 0).rg;
  vec2 t01 = texelFetch(map, origin + ivec2(a.x, b.y), 0).rg;
  vec2 t11 = texelFetch(map, origin + b, 0).rg;
  float dmin = min(min(t00.x, t10.x), min(t01.x, t11.x));
  float dmax = max(max(t00.y, t10.y), max(t01.y, t11.y));
  if (dmin >= 1.0)
  {
    return 1; // nothing drawn under the run
  }
  float n = range.x;
  float f = range.y;
  float zNear = 2.0 * n * f / ((f + n) - (2.0 * dmin - 1.0) * (f - n));
  // A margin of 1e-5 on the distances: the steps' own points are computed
  // through other roundings than the ends' interpolation.
  if (max(ca.w, cb.w) * 1.00001 <= zNear * 1.002)
  {
    return 1;
  }
  float zFar = 2.0 * n * f / ((f + n) - (2.0 * dmax - 1.0) * (f - n));
  if (dmax < 1.0 && min(ca.w, cb.w) * 0.99999 > zFar * 1.002)
  {
    return 0;
  }
  return 2;
}

// Map i's run state of the segment [pa, pb] (mixed if its ends are on different cube faces).
#define RUN_IN(i) { int fa = ShadowFaces##i == 6 ? cubeFace(pa - ShadowLight##i) : 0; \
  int fb = ShadowFaces##i == 6 ? cubeFace(pb - ShadowLight##i) : 0; \
  return fa != fb ? 2 : runIn(ShadowMap##i, ShadowSize##i, ShadowTop##i, ShadowMatrix##i[fa], ShadowRange##i, pa, pb, fa, ShadowFaces##i); }
#define RUN_CASE(i) if (s == i) RUN_IN(i)
int runState(int s, vec3 pa, vec3 pb)
{
  SHADOW_MAPS(RUN_CASE)
  RUN_IN(0)
}

// The march of Wyman & Ramsey over [span.x, span.y] for shadowed light l (a
// spot light's cone interval, or the whole ray for a point light), in
// sub-intervals uniform in the angle seen from the light (shadow boundaries
// are angular there). Each adds w * [Phi(x_k) - Phi(x_k-1)] from the
// closed-form running integral when a jittered point of it is lit: a fully
// lit ray telescopes to the unshadowed result. `exponent` 0: w = 1.
vec3 shadowedMarch(vec3 o, vec3 r, vec2 span, float tc, float h, int l, float exponent)
{
  vec3 L = LightPosition[l];
  float th0 = atan(span.x - tc, h);
  float th1 = isinf(span.y) ? 1.5707963267948966 : atan(span.y - tc, h);
  int spotSteps = exponent == 0.0 ? 1 : min(SpotSteps * int(ceil(sqrt(max(exponent, 2.0) / 2.0))), 256);
  int steps = max(ShadowSteps, spotSteps);
  bool weighted = exponent != 0.0;
//PLUME::IF TEXTURE
  if (textured(l))
  {
    steps = textureSteps(l, o, r, span, steps);
    weighted = true;
  }
//PLUME::ENDIF
  float dth = (th1 - th0) / float(steps);
  // Interleaved gradient noise: a per-pixel offset of the lit test in each step.
  float jitter = fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
  vec3 footPhi, footTail;
  footPotentials(tc, h, footPhi, footTail);
  vec3 phiA = runningIntegral(span.x, tc, h, footPhi, footTail);
  int s = LightShadow[l];
  vec3 unit = vec3(0.0);
  // Runs of RUN steps. A run that the min-max chain finds wholly shadowed
  // adds nothing; one wholly lit adds Phi(end) - Phi(start) (the lit steps
  // telescope) or, for a weighted light, its steps' weighted differences
  // without their lit tests. Only a mixed run tests every step. Each run's
  // trip count is 0 or its length: llvmpipe skips a loop that no lane of a
  // SIMD block enters, but runs both sides of a divergent `if`.
  const int RUN = 8;
  float xa = span.x;
  for (int k0 = 0; k0 < steps; k0 += RUN)
  {
    int k1 = min(k0 + RUN, steps);
    float xe = (k1 == steps) ? span.y : tc + h * tan(th0 + float(k1) * dth);
    int state = 2;
    if (ShadowMinMax == 1 && !isinf(xe))
    {
      state = runState(s, o + xa * r, o + xe * r);
    }
    xa = xe;
    RunsTotal += 1.0;
    RunsDecided += state == 2 ? 0.0 : 1.0;
    bool whole = state == 0 || (state == 1 && !weighted);
    for (int j = whole ? 0 : 1; j < 1; ++j)
    {
      // One difference for the run; Phi(end) as the per-step loop computes it.
      vec3 phiB = runningIntegral(xe, tc, h, footPhi, footTail);
      if (state == 1)
      {
        unit += phiB - phiA;
      }
      phiA = phiB;
    }
    for (int k = whole ? k1 + 1 : k0 + 1; k <= k1; ++k)
    {
      float xb = (k == steps) ? span.y : tc + h * tan(th0 + float(k) * dth);
      vec3 phiB = runningIntegral(xb, tc, h, footPhi, footTail);
      bool on = state == 1;
      for (int q = state == 2 ? 0 : 1; q < 1; ++q)
      {
        float xj = tc + h * tan(th0 + (float(k) - 1.0 + jitter) * dth);
        on = lit(s, o + xj * r) > 0.0;
      }
      if (on)
      {
        vec3 w = vec3(1.0);
        if (weighted)
        {
          float thm = th0 + (float(k) - 0.5) * dth;
          vec3 dir = normalize(o + (tc + h * tan(thm)) * r - L);
          w = vec3(exponent == 0.0 ? 1.0 : pow(max(dot(dir, LightAxis[l]), 0.0), exponent));
//PLUME::IF TEXTURE
          if (textured(l))
          {
            w *= lightTexture(l, dir);
          }
//PLUME::ENDIF
        }
        // Not clamped per step: the table's interpolation error can make a
        // short step's difference slightly negative, and clamping each step
        // would add that error up (with a strongly peaked phase, 2 % of the
        // range); unclamped, the lit steps telescope. The sum is clamped.
        unit += w * (phiB - phiA);
      }
      phiA = phiB;
    }
  }
  return max(unit, vec3(0.0));
}
//PLUME::ENDIF

#ifdef PLUME_FEATURE_MARCH
// The brute-force peer (vtkPlumeAirlightPass::MarchSteps > 0): the same
// integral by the midpoint rule with MARCH_STEPS samples per ray and light,
// as a user would write it; rays that hit nothing stop at MarchFar. Returns
// (1/2) integral w exp(-kt (x + d)) / d^2 dx, the closed form's `unit`.
uniform float MarchFar;
vec3 march(vec3 o, vec3 r, float xs, int l)
{
  float xe = isinf(xs) ? MarchFar : xs;
  float dx = xe / float(MARCH_STEPS);
  vec3 sum = vec3(0.0);
  for (int k = 0; k < MARCH_STEPS; ++k)
  {
    float x = (float(k) + 0.5) * dx;
    vec3 v = o + x * r - LightPosition[l];
    float d2 = max(dot(v, v), 1e-30);
    float d = sqrt(d2);
    float w = 1.0;
#ifdef PLUME_FEATURE_SPOT
    if (LightCosCone[l] > -1.5)
    {
      float c = dot(v, LightAxis[l]) / d;
      w = c >= LightCosCone[l] ? pow(max(c, 0.0), LightExponent[l]) : 0.0;
    }
#endif
    vec3 tint = vec3(1.0);
//PLUME::IF TEXTURE
    if (textured(l) && w > 0.0)
    {
      tint = lightTexture(l, v);
    }
//PLUME::ENDIF
//PLUME::IF SHADOW
    // A shadowed light: the same shadow map test at every sample.
    if (LightShadow[l] >= 0 && w > 0.0)
    {
      w *= lit(LightShadow[l], o + x * r);
    }
//PLUME::ENDIF
    // Henyey-Greenstein times 4 pi; cos(scattering angle) = -dot(v, r) / d.
    float g = Anisotropy;
    w *= (1.0 - g * g) / pow(max(1.0 + g * g + 2.0 * g * dot(v, r) / d, 1e-30), 1.5);
    sum += w * tint * exp(-KappaT * (x + d)) / d2;
  }
  return 0.5 * dx * sum;
}
#endif

// The unshadowed airlight of light l over the lit part [span.x, span.y] of
// the ray, without the factor ks I0/(2 pi): Phi(span.y) - Phi(span.x) for an
// unweighted light (a point light, a spot with exponent 0); a weighted one (a
// spot's exponent, a light's image) in sub-intervals uniform in the angle
// theta = atan(t/h) seen from the light, each weighted by pow(cos angle to
// the axis) (and the image) at its middle. One code path for both: llvmpipe
// would run a separate closed form for the unweighted case beside the loop.
vec3 spanAirlight(vec3 o, vec3 r, vec2 span, float tc, float h, int l, float exponent, bool weighted)
{
  int steps = 1;
//PLUME::IF SPOT
  float th0 = atan(span.x - tc, h);
  float th1 = isinf(span.y) ? 1.5707963267948966 : atan(span.y - tc, h);
  // The weight's angular width shrinks as 1/sqrt(exponent): SpotSteps
  // sub-intervals per unit of sqrt(exponent / 2) for a chord that spans the
  // cone's full angle 2 alpha (the most a chord inside the cone subtends at
  // the apex), a shorter chord's share of them (the same angular step), at
  // most 256.
  float share = min((th1 - th0) / (2.0 * acos(clamp(LightCosCone[l], -1.0, 1.0))), 1.0);
  steps = weighted
    ? clamp(int(ceil(float(SpotSteps) * ceil(sqrt(max(exponent, 2.0) / 2.0)) * share)), 1, 256) : 1;
//PLUME::IF TEXTURE
  if (textured(l))
  {
    steps = textureSteps(l, o, r, span, steps);
  }
//PLUME::ENDIF
  float dth = (th1 - th0) / float(steps);
  vec3 L = LightPosition[l];
//PLUME::ENDIF
  vec3 footPhi, footTail;
  footPotentials(tc, h, footPhi, footTail);
  vec3 phiA = runningIntegral(span.x, tc, h, footPhi, footTail);
  vec3 unit = vec3(0.0);
  for (int k = 1; k <= steps; ++k)
  {
    float xb = span.y;
    vec3 w = vec3(1.0);
//PLUME::IF SPOT
    xb = (k == steps) ? span.y : tc + h * tan(th0 + float(k) * dth);
    float thm = th0 + (float(k) - 0.5) * dth;
    vec3 dir = normalize(o + (tc + h * tan(thm)) * r - L);
    w = vec3(exponent == 0.0 ? 1.0 : pow(max(dot(dir, LightAxis[l]), 0.0), exponent));
//PLUME::IF TEXTURE
    if (textured(l))
    {
      w *= lightTexture(l, dir);
    }
//PLUME::ENDIF
//PLUME::ENDIF
    vec3 phiB = runningIntegral(xb, tc, h, footPhi, footTail);
    unit += w * (phiB - phiA); // not clamped per step, see shadowedMarch
    phiA = phiB;
  }
  return max(unit, vec3(0.0));
}

// The airlight of the view ray o + x r, x in [0, xs], summed over the lights.
vec3 airlightOf(vec3 o, vec3 r, float xs)
{
  vec3 airlight = vec3(0.0);
  for (int l = 0; l < NumberOfLights; ++l)
  {
    vec3 L = LightPosition[l];
    vec3 toLight = L - o;
    float tc = dot(toLight, r);                 // foot of the perpendicular
    float h = length(toLight - tc * r);         // distance of the light from the ray's line
    h = max(h, 1e-30);
    vec3 unit = vec3(0.0);
#ifdef PLUME_FEATURE_MARCH
    unit = march(o, r, xs, l);
#else
    vec2 span = vec2(0.0, xs); // the lit part of the ray: all of it, or a spot's cone interval
    float exponent = 0.0;
    bool weighted = false; // the exponent's or the image's weight: sub-intervals
//PLUME::IF SPOT
    if (LightCosCone[l] > -1.5)
    {
      span = coneInterval(o, r, xs, L, LightAxis[l], LightCosCone[l]);
      exponent = LightExponent[l];
      weighted = exponent != 0.0;
//PLUME::IF TEXTURE
      weighted = weighted || textured(l);
//PLUME::ENDIF
    }
//PLUME::ENDIF
    if (span.x < span.y)
    {
//PLUME::IF SHADOW
      if (LightShadow[l] >= 0)
      {
        unit = shadowedMarch(o, r, span, tc, h, l, exponent);
      }
      else
//PLUME::ENDIF
      {
        unit = spanAirlight(o, r, span, tc, h, l, exponent, weighted);
      }
    }
#endif
    airlight += min(KappaS * LightI0[l] * INV_2PI * unit, vec3(HUGE));
  }
  return airlight;
}

// The view ray through the centre of viewport pixel `pixel` (window depth
// `depth`): origin o, unit direction r, distance to the surface (inf: none).
//PLUME::IF MEDIA
// Translucent media (volumes, smoke sheets) drawn by the compositing pass
// into a layer of their own: premultiplied colour and opacity (Cv, av).
uniform sampler2D MediaLayer;
uniform sampler2D MediaDepth;      // the depth before the media (where the final one is nearer, a medium wrote it)
uniform int HasMediaDepth;
uniform sampler2D MediaTransmittance; // the media drawn over (1, 1, 1, 1): minus MediaLayer, their RGB transmittance
uniform int HasMediaTransmittance;
uniform int NumberOfMediaBoxes;
uniform vec3 MediaBoxMin[8];       // the media props' world bounds
uniform vec3 MediaBoxMax[8];
uniform int MediaBoxCentred[8];    // 1: a medium whose mass is at the middle of its bounds (smoke sheets)
uniform mat4 EyeToWorldPoint;

// Where the haze of the ray splits into "in front of the medium" and "behind
// it": on the ray's chord [a, b] through the media's bounds (clipped to
// [0, xs]), at the fraction f = 1/tau - (1 - av)/av, tau = -ln(1 - av), that
// is exact to first order for a medium of uniform extinction along the chord:
// the haze inside it, weighted by the medium's transmittance from a, is
// a + (1 - av)(1 - f) of it, and its emission's mean depth is there too.
// f -> 1/2 for a faint medium, -> 0 (the entry) for an opaque one. xs when the
// ray misses the bounds.
float mediaSplit(vec3 o, vec3 r, float xs, float av)
{
  vec3 ow = (EyeToWorldPoint * vec4(o, 1.0)).xyz;
  vec3 rw = mat3(EyeToWorldPoint) * r;
  vec3 inv = 1.0 / rw; // +-inf for an axis-parallel ray: the slab test still works
  float a = 1.0 / 0.0;
  float b = -1.0 / 0.0;
  bool centred = true;
  for (int k = 0; k < NumberOfMediaBoxes; ++k)
  {
    vec3 t0 = (MediaBoxMin[k] - ow) * inv;
    vec3 t1 = (MediaBoxMax[k] - ow) * inv;
    vec3 tn = min(t0, t1);
    vec3 tf = max(t0, t1);
    float enter = max(max(tn.x, tn.y), tn.z);
    float leave = min(min(tf.x, tf.y), tf.z);
    if (enter <= leave && leave > 0.0)
    {
      a = min(a, enter);
      b = max(b, leave);
      centred = centred && MediaBoxCentred[k] == 1;
    }
  }
  a = max(a, 0.0);
  b = min(b, xs);
  if (!(a < b) || isinf(b))
  {
    return a < xs ? a : xs;
  }
  // A sheet's bounds are its surface widened by its blur on every side: its
  // smoke is at the middle of the chord, whatever its opacity.
  float f = 0.5;
  if (centred)
  {
  }
  else if (av >= 1.0 - 1e-6)
  {
    f = 0.0;
  }
  else if (av > 1e-3)
  {
    f = clamp(-1.0 / log(1.0 - av) - (1.0 - av) / av, 0.0, 0.5);
  }
  return a + f * (b - a);
}
//PLUME::ENDIF

float viewRay(ivec2 pixel, float depth, out vec3 o, out vec3 r)
{
  vec2 ndc = (vec2(pixel) + 0.5) / ViewportSize * 2.0 - 1.0;
  vec4 pn = InverseProjection * vec4(ndc, -1.0, 1.0);
  vec4 pf = InverseProjection * vec4(ndc, 1.0, 1.0);
  vec3 nearPoint = pn.xyz / pn.w;
  vec3 farPoint = pf.xyz / pf.w;
  o = Perspective == 1 ? vec3(0.0) : nearPoint;
  r = normalize(farPoint - o);
  float xs = 1.0 / 0.0; // nothing drawn: the ray runs through the medium to infinity
  if (depth < 1.0)
  {
    vec4 ps = InverseProjection * vec4(ndc, 2.0 * depth - 1.0, 1.0);
    xs = length(ps.xyz / ps.w - o);
  }
  return xs;
}

#ifndef PLUME_FEATURE_LATTICE_FINE
// Level 0's nodes and cells passes draw into a folded target: the first
// LatticeFold.y rows at x < LatticeFold.x, the others beside them, so that
// llvmpipe's 64 x 64 tiles split the pass between its threads (a 64 x 64
// target is one tile). Texel t's node or cell (of `count`); a texel past
// the last (an odd count's folded half) is discarded.
uniform ivec2 LatticeFold;
ivec2 unfold(ivec2 t, ivec2 count)
{
  ivec2 u = t.x < LatticeFold.x ? t : ivec2(t.x - LatticeFold.x, t.y + LatticeFold.y);
  if (any(greaterThanEqual(u, count)))
  {
    discard;
  }
  return u;
}
#endif

// The lattice's node (i, j) is the ray through this pixel.
ivec2 nodePixel(ivec2 node)
{
  return min(node * Lattice, ivec2(ViewportSize) - 1);
}

// Node n's airlight. Level 0 stores its nodes in order. A finer level
// (spacing halved) evaluates only the nodes of its parent's refined cells
// that are not the parent's own nodes, packed densely 64 a row as the CPU
// listed them (llvmpipe shades 4 x 4 blocks: a block per parent cell would
// run 16 lanes for its 5 new nodes); its nodes with both indices even are
// the parent's.
vec3 nodeAirlight(ivec2 n)
{
#ifdef PLUME_FEATURE_LATTICE_FINE
  if (all(equal(n % 2, ivec2(0))))
  {
    return texelFetch(LatticeCoarseNodes, n / 2, 0).rgb;
  }
  int k = int(texelFetch(LatticeNodeMap, n, 0).r);
  return texelFetch(LatticeNodes, ivec2(k % 64, k / 64), 0).rgb;
#else
  return texelFetch(LatticeNodes, n, 0).rgb;
#endif
}

// Viewport pixel `pixel`'s lattice coordinate: its cell plus the fraction
// across it, in node units. It is pixel / D in every cell but the last of a
// row or column, which is narrower (its far node is the viewport's last
// pixel) and so steeper: the larger of the two lines.
vec2 latticeCoordinate(ivec2 pixel)
{
  vec2 p = vec2(pixel);
  return max(p * LatticeInverse, p * LatticeLastSlope + LatticeLastOffset);
}

// The cell at lattice coordinate u (the last cell of a row or column also
// holds the viewport's last pixel, at u = cells).
ivec2 cellOf(vec2 u)
{
  return min(ivec2(u), LatticeCellCount - 1);
}

// The nodes' airlight at lattice coordinate u, bilinear between its cell's
// four nodes: level 0 one filtered fetch (the texture unit's float weights).
vec3 interpolatedAirlight(vec2 u)
{
#ifdef PLUME_FEATURE_LATTICE_FINE
  ivec2 c = cellOf(u);
  vec2 f = u - vec2(c);
  vec3 a = mix(nodeAirlight(c), nodeAirlight(c + ivec2(1, 0)), f.x);
  vec3 b = mix(nodeAirlight(c + ivec2(0, 1)), nodeAirlight(c + 1), f.x);
  return mix(a, b, f.y);
#else
  return textureLod(LatticeNodes, (u + 0.5) * LatticeInverseNodes, 0.0).rgb;
#endif
}

//PLUME::IF LATTICE_CLASSIFY
// |second difference| of the nodes' airlight along `axis` at node n, centred
// one node inwards at the border of the nodes [lo, hi] it may use (the nodes
// n - axis, n, n + axis).
vec3 secondDifference(ivec2 n, ivec2 axis, ivec2 lo, ivec2 hi)
{
  int i = axis.x == 1 ? n.x : n.y;
  ivec2 range = axis.x == 1 ? ivec2(lo.x, hi.x) : ivec2(lo.y, hi.y);
  ivec2 c = n + axis * (clamp(i, range.x + 1, range.y - 1) - i);
  vec3 a = nodeAirlight(c - axis);
  vec3 b = nodeAirlight(c);
  vec3 d = nodeAirlight(c + axis);
  return abs(a - 2.0 * b + d);
}

// The eye-space z of the point at pixel `pixel` and window depth `depth`.
float eyeZ(ivec2 pixel, float depth)
{
  vec2 ndc = (vec2(pixel) + 0.5) / ViewportSize * 2.0 - 1.0;
  vec4 p = InverseProjection * vec4(ndc, 2.0 * depth - 1.0, 1.0);
  return p.z / p.w;
}

// 1 if cell `cell` must be refined (every pixel evaluated exactly), else 0.
// Bilinear interpolation errs by about (|f_xx| + |f_yy|) D^2 / 8 inside the
// cell; the nodes' second differences estimate f_xx D^2 and f_yy D^2 at its
// corners. The cell is interpolated only if that estimate is within
// LatticeTolerance in every channel at all four corners, no light projects
// into the cell or its neighbours (the glow's peak falls between nodes), and
// every pixel lies on the surface its corners predict: all without a surface,
// or all on one whose window depth, bilinear between the corners (exact for a
// plane: window depth is affine in the window's x and y), gives its eye depth
// within LatticeDepthTolerance (silhouettes, objects smaller than a cell).
float classifyCell(ivec2 cell)
{
  ivec2 p0 = nodePixel(cell);
  ivec2 p1 = nodePixel(cell + 1);
  for (int l = 0; l < NumberOfLights; ++l)
  {
    vec2 q = LightPixel[l].xy;
    if (LightPixel[l].z > 0.0 && all(greaterThan(q, vec2(p0 - Lattice))) && all(lessThan(q, vec2(p1 + Lattice))))
    {
      return 1.0;
    }
    // A narrow spot's shaft can pass between the nodes: the cells along its
    // axis's image (within 1.5 cells of the cell's centre) are refined.
    vec2 a = LightShaft[l].xy;
    vec2 ab = LightShaft[l].zw - a;
    vec2 centre = 0.5 * vec2(p0 + p1);
    float t = clamp(dot(centre - a, ab) / max(dot(ab, ab), 1e-12), 0.0, 1.0);
    if (length(centre - a - t * ab) <= 1.5 * float(Lattice))
    {
      return 1.0;
    }
  }
  // The nodes the second differences may use: the whole lattice, or on a
  // finer level its parent cell's (the only ones evaluated: 3 x 3, the
  // differences centred on its middle row and column).
  ivec2 lo = ivec2(0), hi = LatticeCellCount;
#ifdef PLUME_FEATURE_LATTICE_FINE
  lo = cell / LatticeParentBlock * LatticeParentBlock;
  hi = min(lo + LatticeParentBlock, LatticeCellCount);
  if (any(lessThan(hi - lo, ivec2(2))))
  {
    return 1.0; // a parent one cell wide (the viewport's edge): no second difference
  }
#endif
  vec3 e = vec3(0.0);
  for (int k = 0; k < 4; ++k)
  {
    ivec2 n = cell + ivec2(k & 1, k >> 1);
    e = max(e, secondDifference(n, ivec2(1, 0), lo, hi) + secondDifference(n, ivec2(0, 1), lo, hi));
  }
  if (any(greaterThan(e, vec3(8.0 * LatticeTolerance))))
  {
    return 1.0;
  }
  vec4 z = vec4(texelFetch(SceneDepth, p0, 0).r, texelFetch(SceneDepth, ivec2(p1.x, p0.y), 0).r,
    texelFetch(SceneDepth, ivec2(p0.x, p1.y), 0).r, texelFetch(SceneDepth, p1, 0).r);
  bvec4 none = greaterThanEqual(z, vec4(1.0));
  if (any(none) && !all(none))
  {
    return 1.0;
  }
  // the cell's pixels (the last cell of a row or column: up to the viewport's edge)
  ivec2 end = ivec2(cell.x == LatticeCellCount.x - 1 ? int(ViewportSize.x) : p1.x,
    cell.y == LatticeCellCount.y - 1 ? int(ViewportSize.y) : p1.y);
  vec2 invSize = 1.0 / vec2(p1 - p0);
  // A crease (two surfaces meeting, the depth continuous: a room's corner)
  // hides nothing between the nodes, and the second differences above bound
  // its kink: where the corners' eye depths are within CREASE_SPREAD of each
  // other, a pixel may also lie within their range instead of on the
  // corners' plane. Anything in front of or behind the corners (a small
  // object, a hole, a convex edge) is still refined.
  vec4 zc = -vec4(eyeZ(p0, z.x), eyeZ(ivec2(p1.x, p0.y), z.y), eyeZ(ivec2(p0.x, p1.y), z.z), eyeZ(p1, z.w));
  float zlo = min(min(zc.x, zc.y), min(zc.z, zc.w));
  float zhi = max(max(zc.x, zc.y), max(zc.z, zc.w));
  const float CREASE_SPREAD = 0.05;
  bool crease = zhi <= (1.0 + CREASE_SPREAD) * zlo;
  zlo *= 1.0 - LatticeDepthTolerance;
  zhi *= 1.0 + LatticeDepthTolerance;
  // At a pixel, eye z is (a + b zn) / (c + e zn) of zn = 2 depth - 1 (the
  // inverse projection's z and w rows; a and c depend on the pixel): the
  // mismatch |z' - z| > tolerance |z| is compared multiplied out (z itself,
  // one division, only for the crease's range): no unprojection per pixel.
  vec4 rowZ = vec4(InverseProjection[0].z, InverseProjection[1].z, InverseProjection[2].z, InverseProjection[3].z);
  vec4 rowW = vec4(InverseProjection[0].w, InverseProjection[1].w, InverseProjection[2].w, InverseProjection[3].w);
  vec2 ndcScale = 2.0 / ViewportSize;
  for (int j = p0.y; j < end.y; ++j)
  {
    for (int i = p0.x; i < end.x; ++i)
    {
      ivec2 p = ivec2(i, j);
      float d = texelFetch(SceneDepth, p, 0).r;
//PLUME::IF MEDIA
      // a translucent medium splits the ray: the nodes' airlight is of the whole ray
      vec4 layer = texelFetch(MediaLayer, p, 0);
      if (any(greaterThan(layer, vec4(0.0))))
      {
        return 1.0;
      }
//PLUME::ENDIF
      if (none.x)
      {
        if (d < 1.0)
        {
          return 1.0;
        }
        continue;
      }
      vec2 f = vec2(p - p0) * invSize;
      float predicted = mix(mix(z.x, z.y, f.x), mix(z.z, z.w, f.x), f.y);
      vec2 ndc = (vec2(p) + 0.5) * ndcScale - 1.0;
      float a = dot(rowZ.xy, ndc) + rowZ.w;
      float c = dot(rowW.xy, ndc) + rowW.w;
      float zn = 2.0 * d - 1.0, zp = 2.0 * predicted - 1.0;
      float num = a + rowZ.z * zn, den = c + rowW.z * zn;
      float numP = a + rowZ.z * zp, denP = c + rowW.z * zp;
      float ze = num / den;
      bool inRange = crease && -ze >= zlo && -ze <= zhi;
      if (d >= 1.0 || (!inRange && abs(numP * den - num * denP) > LatticeDepthTolerance * abs(num * denP)))
      {
        return 1.0;
      }
    }
  }
  return 0.0;
}
//PLUME::ENDIF

void main()
{
  // (The quad's texCoord is not needed, pixels come from gl_FragCoord; this
  // keeps the attribute alive so the quad helper can bind it.)
  if (texCoord.x < -1.0)
  {
    discard;
  }
  vec3 o, r;
#ifdef PLUME_FEATURE_LATTICE_NODES
  // One lattice node per fragment of the nodes' target: the airlight of its
  // ray over the whole ray (cells with a translucent medium are refined).
  ivec2 t = ivec2(gl_FragCoord.xy);
#ifdef PLUME_FEATURE_LATTICE_FINE
  ivec2 node = nodePixel(ivec2(texelFetch(LatticeNodeList, t, 0).rg));
#else
  t = unfold(t, LatticeCellCount + 1);
  ivec2 node = nodePixel(t);
#endif
  float xsNode = viewRay(node, texelFetch(SceneDepth, node, 0).r, o, r);
  gl_FragDepth = 1.0;
  gl_FragData[0] = vec4(airlightOf(o, r, xsNode), 1.0);
  return;
#endif
//PLUME::IF LATTICE_CLASSIFY
  gl_FragDepth = 1.0;
#ifdef PLUME_FEATURE_LATTICE_FINE
  gl_FragData[0] = vec4(classifyCell(ivec2(gl_FragCoord.xy)), 0.0, 0.0, 1.0);
#else
  gl_FragData[0] = vec4(classifyCell(unfold(ivec2(gl_FragCoord.xy), LatticeCellCount)), 0.0, 0.0, 1.0);
#endif
  return;
//PLUME::ENDIF
  ivec2 pixel = ivec2(gl_FragCoord.xy - ViewportOrigin);
#ifdef PLUME_FEATURE_LATTICE_INTERPOLATE
  // A finer level, drawn over its parent's refined cells: its interpolated
  // cells' airlight, added to what LATTICE_RESOLVE wrote (no airlight there);
  // its refined cells get theirs from LATTICE_REFINE. (No medium: cells with
  // one are refined at every level.)
  vec2 u = latticeCoordinate(pixel);
  if (texelFetch(LatticeCells, cellOf(u), 0).r != 0.0)
  {
    discard;
  }
  gl_FragDepth = 1.0;
  gl_FragData[0] = vec4(interpolatedAirlight(u), 0.0);
  return;
#endif
  vec4 color = texelFetch(SceneColor, pixel, 0);
  float depth = texelFetch(SceneDepth, pixel, 0).r;
  gl_FragDepth = depth;
  float xs = viewRay(pixel, depth, o, r);

  vec3 transmittance = isinf(xs) ? vec3(0.0) : exp(-KappaT * xs);
  // A channel with kt = 0 keeps its colour even at infinity.
  transmittance = mix(transmittance, vec3(1.0), vec3(equal(KappaT, vec3(0.0))));
  vec3 airlight = vec3(0.0);
#ifdef PLUME_FEATURE_LATTICE_RESOLVE
  // Interpolated cells take the nodes' airlight; refined cells none here
  // (LATTICE_REFINE adds theirs). Classification refines every cell with a
  // translucent medium, so an interpolated pixel's ray is whole.
  vec2 u = latticeCoordinate(pixel);
  bool interpolated = texelFetch(LatticeCells, cellOf(u), 0).r == 0.0;
  if (interpolated)
  {
    airlight = interpolatedAirlight(u);
  }
#endif
  // A translucent medium at the pixel: the haze splits at xv (mediaSplit)
  // into the part in front of it (added) and behind it (dimmed by 1 - av).
  float xv = xs;
  vec4 layer = vec4(0.0);
  vec3 tv = vec3(1.0); // the media's transmittance
//PLUME::IF MEDIA
  layer = texelFetch(MediaLayer, pixel, 0);
  tv = HasMediaTransmittance == 1 ? clamp(texelFetch(MediaTransmittance, pixel, 0).rgb - layer.rgb, 0.0, 1.0)
                                  : vec3(1.0 - clamp(layer.a, 0.0, 1.0));
  if (any(lessThan(tv, vec3(1.0))) || any(greaterThan(layer.rgb, vec3(0.0))))
  {
    // A medium that wrote depth (an opaque isosurface) is a surface: all the
    // haze up to it in front. (Compared as distances, 0.1 % apart: the depth
    // before the media may have been copied at another precision.)
    vec3 o2, r2;
    bool wroteDepth = HasMediaDepth == 1 && xs < 0.999 * viewRay(pixel, texelFetch(MediaDepth, pixel, 0).r, o2, r2);
    xv = wroteDepth ? xs : mediaSplit(o, r, xs, 1.0 - (tv.r + tv.g + tv.b) / 3.0);
  }
//PLUME::ENDIF
#ifndef PLUME_FEATURE_NO_LIGHTS
  airlight = airlightOf(o, r, xv);
#endif
  vec3 mediumTransmittance = mix(exp(-KappaT * xv), vec3(1.0), vec3(equal(KappaT, vec3(0.0))));
  vec3 behind = vec3(0.0);
#ifndef PLUME_FEATURE_NO_LIGHTS
  // llvmpipe runs both sides of a divergent `if` for every pixel of a SIMD
  // block (masked); a loop whose trip count is 0 in every lane is skipped.
  for (int k = xv < xs ? 0 : 1; k < 1; ++k)
  {
    // the ray from xv on, seen through the haze in front of xv
    behind = mediumTransmittance * airlightOf(o + xv * r, r, xs - xv);
  }
#endif
  // The surface as the window would show it without the medium (the float
  // target keeps values above 1 that an 8-bit window clamps), then attenuated;
  // the translucent media's layer over it, attenuated up to xv.
  vec3 far = behind + clamp(color.rgb, 0.0, 1.0) * transmittance;
  vec3 result = airlight + clamp(layer.rgb, 0.0, 1.0) * mediumTransmittance + tv * far;
  airlight += tv * behind;
#ifdef PLUME_FEATURE_LATTICE_REFINE
  // a refined cell: its exact airlight, added to what LATTICE_RESOLVE wrote
  gl_FragData[0] = vec4(airlight, 0.0);
  return;
#endif
  gl_FragData[0] = AirlightOnly == 1 ? vec4(airlight, 0.0) : vec4(result, 1.0);
//PLUME::IF SHADOW
  if (ShadowRunStatistics == 1)
  {
    gl_FragData[0] = vec4(RunsDecided, RunsTotal, 0.0, 1.0);
  }
//PLUME::ENDIF
}
