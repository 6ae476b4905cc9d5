//VTK::System::Dec

// vtkPlumeSheetMapper fragment shader: the optical depth of one triangle's
// smoothed density along this pixel's view ray, added (blend ONE, ONE) into a
// float accumulation target; the composite pass turns the sum into
// transmittance exp(-tau). Addition commutes, so triangles need no sorting.
//
// Model: density(x) = integral over the triangle of d(p) G(x - p) dA(p), G an
// anisotropic Gaussian (sigma_b in the triangle plane, sigma_t across it,
// normalised to 1). tau = integral of density along the ray. For a source
// point p the line integral of G along the ray o + v t (|v| = 1) in triangle
// space (x, y in plane, z normal), with w = o - p, is (derivation in
// Documentation/Renderers.md):
//   D  = st^2 (vx^2 + vy^2) + sb^2 vz^2
//   m2 = (sb^2 [(wy vz - wz vy)^2 + (wz vx - wx vz)^2] + st^2 (wx vy - wy vx)^2) / (sb^2 D)
//   L  = exp(-m2 / 2) / (2 pi sb sqrt(D))          (whole line)
// times 0.5 [erf(k (t1 - t*)) - erf(k (t0 - t*))] for the bounded ray t in [t0, t1],
//   t* = -(st^2 (wx vx + wy vy) + sb^2 wz vz) / D,  k = sqrt(D) / (sqrt(2) sb st).
// None of it divides by st, so st = 0 is the exact thin-sheet limit.
// tau = sum over samples of d(p) L(p) times the cell area a (the printed
// Eq. 18 divides by a; a quadrature weight multiplies).
//
// Quadrature variants: GRID (seed 000: PLUME_GRID_A x PLUME_GRID_B cells over
// the footprint-aligned region, sampled twice with random offsets) or
// ANALYTIC (default: the across-footprint integral in closed form, Gauss-
// Legendre along the footprint between break points, see AcrossIntegral).
// Variants: BOUNDED (integrate from the near plane to the opaque depth in
// OpaqueDepth) or UNBOUNDED (whole line, as in the paper); PLUME_GRID_A x
// PLUME_GRID_B cells, sampled twice with per-fragment random offsets.

//PLUME::Defines

flat in vec3 triOrigin;
flat in vec3 triAxisI;
flat in vec3 triAxisU;
flat in vec3 triNormal;
flat in vec3 triCorners;
flat in vec3 triD0;
flat in vec3 triD1;
flat in vec3 triD2;
flat in vec3 triSigmaB;
flat in vec3 triSigmaT;

uniform mat4 InverseProjection; // clip -> eye
uniform vec2 ViewportSize;
uniform float Cutoff;
//PLUME::IF BOUNDED
uniform sampler2D OpaqueDepth; // window depth of the opaque scene, viewport-sized
//PLUME::ENDIF

//VTK::Output::Dec

const float PI = 3.14159265358979;
const float BIG = 1e30;

vec3 Unproject(vec2 ndc, float z)
{
  vec4 p = InverseProjection * vec4(ndc, z, 1.0);
  return p.xyz / p.w;
}

// Abramowitz & Stegun 7.1.26, |error| < 1.5e-7
float Erf(float x)
{
  float ax = min(abs(x), 10.0);
  float t = 1.0 / (1.0 + 0.3275911 * ax);
  float y = 1.0 -
    (((((1.061405429 * t - 1.453152027) * t) + 1.421413741) * t - 0.284496736) * t + 0.254829592) *
      t * exp(-ax * ax);
  return x < 0.0 ? -y : y;
}

uint Hash(uint x)
{
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

vec2 Random2(uint seed)
{
  uint a = Hash(seed);
  uint b = Hash(a ^ 0x9e3779b9u);
  return vec2(float(a >> 8), float(b >> 8)) * (1.0 / 16777216.0);
}

//PLUME::IF ANALYTIC
// Gauss-Legendre nodes and weights on [-1, 1] (PLUME_GRID_A of them, from the Defines)
const float GLX[PLUME_GRID_A] = float[PLUME_GRID_A](PLUME_GL_NODES);
const float GLW[PLUME_GRID_A] = float[PLUME_GRID_A](PLUME_GL_WEIGHTS);

// the ray and the triangle in the footprint frame, set by main()
vec3 Ot;
vec3 Vt;
float El;
vec2 Eh;
vec2 Ep;
vec2 Q;
vec3 CA;
vec3 CB;
float TStart;
float TEnd;

// Gauss-Legendre nodes across the footprint (PLUME_GRID_B), for triangles whose sigmas vary
const float GLBX[PLUME_GRID_B] = float[PLUME_GRID_B](PLUME_GLB_NODES);
const float GLBW[PLUME_GRID_B] = float[PLUME_GRID_B](PLUME_GLB_WEIGHTS);
//PLUME::IF SIGMA_VARIES
bool SigmaVaries; // sigma_b or sigma_t differ between the triangle's corners
//PLUME::ENDIF
//PLUME::IF SIGMA_CONSTANT
// every corner has the same sigmas (no blur/thickness array, the pixel floor
// not reached): the varying-sigma branches compile away, and what depends
// only on the sigmas is computed once per fragment (main) instead of in each
// of the 8 x pieces calls of AcrossIntegral
const bool SigmaVaries = false;
float SB;       // sigma_b
float SB2;      // sigma_b^2
float InvD;     // 1 / D
float CutD;     // 2 Cutoff^2 D: beyond it u^2 / D passes the cutoff
float NormL;    // 1 / (2 pi sb sqrt(D))
float KT;       // k = sqrt(D) / (sqrt(2) sb st) (st > 0)
float TcA;      // tc(a) = TcA a + Tc0
float Tc0;
float InvS2;    // 1 / (sqrt(2) sb)
float HalfInvSB2; // 0.5 / sb^2
vec3 DQ;        // the density at footprint point (a, b): DQ + a DA + b DB
vec3 DA;
vec3 DB;
//PLUME::ENDIF
vec3 EdgeSlope; // along each edge k -> k + 1: d b / d a (0 where the edge is across a)

// The line integral of the Gaussian of a source point at footprint
// coordinates (a, b) with sigmas sb, st (bounded ray: times the fraction of
// the 1D Gaussian in t inside [TStart, TEnd]); see the header.
float LineFactor(float a, float b, float sb, float st)
{
  float sb2 = sb * sb;
  float D = max(st * st * El * El + sb2 * Vt.z * Vt.z, 1e-30 * sb2);
  float u = Ot.z * El + a * Vt.z;
  float m2 = b * b / sb2 + u * u / D;
  if (m2 > 80.0)
  {
    return 0.0; // exp(-40): nothing
  }
  float sqrtD = sqrt(D);
  float tc = (st * st * a * El - sb2 * Ot.z * Vt.z) / D;
  float frac;
  if (st > 0.0)
  {
    float k = sqrtD / (1.41421356 * sb * st);
    float lo = k * (TStart - tc);
    float hi = k * (TEnd - tc);
    frac = (lo < -4.5 && hi > 4.5) ? 1.0 : 0.5 * (Erf(hi) - Erf(lo));
  }
  else
  {
    frac = (tc >= TStart && tc <= TEnd) ? 1.0 : 0.0;
  }
  return exp(-0.5 * m2) / (2.0 * PI * sb * sqrtD) * frac;
}

// barycentric coordinates of the footprint point (a, b)
vec3 Barycentric(float a, float b)
{
  vec2 p = Q + a * Eh + b * Ep;
  float l2 = p.y / triCorners.z;
  float l1 = (p.x - l2 * triCorners.y) / triCorners.x;
  return vec3(1.0 - l1 - l2, l1, l2);
}

// the change of the barycentric coordinates per unit step along `dir`
vec3 BarycentricSlope(vec2 dir)
{
  float l2 = dir.y / triCorners.z;
  float l1 = (dir.x - l2 * triCorners.y) / triCorners.x;
  return vec3(-l1 - l2, l1, l2);
}

// the triangle's chord at footprint coordinate a: [bLo, bHi] (empty: bHi <= bLo)
vec2 Chord(float a)
{
  float bLo = BIG;
  float bHi = -BIG;
  for (int k = 0; k < 3; ++k)
  {
    int k2 = k == 2 ? 0 : k + 1;
    float aA = CA[k];
    float aB = CA[k2];
    if ((a - aA) * (a - aB) <= 0.0 && aA != aB)
    {
      float bb = CB[k] + (a - aA) * EdgeSlope[k];
      bLo = min(bLo, bb);
      bHi = max(bHi, bb);
    }
  }
  return vec2(bLo, bHi);
}

// In the footprint frame (eh, ep, n) the ray direction is (el, 0, vz) and
// w = o - p = (-a, -b, oz), so m2 = b^2/sb^2 + (oz el + a vz)^2 / D: across
// the footprint (b) the integrand is a Gaussian times the linear density,
// integrated in closed form over the triangle's chord at a (erf and exp
// terms) with sigma_b, sigma_t frozen at the chord point nearest the
// footprint. Where the sigmas vary over the triangle, the frozen-sigma
// integrand is a control variate: Gauss-Legendre (PLUME_GRID_B nodes on each
// side of that point, within Cutoff x the chord's largest sigma_b) adds the
// integral of the exact integrand minus the frozen one, which vanishes at
// that point and stays small and smooth; freezing alone gave 6 % max errors
// with sigma_b 0.06..0.14 over one triangle. Returns the integral over b of
// d(a, b) L(a, b).
//PLUME::IF SIGMA_CONSTANT
// (the sigmas the same everywhere: nothing to freeze or correct, and the
// sigmas' terms come from main())
vec3 AcrossIntegral(float a)
{
  vec2 chord = Chord(a);
  float bLo = chord.x;
  float bHi = chord.y;
  if (!(bHi > bLo))
  {
    return vec3(0.0);
  }
  float u = Ot.z * El + a * Vt.z;
  if (u * u > CutD)
  {
    return vec3(0.0); // beyond the cutoff
  }
  float tc = TcA * a + Tc0;
  float frac;
  if (KT > 0.0)
  {
    float lo = KT * (TStart - tc);
    float hi = KT * (TEnd - tc);
    frac = (lo < -4.5 && hi > 4.5) ? 1.0 : 0.5 * (Erf(hi) - Erf(lo));
  }
  else
  {
    frac = (tc >= TStart && tc <= TEnd) ? 1.0 : 0.0;
  }
  if (!(frac > 0.0))
  {
    return vec3(0.0);
  }
  // G0 = int exp(-b^2/(2 sb^2)) db, G1 = int b exp(...) db over [bLo, bHi];
  // the density is linear along the chord with slope DB
  float G0 = SB * 1.25331414 * (Erf(bHi * InvS2) - Erf(bLo * InvS2));
  float G1 = SB2 * (exp(-HalfInvSB2 * bLo * bLo) - exp(-HalfInvSB2 * bHi * bHi));
  vec3 dLo = DQ + a * DA + bLo * DB;
  vec3 across = max(dLo * G0 + DB * (G1 - bLo * G0), vec3(0.0));
  float L = min(exp(-0.5 * u * u * InvD) * NormL * frac, 1e30);
  return min(across * L, vec3(1e30));
}
//PLUME::ENDIF
//PLUME::IF SIGMA_VARIES
vec3 AcrossIntegral(float a)
{
  vec2 chord = Chord(a);
  float bLo = chord.x;
  float bHi = chord.y;
  if (!(bHi > bLo))
  {
    return vec3(0.0);
  }
  float bm = clamp(0.0, bLo, bHi);
  vec3 lm = clamp(Barycentric(a, bm), 0.0, 1.0);
  float sb = dot(lm, triSigmaB);
  float st = dot(lm, triSigmaT);
  vec3 lLo = Barycentric(a, bLo);
  vec3 lHi = Barycentric(a, bHi);
  float sb2 = sb * sb;
  float D = max(st * st * El * El + sb2 * Vt.z * Vt.z, 1e-30 * sb2);
  float u = Ot.z * El + a * Vt.z;
  float ma = u * u / D;
  // beyond the cutoff at the chord's largest sigmas (the smallest m2 on it)
  float sbBig = sb;
  float stBig = st;
  if (SigmaVaries)
  {
    sbBig = max(sb, max(dot(clamp(lLo, 0.0, 1.0), triSigmaB), dot(clamp(lHi, 0.0, 1.0), triSigmaB)));
    stBig = max(st, max(dot(clamp(lLo, 0.0, 1.0), triSigmaT), dot(clamp(lHi, 0.0, 1.0), triSigmaT)));
  }
  float DBig = max(stBig * stBig * El * El + sbBig * sbBig * Vt.z * Vt.z, 1e-30 * sb2);
  if (u * u / DBig > 2.0 * Cutoff * Cutoff)
  {
    return vec3(0.0);
  }
  float sqrtD = sqrt(D);
  float tc = (st * st * a * El - sb2 * Ot.z * Vt.z) / D;
  float frac;
  if (st > 0.0)
  {
    float k = sqrtD / (1.41421356 * sb * st);
    float lo = k * (TStart - tc);
    float hi = k * (TEnd - tc);
    frac = (lo < -4.5 && hi > 4.5) ? 1.0 : 0.5 * (Erf(hi) - Erf(lo));
  }
  else
  {
    frac = (tc >= TStart && tc <= TEnd) ? 1.0 : 0.0;
  }
  if (!(frac > 0.0) && !SigmaVaries)
  {
    return vec3(0.0);
  }
  vec3 dLo = lLo.x * triD0 + lLo.y * triD1 + lLo.z * triD2;
  vec3 dHi = lHi.x * triD0 + lHi.y * triD1 + lHi.z * triD2;
  // G0 = int exp(-b^2/(2 sb^2)) db, G1 = int b exp(...) db over [bLo, bHi]
  float s2 = 1.41421356 * sb;
  float G0 = sb * 1.25331414 * (Erf(bHi / s2) - Erf(bLo / s2));
  float G1 = sb2 * (exp(-0.5 * bLo * bLo / sb2) - exp(-0.5 * bHi * bHi / sb2));
  vec3 slope = (dHi - dLo) / (bHi - bLo);
  vec3 across = max(dLo * G0 + slope * (G1 - bLo * G0), vec3(0.0));
  float L = min(exp(-0.5 * ma) / (2.0 * PI * sb * sqrtD) * frac, 1e30);
  vec3 result = across * L;
  if (SigmaVaries)
  {
    // + int d(b) [L(b; sigma(b)) - L(b; sigma at bm)] db, on each side of bm
    // pieces graded from bm: 2, 4, 8, ... x sb (its scale there: the
    // difference varies on it near bm, on the larger sigmas farther out)
    float reach = Cutoff * sbBig;
    vec3 corr = vec3(0.0);
    for (int side = 0; side < 2; ++side)
    {
      float dir = side == 0 ? -1.0 : 1.0;
      float end = side == 0 ? max(bLo, bm - reach) : min(bHi, bm + reach);
      float len = abs(end - bm);
      float from = 0.0;
      float step = 2.0 * sb;
      for (int piece = 0; piece < 8 && from < len; ++piece)
      {
        float to = (piece == 7 || from + step >= 0.75 * len) ? len : from + step;
        float hw = 0.5 * (to - from);
        float mid = bm + dir * 0.5 * (to + from);
        vec3 part = vec3(0.0);
        for (int j = 0; j < PLUME_GRID_B; ++j)
        {
          float b = mid + hw * GLBX[j];
          vec3 l = clamp(Barycentric(a, b), 0.0, 1.0);
          vec3 d = l.x * triD0 + l.y * triD1 + l.z * triD2;
          float exact = LineFactor(a, b, dot(l, triSigmaB), dot(l, triSigmaT));
          float frozen = exp(-0.5 * b * b / sb2) * L;
          part += GLBW[j] * d * (exact - frozen);
        }
        corr += hw * part;
        from = to;
        step *= 2.0;
      }
    }
    result = max(result + corr, vec3(0.0));
  }
  return min(result, vec3(1e30));
}
//PLUME::ENDIF
//PLUME::ENDIF
//PLUME::IF GRID ADAPTIVE
// d(p) times the line integral of the Gaussian at p (triangle space point p,
// barycentric coordinates l) along the ray ot + t vt, t in [tStart, tEnd]:
// the general formula of the header, shared by the grid quadrature and the
// adaptive small-triangle rule
vec3 PointIntegral(vec2 p, vec3 l, vec3 ot, vec3 vt, float tStart, float tEnd)
{
  vec3 d = l.x * triD0 + l.y * triD1 + l.z * triD2;
  float sb = dot(l, triSigmaB);
  float st = dot(l, triSigmaT);
  vec3 w = vec3(ot.xy - p, ot.z);
  float sb2 = sb * sb;
  float st2 = st * st;
  float D = max(st2 * dot(vt.xy, vt.xy) + sb2 * vt.z * vt.z, 1e-30 * sb2);
  float cx = w.y * vt.z - w.z * vt.y;
  float cy = w.z * vt.x - w.x * vt.z;
  float cz = w.x * vt.y - w.y * vt.x;
  float m2 = (sb2 * (cx * cx + cy * cy) + st2 * cz * cz) / (sb2 * D);
  if (m2 > 2.0 * Cutoff * Cutoff)
  {
    return vec3(0.0); // beyond the cutoff (and keeps exp() away from underflow noise)
  }
  float sqrtD = sqrt(D);
  float L = exp(-0.5 * m2) / (2.0 * PI * sb * sqrtD);
  // bounded ray: the fraction of the 1D Gaussian in t that lies in [tStart, tEnd]
  float tc = -(st2 * dot(w.xy, vt.xy) + sb2 * w.z * vt.z) / D;
  float frac;
  if (st > 0.0)
  {
    float k = sqrtD / (1.41421356 * sb * st);
    float lo = k * (tStart - tc);
    float hi = k * (tEnd - tc);
    frac = (lo < -4.5 && hi > 4.5) ? 1.0 : 0.5 * (Erf(hi) - Erf(lo));
  }
  else
  {
    frac = (tc >= tStart && tc <= tEnd) ? 1.0 : 0.0;
  }
  return d * min(L * frac, 1e30);
}
//PLUME::ENDIF

void main()
{
  vec2 ndc = gl_FragCoord.xy / ViewportSize * 2.0 - 1.0;
  vec3 o = Unproject(ndc, -1.0); // the ray starts on the near plane
  vec3 v = normalize(Unproject(ndc, 1.0) - o);
//PLUME::IF BOUNDED
  float tStart = 0.0;
  float tEnd = BIG;
  float depth = texelFetch(OpaqueDepth, ivec2(gl_FragCoord.xy), 0).r;
  if (depth < 1.0)
  {
    tEnd = max(dot(Unproject(ndc, 2.0 * depth - 1.0) - o, v), 0.0);
  }
//PLUME::ENDIF
//PLUME::IF UNBOUNDED
  float tStart = -BIG;
  float tEnd = BIG;
//PLUME::ENDIF

  // the ray in triangle space
  vec3 rel = o - triOrigin;
  vec3 ot = vec3(dot(rel, triAxisI), dot(rel, triAxisU), dot(rel, triNormal));
  vec3 vt = vec3(dot(v, triAxisI), dot(v, triAxisU), dot(v, triNormal));

  float sbMax = max(triSigmaB.x, max(triSigmaB.y, triSigmaB.z));
  float stMax = max(triSigmaT.x, max(triSigmaT.y, triSigmaT.z));
  float reachB = Cutoff * sbMax;
  float reachT = Cutoff * stMax;

  // the part of the ray within reachT of the plane (Eq. 17), clipped to [tStart, tEnd]
  float t0 = -BIG;
  float t1 = BIG;
  if (abs(vt.z) > 1e-7)
  {
    float ta = (-ot.z - reachT) / vt.z;
    float tb = (-ot.z + reachT) / vt.z;
    t0 = min(ta, tb);
    t1 = max(ta, tb);
  }
  else if (abs(ot.z) > reachT)
  {
    discard; // parallel to the plane and outside its slab
  }
  t0 = max(t0, tStart);
  t1 = min(t1, tEnd);
  if (t0 > t1)
  {
    discard;
  }

  // sampling region aligned with the ray's footprint in the plane:
  // coordinates (a, b) along / across it, origin at the footprint of t = 0
  vec2 e = vt.xy;
  float el = length(e);
  vec2 eh = el > 1e-6 ? e / el : vec2(1.0, 0.0);
  vec2 ep = vec2(-eh.y, eh.x);
  vec2 q = ot.xy;
  vec2 c0 = -q;
  vec2 c1 = vec2(triCorners.x, 0.0) - q;
  vec2 c2 = triCorners.yz - q;
  vec3 ca = vec3(dot(c0, eh), dot(c1, eh), dot(c2, eh));
  vec3 cb = vec3(dot(c0, ep), dot(c1, ep), dot(c2, ep));
  float a0 = max(el * max(t0, -BIG) - reachB, min(ca.x, min(ca.y, ca.z)));
  float a1 = min(el * min(t1, BIG) + reachB, max(ca.x, max(ca.y, ca.z)));
  float b0 = max(-reachB, min(cb.x, min(cb.y, cb.z)));
  float b1 = min(reachB, max(cb.x, max(cb.y, cb.z)));
  if (!(a0 < a1) || !(b0 < b1))
  {
    discard;
  }
//PLUME::IF GRID
  float da = (a1 - a0) / float(PLUME_GRID_A);
  float db = (b1 - b0) / float(PLUME_GRID_B);

  // barycentric coordinates of p' = q + a eh + b ep from p1' = 0, p2' = (cx, 0), p3' = (cy, cz)
  float invCx = 1.0 / triCorners.x;
  float invCz = 1.0 / triCorners.z;

  uint seed = Hash(uint(gl_FragCoord.x) + 65536u * uint(gl_FragCoord.y)) ^ Hash(uint(gl_PrimitiveID) * 2654435761u);
  vec3 sum = vec3(0.0);
  for (int pass = 0; pass < 2; ++pass)
  {
    vec2 r = Random2(seed + uint(pass) * 0x68bc21ebu);
    for (int i = 0; i < PLUME_GRID_A; ++i)
    {
      float a = a0 + (float(i) + r.x) * da;
      for (int j = 0; j < PLUME_GRID_B; ++j)
      {
        float b = b0 + (float(j) + r.y) * db;
        vec2 p = q + a * eh + b * ep;
        float l2 = p.y * invCz;
        float l1 = (p.x - l2 * triCorners.y) * invCx;
        float l0 = 1.0 - l1 - l2;
        if (l0 < 0.0 || l1 < 0.0 || l2 < 0.0)
        {
          continue;
        }
        sum += PointIntegral(p, vec3(l0, l1, l2), ot, vt, tStart, tEnd);
      }
    }
  }
  vec3 tau = min(0.5 * da * db * sum, vec3(1e30));
//PLUME::ENDIF
//PLUME::IF ANALYTIC
  // The across-footprint integral is closed-form (AcrossIntegral); along the
  // footprint the integrand is smooth between the corners' a coordinates
  // (where the chord's ends change edge) and the a where the ray's
  // Gaussian centre crosses the ends of the ray: Gauss-Legendre with
  // PLUME_GRID_A nodes on each piece between those break points.
  Ot = ot;
  Vt = vt;
  El = el;
  Eh = eh;
  Ep = ep;
  Q = q;
  CA = ca;
  CB = cb;
  TStart = tStart;
  TEnd = tEnd;
//PLUME::IF SIGMA_VARIES
  SigmaVaries = any(notEqual(triSigmaB, triSigmaB.xxx)) || any(notEqual(triSigmaT, triSigmaT.xxx));
//PLUME::ENDIF
//PLUME::ENDIF
//PLUME::IF ADAPTIVE
  {
    // Adaptive sampling: over a triangle much smaller than sigma_b the
    // integrand is nearly linear (it varies on the scale sigma_b or slower),
    // so the degree-2 edge-midpoint rule with the closed-form line integral
    // replaces the pieces (3 evaluations instead of ~30).
    float diam = max(max(triCorners.x, length(triCorners.yz)),
      length(triCorners.yz - vec2(triCorners.x, 0.0)));
    float sbMin = min(triSigmaB.x, min(triSigmaB.y, triSigmaB.z));
    if (diam < PLUME_SMALL_TRIANGLE * sbMin)
    {
      vec2 p1 = vec2(triCorners.x, 0.0);
      vec2 p2 = triCorners.yz;
      vec3 acc = PointIntegral(0.5 * p1, vec3(0.5, 0.5, 0.0), ot, vt, tStart, tEnd) +
        PointIntegral(0.5 * (p1 + p2), vec3(0.0, 0.5, 0.5), ot, vt, tStart, tEnd) +
        PointIntegral(0.5 * p2, vec3(0.5, 0.0, 0.5), ot, vt, tStart, tEnd);
      float area = 0.5 * abs(triCorners.x * triCorners.z);
      gl_FragData[0] = vec4(min(acc * area / 3.0, vec3(1e30)), 0.0);
      return;
    }
  }
//PLUME::ENDIF
//PLUME::IF ANALYTIC
  // once per fragment, not in each of AcrossIntegral's 8 x pieces calls: the
  // edges' slopes and, with constant sigmas, every term of the sigmas alone
  for (int k = 0; k < 3; ++k)
  {
    int k2 = k == 2 ? 0 : k + 1;
    EdgeSlope[k] = ca[k2] != ca[k] ? (cb[k2] - cb[k]) / (ca[k2] - ca[k]) : 0.0;
  }
//PLUME::IF SIGMA_CONSTANT
  {
    SB = triSigmaB.x;
    float st = triSigmaT.x;
    SB2 = SB * SB;
    float D = max(st * st * el * el + SB2 * vt.z * vt.z, 1e-30 * SB2);
    float sqrtD = sqrt(D);
    InvD = 1.0 / D;
    CutD = 2.0 * Cutoff * Cutoff * D;
    NormL = 1.0 / (2.0 * PI * SB * sqrtD);
    KT = st > 0.0 ? sqrtD / (1.41421356 * SB * st) : 0.0;
    TcA = st * st * el / D;
    Tc0 = -SB2 * ot.z * vt.z / D;
    InvS2 = 1.0 / (1.41421356 * SB);
    HalfInvSB2 = 0.5 / SB2;
    // barycentric coordinates are linear in (a, b) (see Barycentric), so is
    // the density: its value at the footprint origin and its two slopes
    vec3 lq = Barycentric(0.0, 0.0);
    DQ = lq.x * triD0 + lq.y * triD1 + lq.z * triD2;
    vec3 la = BarycentricSlope(eh);
    DA = la.x * triD0 + la.y * triD1 + la.z * triD2;
    vec3 lb = BarycentricSlope(ep);
    DB = lb.x * triD0 + lb.y * triD1 + lb.z * triD2;
  }
//PLUME::ENDIF
  float cuts[23];
  int nc = 0;
  cuts[nc++] = a0;
  for (int k = 0; k < 3; ++k)
  {
    if (ca[k] > a0 && ca[k] < a1)
    {
      cuts[nc++] = ca[k];
    }
  }
  // Where an edge crosses the footprint line (b = 0) the chord's end sweeps
  // through the Gaussian's core: a steep (erf) step in a if the edge runs
  // across the footprint. Pieces of +-2 step widths around it keep it smooth.
  for (int k = 0; k < 3; ++k)
  {
    int k2 = k == 2 ? 0 : k + 1;
    float dA = ca[k2] - ca[k];
    float dB = cb[k2] - cb[k];
    if (cb[k] * cb[k2] < 0.0 && abs(dA) > 0.0)
    {
      float ax = ca[k] + cb[k] / (cb[k] - cb[k2]) * dA;
      float w = 2.0 * 1.41421356 * sbMax * abs(dA / dB);
      if (w < a1 - a0)
      {
        if (ax - w > a0 && ax - w < a1)
        {
          cuts[nc++] = ax - w;
        }
        if (ax + w > a0 && ax + w < a1)
        {
          cuts[nc++] = ax + w;
        }
      }
    }
  }
  if (stMax > 0.0 && el > 1e-6)
  {
    // tc(a) = (st^2 el a - sb^2 oz vz) / D at the largest sigmas
    float D = stMax * stMax * el * el + sbMax * sbMax * vt.z * vt.z;
    float base = sbMax * sbMax * ot.z * vt.z;
    float slope = stMax * stMax * el;
    float aEnd = (tEnd * D + base) / slope;
    float aStart = (tStart * D + base) / slope;
    if (aEnd > a0 && aEnd < a1)
    {
      cuts[nc++] = aEnd;
    }
    if (aStart > a0 && aStart < a1)
    {
      cuts[nc++] = aStart;
    }
  }
  if (SigmaVaries && abs(vt.z) > 1e-6)
  {
    // varying sigmas: the Gaussian's core along the footprint (centred where
    // the ray crosses the plane's footprint, u = 0) is as narrow as the
    // smallest sigmas make it while the pieces are sized by the largest:
    // cuts graded 1, 2, 4, ... x the narrowest width keep it resolved
    float sbMin = min(triSigmaB.x, min(triSigmaB.y, triSigmaB.z));
    float stMin = min(triSigmaT.x, min(triSigmaT.y, triSigmaT.z));
    float aC = -ot.z * el / vt.z;
    float wMin = sqrt(stMin * stMin * el * el + sbMin * sbMin * vt.z * vt.z) / abs(vt.z);
    float w = wMin;
    for (int k = 0; k < 6 && w < a1 - a0; ++k)
    {
      if (aC - w > a0 && aC - w < a1)
      {
        cuts[nc++] = aC - w;
      }
      if (aC + w > a0 && aC + w < a1)
      {
        cuts[nc++] = aC + w;
      }
      w *= 2.0;
    }
  }
  cuts[nc++] = a1;
  // insertion sort (at most 23 values)
  for (int i = 1; i < nc; ++i)
  {
    float x = cuts[i];
    int j = i - 1;
    while (j >= 0 && cuts[j] > x)
    {
      cuts[j + 1] = cuts[j];
      --j;
    }
    cuts[j + 1] = x;
  }
  vec3 tau = vec3(0.0);
  for (int s = 0; s + 1 < nc; ++s)
  {
    float halfLen = 0.5 * (cuts[s + 1] - cuts[s]);
    if (!(halfLen > 0.0))
    {
      continue;
    }
    float mid = 0.5 * (cuts[s + 1] + cuts[s]);
    vec3 part = vec3(0.0);
    for (int i = 0; i < PLUME_GRID_A; ++i)
    {
      part += GLW[i] * AcrossIntegral(mid + halfLen * GLX[i]);
    }
    tau += halfLen * part;
  }
  tau = min(tau, vec3(1e30));
//PLUME::ENDIF
  gl_FragData[0] = vec4(tau, 0.0);
}
