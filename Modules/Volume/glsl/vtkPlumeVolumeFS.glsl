//VTK::System::Dec

// vtkPlumeVolumeMapper fragment shader: one ray per pixel, in the volume's
// index space (voxel (i,j,k) at (i,j,k)). Outputs premultiplied colour.
//
// Feature blocks (//PLUME::IF name ... //PLUME::ENDIF, kept by
// vtkPlumeShaderVariants when one of the terms holds; A+B: both enabled), so only
// what is used is compiled:
//   COMPOSITE | MIP | ISO | SMOKE   the mode
//   POINT | PREINT   composite: a sample's value over its segment | segments
//                    pre-integrated between their end values (no SKIP, PLAIN
//                    or MASK then; SKIP_PREINT instead of SKIP)
//   JITTER           jittered first segment (per pixel; JITTER+COARSE: per
//                    lattice ray, whatever band of the texture it is stored in)
//   DEPTH            stop at the opaque scene's depth
//   SKIP             empty-space skipping, with one of: SKIP_TRANSPARENT
//                    (composite/smoke: jump over transparent blocks), SKIP_MIP
//                    (blocks whose max is not above the running max), SKIP_ISO
//                    (blocks whose range misses the iso value by PLUME_ISO_MARGIN
//                    on the side the ray already is; with MASK: SKIP_ISO+MASK blocks)
//   SKIP_PREINT      PREINT's skipping: segments wholly inside transparent blocks
//                    are jumped over (their end values lie in the blocks' ranges,
//                    which overlap at shared nodes, so every value between them
//                    is transparent too)
//   SHADE            composite with gradient (Phong) shading of every sample
//   PLAIN | GRADIENT (both with NOMASK) the volume texture is u | (u, central
//                    differences along x, y, z) for shading in one look-up;
//                    SHADE_NOGRADIENT: SHADE takes six look-ups instead
//   MASK | NOMASK    the volume texture is (u w, w), w = 1 at nodes inside the
//                    data (valid-point mask), 0 outside: values are r / g, over
//                    the valid nodes only, and extinction is weighted by g, so
//                    the data fades out over its last voxel | a plain u texture
//   COARSE           the ray-lattice pass: one ray per Lattice x Lattice pixels
//                    into the lattice texture (texel i: the ray through pixel i L)
//   CLASSIFY         after it, one fragment per lattice cell (the L x L pixels
//                    between lattice rays i and i + 1): 0 where the rays around
//                    agree within LatticeTolerance (every premultiplied channel)
//                    and, with DEPTH, every pixel's opaque depth is what the
//                    cell's corner rays predict; 1 (cast own rays) elsewhere
//   REFINE           the full-resolution interpolation pass: a pixel in a cell
//                    classified 0 interpolates the lattice bilinearly (one
//                    filtered look-up); elsewhere it is discarded (nothing
//                    else runs), and the ray program draws the cells
//                    classified 1 (vtkPlumeLatticeCellsVS)
//   ISO_DEPTH        ISO without REFINE: the hit writes its window depth
//                    (gl_FragDepth), as opaque geometry does
//   SHADOW_RAYS | LIGHT_CACHE   SMOKE: a shadow ray per sample and light | the
//                    transmittances interpolated from the light volume
//   LIGHT_VOLUME     the light volume's passes (vtkPlumeLightVolume): a sweep
//                    layer (LightPass 0: fragment (u, v) writes the transmittance
//                    of the sweep's node (u, v, SweepLayer) towards light
//                    SweepLight from an earlier layer's), or a z-slice of the
//                    light volume (LightPass 1: node (i, j, LightSlice) from its
//                    sweep texel)
// Values (#define): PLUME_LIGHTS n (lit modes), PLUME_ISO_MARGIN (SKIP_ISO).

//PLUME::Defines

uniform sampler3D Volume;           // raw scalar t (MASK: t w, w; GRADIENT: t, central differences)
uniform vec2 ValueScaleBias;        // u = t scale + bias: 0..1 over the transfer functions' range
uniform sampler2D TransferFunction; // 1 row: rgb = colour, a = extinction per world unit, over u
uniform float TFSize;
uniform vec3 Dims;
uniform mat4 ClipToIndex;
uniform vec2 ViewportOrigin;
uniform vec2 ViewportSize;
uniform vec3 BoxMin;
uniform vec3 BoxMax;
uniform mat3 IndexToWorld;          // linear part of index -> world
uniform float StepIndex;            // sample distance, voxels
uniform int MaxSteps;
uniform float UnitDistance;         // scalar opacity unit distance (world)
uniform float OpacityThreshold;
//PLUME::IF PREINT
uniform sampler2D TransferIntegral; // 1 row: rgb = running integral of c sigma, a = of sigma, over u
//PLUME::ENDIF
//PLUME::IF DEPTH
uniform sampler2D OpaqueDepth;
//PLUME::ENDIF
//PLUME::IF COARSE REFINE CLASSIFY
uniform float Lattice;              // pixels between lattice rays
//PLUME::ENDIF
//PLUME::IF REFINE CLASSIFY
uniform sampler2D LatticeColor;     // the lattice rays' premultiplied colour (linear filtering)
uniform vec2 LatticeSize;
uniform float LatticeSplit;         // lattice rows above it are stored LatticeBandShift rows up
uniform float LatticeBandShift;     // (two bands, one llvmpipe tile each; split 1e9: one band)
uniform float LatticeRows;          // the texture's height
//PLUME::ENDIF
//PLUME::IF COARSE
uniform float LatticeRowOffset;     // lattice row = texture row + this (the band drawn)
//PLUME::ENDIF
//PLUME::IF CLASSIFY
uniform float LatticeTolerance;
//PLUME::ENDIF
//PLUME::IF REFINE
uniform sampler2D CellRefine;       // per lattice cell: 0 = interpolate, 1 = cast own rays
//PLUME::ENDIF
//PLUME::IF JITTER
uniform int JitterSeed;
//PLUME::ENDIF
//PLUME::IF SKIP_MIP SKIP_ISO
uniform sampler3D BlockRanges;      // per block: min, max of u
//PLUME::ENDIF
//PLUME::IF SKIP_TRANSPARENT SKIP_PREINT
uniform sampler3D Occupancy;        // per block: 0 = every value in it is transparent
//PLUME::ENDIF
//PLUME::IF SKIP SKIP_PREINT
uniform float BlockSize;            // voxels per block
uniform vec3 BlockDims;            // blocks per axis
uniform vec3 DrawMin;              // bounds of the non-transparent blocks (index space)
uniform vec3 DrawMax;
//PLUME::ENDIF
//PLUME::IF ISO
uniform float IsoValue;             // normalised
//PLUME::ENDIF
//PLUME::IF ISO SHADE
uniform mat3 NormalToWorld;         // inverse transpose of IndexToWorld
uniform float Specular;
uniform float SpecularPower;
//PLUME::ENDIF
//PLUME::IF ISO SHADE SMOKE
uniform float Ambient;
uniform float Diffuse;
//PLUME::ENDIF
//PLUME::IF SMOKE
uniform float ShadowStepIndex;      // shadow-ray step, voxels
uniform vec3 LightIndexDir[PLUME_LIGHTS];     // unit direction towards the light, index space
uniform float LightWorldPerIndex[PLUME_LIGHTS]; // world length of one index unit along it
//PLUME::ENDIF
//PLUME::IF LIGHT_CACHE
uniform sampler3D LightVolume;      // per node: transmittance towards light l in channel l
//PLUME::ENDIF
//PLUME::IF LIGHT_VOLUME
uniform int LightPass;              // 0: a sweep layer; 1: a z-slice of the light volume
uniform sampler3D LightSweep;       // the sweep's layers so far: texel (u, v, q), transmittance
uniform int SweepLight;             // the light swept
uniform int SweepAxis;              // its dominant index axis a (vtkPlumeLightVolume::GetSweep)
uniform int SweepFlip;              // 1: layer q holds coordinate Dims[a] - 1 - q on axis a; 0: q
uniform int SweepLayer;             // the layer drawn (LightPass 0)
uniform int SweepStride;            // it reads the layer SweepStride * k just before it
uniform int LightSlice;             // the z-slice drawn (LightPass 1)
//PLUME::ENDIF
//PLUME::IF ISO SMOKE SHADE
uniform vec3 LightDirection[PLUME_LIGHTS]; // unit, world, towards the light
uniform vec3 LightColor[PLUME_LIGHTS];     // colour x intensity
//PLUME::ENDIF

//VTK::Output::Dec

// textureLod: the look-ups run in non-uniform control flow (the ray loop),
// where implicit derivatives are undefined; the textures have no mipmaps
//PLUME::IF NOMASK
float sampleU(vec3 p)
{
  return textureLod(Volume, (p + 0.5) / Dims, 0.0).r * ValueScaleBias.x + ValueScaleBias.y;
}
//PLUME::ENDIF
//PLUME::IF MASK
// (u over the valid nodes, their interpolation weight w); no valid node: (0, 0)
vec2 sampleUW(vec3 p)
{
  vec2 s = textureLod(Volume, (p + 0.5) / Dims, 0.0).rg;
  return vec2(s.g > 0.0 ? (s.r / s.g) * ValueScaleBias.x + ValueScaleBias.y : 0.0, s.g);
}

float sampleU(vec3 p)
{
  return sampleUW(p).x;
}
//PLUME::ENDIF

vec4 transfer(float u)
{
  return textureLod(TransferFunction, vec2((u * (TFSize - 1.0) + 0.5) / TFSize, 0.5), 0.0);
}

// extinction per world unit at u (tabulated as -ln(1 - min(alpha, 1 - 1e-6)) / UnitDistance)
float extinction(float u)
{
  return transfer(u).a;
}

//PLUME::IF PREINT
// running integral of (c sigma, sigma) from u = 0 to u; beyond the table the
// end entries hold (as transfer() clamps)
vec4 integral(float u)
{
  float uc = clamp(u, 0.0, 1.0);
  vec4 s = textureLod(TransferIntegral, vec2((uc * (TFSize - 1.0) + 0.5) / TFSize, 0.5), 0.0);
  if (u != uc)
  {
    vec4 e = transfer(uc);
    s += (u - uc) * vec4(e.rgb * e.a, e.a);
  }
  return s;
}

// (colour, opacity) of a segment of world length len along which the value
// goes linearly from uf to ub: optical depth len * mean sigma (exact), colour
// the sigma-weighted mean colour over the values crossed
vec4 segment(float uf, float ub, float len)
{
  float du = ub - uf;
  vec4 m; // mean of (c sigma, sigma) over [uf, ub]
  if (abs(du) > 1e-3)
  {
    m = (integral(ub) - integral(uf)) / du;
  }
  else
  {
    vec4 e = transfer(0.5 * (uf + ub)); // (differences of nearby floats lose digits)
    m = vec4(e.rgb * e.a, e.a);
  }
  m = max(m, vec4(0.0));
  return vec4(m.a > 0.0 ? m.rgb / m.a : vec3(0.0), 1.0 - exp(-m.a * len));
}
//PLUME::ENDIF

// [t0, t1] of the ray p + t d inside the box, clipped to [lo, hi] (empty: t0 >= t1).
// Vectorised slab test; |d| components below 1e-30 are replaced by 1e-30 so an
// axis-parallel ray gets +-1e30 bounds (inside the slab) instead of NaN.
vec2 clipToBox(vec3 p, vec3 d, float lo, float hi)
{
  vec3 dd = mix(d, vec3(1e-30), lessThan(abs(d), vec3(1e-30)));
  vec3 ta = (BoxMin - p) / dd;
  vec3 tb = (BoxMax - p) / dd;
  vec3 tn = min(ta, tb);
  vec3 tf = max(ta, tb);
  return vec2(max(lo, max(tn.x, max(tn.y, tn.z))), min(hi, min(tf.x, min(tf.y, tf.z))));
}

//PLUME::IF REFINE CLASSIFY
// where lattice ray r is stored (see LatticeSplit)
ivec2 latticeTexel(ivec2 r)
{
  return r.y > int(LatticeSplit) ? r + ivec2(0, int(LatticeBandShift)) : r;
}
//PLUME::ENDIF

//PLUME::IF JITTER
float jitter()
{
  uvec2 q = uvec2(gl_FragCoord.xy);
//PLUME::ENDIF
//PLUME::IF JITTER+COARSE
  // each lattice ray its own offset: one shared offset made a coherent error
  // (RMS +30 % at 16-64-voxel steps, h/volspeed, measured 2026-11-28)
  q = uvec2(gl_FragCoord.xy + vec2(0.0, LatticeRowOffset)); // the lattice ray's, whatever its band
//PLUME::ENDIF
//PLUME::IF JITTER
  uint h = q.x * 1973u + q.y * 9277u + uint(JitterSeed) * 26699u;
  h = (h ^ 61u) ^ (h >> 16);
  h *= 9u;
  h ^= h >> 4;
  h *= 0x27d4eb2du;
  h ^= h >> 15;
  return 1.0 - float(h & 0xffffffu) / 16777216.0; // (0, 1]
}
//PLUME::ENDIF

//PLUME::IF SMOKE
// extinction per world unit at p (index space), weighted by the valid nodes with MASK
float sampleExtinction(vec3 p)
{
//PLUME::ENDIF
//PLUME::IF SMOKE+NOMASK
  return extinction(sampleU(p));
//PLUME::ENDIF
//PLUME::IF SMOKE+MASK
  vec2 uw = sampleUW(p);
  return extinction(uw.x) * uw.y;
//PLUME::ENDIF
//PLUME::IF SMOKE
}

// transmittance from p (index space) towards light l, through the box
float lightTransmittance(vec3 p, int l)
{
  vec3 e = LightIndexDir[l];
  vec2 t = clipToBox(p, e, 0.0, 1e30);
  if (!(t.y > 0.0))
  {
    return 1.0;
  }
  int n = int(ceil(t.y / ShadowStepIndex));
  n = clamp(n, 1, 256);
  float h = t.y / float(n);
  float tau = 0.0;
  for (int k = 0; k < n; ++k)
  {
    tau += sampleExtinction(p + (float(k) + 0.5) * h * e);
    if (tau * h * LightWorldPerIndex[l] > 10.0)
    {
      return 0.0;
    }
  }
  return exp(-tau * h * LightWorldPerIndex[l]);
}
//PLUME::ENDIF

//PLUME::IF GRADIENT
// (u, its central differences along x, y, z) at index-space point p
vec4 sampleUG(vec3 p)
{
  vec4 s = textureLod(Volume, (p + 0.5) / Dims, 0.0);
  return vec4(s.r * ValueScaleBias.x + ValueScaleBias.y, s.gba * ValueScaleBias.x);
}
//PLUME::ENDIF
//PLUME::IF ISO SHADE_NOGRADIENT
// central differences (one voxel each way) of u at index-space point p
vec3 gradientAt(vec3 p)
{
  return vec3(sampleU(p + vec3(1, 0, 0)) - sampleU(p - vec3(1, 0, 0)),
    sampleU(p + vec3(0, 1, 0)) - sampleU(p - vec3(0, 1, 0)),
    sampleU(p + vec3(0, 0, 1)) - sampleU(p - vec3(0, 0, 1)));
}
//PLUME::ENDIF

//PLUME::IF ISO SHADE
// Phong lighting of colour `base` with index-space gradient g (central
// differences), normal turned towards the viewer; zero gradient: facing the viewer
vec3 phong(vec3 base, vec3 g, vec3 viewDir)
{
  vec3 n = NormalToWorld * g;
  float len = length(n);
  n = len > 1e-20 ? n / len : viewDir;
  if (dot(n, viewDir) < 0.0)
  {
    n = -n;
  }
  vec3 color = Ambient * base;
  for (int l = 0; l < PLUME_LIGHTS; ++l)
  {
    vec3 L = LightDirection[l];
    color += Diffuse * max(dot(n, L), 0.0) * base * LightColor[l];
    vec3 H = L + viewDir;
    float hl = length(H);
    float nh = hl > 1e-6 ? max(dot(n, H / hl), 0.0) : 0.0;
    color += Specular * (nh > 0.0 ? pow(nh, SpecularPower) : 0.0) * LightColor[l];
  }
  return color;
}
//PLUME::ENDIF

//PLUME::IF DEPTH+CLASSIFY
// where the ray through viewport position `local` meets the opaque scene,
// index space, clamped to the box, w = 1; w = 0 (and xyz 0) where the scene
// does not stop it before its exit from the box (nothing drawn there, or
// drawn behind the box): those rays all look alike. (Clamping the far point
// of such a ray to the box instead jumped from one side of the box to the
// other along the lines through the view's centre, whose cells then always
// refined.)
vec4 opaqueEnd(vec2 local)
{
  ivec2 px = clamp(ivec2(local), ivec2(0), ivec2(ViewportSize) - 1);
  float z = texelFetch(OpaqueDepth, px, 0).r;
  vec2 ndc = 2.0 * local / ViewportSize - 1.0;
  vec4 n = ClipToIndex * vec4(ndc, -1.0, 1.0);
  vec4 q = ClipToIndex * vec4(ndc, 2.0 * z - 1.0, 1.0);
  vec3 p0 = n.xyz / n.w;
  vec3 end = q.xyz / q.w;
  vec2 t = clipToBox(p0, end - p0, 0.0, 1e30); // the opaque point is at t = 1
  return t.y > t.x && t.y > 1.0 ? vec4(clamp(end, BoxMin, BoxMax), 1.0) : vec4(0.0);
}
//PLUME::ENDIF

//PLUME::IF LIGHT_VOLUME
// layer q of the sweep at (u, v): Catmull-Rom bicubic, limited to the range of
// the 2 x 2 texels around (no new extremes); bilinear interpolation, repeated
// from layer to layer, would blur the shadows (by about a voxel over 16 layers
// of a 32^3 smoke)
float sweepLayerAt(vec2 uv, int q)
{
  ivec2 top = ivec2(textureSize(LightSweep, 0).xy) - 1;
  vec2 x = clamp(uv, vec2(0.0), vec2(top));
  ivec2 i1 = min(ivec2(floor(x)), max(top - 1, ivec2(0)));
  vec2 f = x - vec2(i1);
  vec2 w[4];
  w[0] = f * (-0.5 + f * (1.0 - 0.5 * f));
  w[1] = 1.0 + f * f * (-2.5 + 1.5 * f);
  w[2] = f * (0.5 + f * (2.0 - 1.5 * f));
  w[3] = f * f * (-0.5 + 0.5 * f);
  float sum = 0.0;
  float lo = 1e30;
  float hi = -1e30;
  for (int j = 0; j < 4; ++j)
  {
    float row = 0.0;
    for (int i = 0; i < 4; ++i)
    {
      float v = texelFetch(LightSweep, ivec3(clamp(i1 + ivec2(i - 1, j - 1), ivec2(0), top), q), 0).r;
      row += w[i].x * v;
      if ((i == 1 || i == 2) && (j == 1 || j == 2))
      {
        lo = min(lo, v);
        hi = max(hi, v);
      }
    }
    sum += w[j].y * row;
  }
  return clamp(sum, lo, hi);
}
//PLUME::ENDIF

void main()
{
//PLUME::IF LIGHT_VOLUME
  {
    ivec2 uv = ivec2(gl_FragCoord.xy);
    int a = SweepAxis;
    int b = (a + 1) % 3;
    int c = (a + 2) % 3;
    if (LightPass == 1)
    {
      ivec3 n = ivec3(uv, LightSlice);
      int na = SweepFlip != 0 ? int(Dims[a]) - 1 - n[a] : n[a];
      gl_FragData[0] = vec4(texelFetch(LightSweep, ivec3(n[b], n[c], na), 0).r);
      return;
    }
    vec3 node;
    node[a] = float(SweepFlip != 0 ? int(Dims[a]) - 1 - SweepLayer : SweepLayer);
    node[b] = float(uv.x);
    node[c] = float(uv.y);
    vec3 e = LightIndexDir[SweepLight];
    // the layer read: the last multiple of SweepStride before this one, so a
    // ray is interpolated once per SweepStride layers only (each
    // interpolation blurs the shadows a little)
    int from = ((SweepLayer - 1) / SweepStride) * SweepStride;
    float h = float(SweepLayer - from) / abs(e[a]); // ray length from the node to that layer
//PLUME::ENDIF
//PLUME::IF LIGHT_VOLUME+SKIP_TRANSPARENT
    // a sample's cell lies in one block, whose nodes (shared faces included)
    // are all it interpolates: where every block holding this node is
    // transparent, no sample with extinction reads it, and unless later
    // layers read this one, it is not computed
    if (SweepLayer % SweepStride != 0)
    {
      bool needed = false;
      for (int k = 0; k < 8; ++k)
      {
        vec3 q = node - vec3(float(k & 1), float((k >> 1) & 1), float((k >> 2) & 1));
        ivec3 cell = clamp(ivec3(floor(q / BlockSize)), ivec3(0), ivec3(BlockDims) - 1);
        needed = needed || texelFetch(Occupancy, cell, 0).r != 0.0;
      }
      if (!needed)
      {
        gl_FragData[0] = vec4(1.0);
        return;
      }
    }
//PLUME::ENDIF
//PLUME::IF LIGHT_VOLUME
    float t = 1.0;
    if (SweepLayer == 0 || clipToBox(node, e, 0.0, 1e30).y < h * (1.0 - 1e-5))
    {
      // the ray leaves the box before the previous layer: march the rest
      t = lightTransmittance(node, SweepLight);
    }
    else
    {
      // that layer's transmittance where the ray meets it...
      vec3 p = node + h * e;
      t = sweepLayerAt(vec2(p[b], p[c]), from);
      // ...times the segment's own (midpoint steps of at most ShadowStepIndex),
      // unless the light is already gone (the deep shadow of dense smoke)
      int n = t > 1e-6 ? max(1, int(ceil(h / ShadowStepIndex))) : 0;
      float hs = h / float(n);
      float tau = 0.0;
      for (int k = 0; k < n; ++k)
      {
        tau += sampleExtinction(node + (float(k) + 0.5) * hs * e);
      }
      t = n > 0 ? t * exp(-tau * hs * LightWorldPerIndex[SweepLight]) : 0.0;
    }
    gl_FragData[0] = vec4(t);
    return;
  }
//PLUME::ENDIF
//PLUME::IF CLASSIFY
  {
    // cell a: the pixels a L .. a L + L - 1, between lattice rays a and a + 1
    ivec2 a = ivec2(gl_FragCoord.xy);
    ivec2 top = ivec2(LatticeSize) - 1;
    // the 4 x 4 lattice rays around (g[5], g[6], g[9], g[10] are the cell's corners)
    vec4 g[16];
    for (int k = 0; k < 16; ++k)
    {
      g[k] = texelFetch(LatticeColor, latticeTexel(clamp(a + ivec2(k % 4 - 1, k / 4 - 1), ivec2(0), top)), 0);
    }
    // bilinear interpolation is exact for bilinear images; its error is about
    // 1/8 of the second differences across the cell (edges, silhouettes and
    // peaks make them large), taken at the four corners along x and y
    vec4 curvature = vec4(0.0);
    for (int k = 5; k <= 10; k += (k == 6 ? 3 : 1))
    {
      curvature = max(curvature, abs(g[k - 1] - 2.0 * g[k] + g[k + 1]));
      curvature = max(curvature, abs(g[k - 4] - 2.0 * g[k] + g[k + 4]));
    }
    bool agree = all(lessThanEqual(0.125 * curvature, vec4(LatticeTolerance)));
//PLUME::ENDIF
//PLUME::IF DEPTH+CLASSIFY
    if (agree)
    {
      // no opaque edge in the cell: every pixel's opaque end is what the
      // corner rays' predict, within half a voxel
      // (and whether the scene stops it inside the box at all: w)
      vec4 e00 = opaqueEnd(vec2(a) * Lattice + 0.5);
      vec4 e10 = opaqueEnd(vec2(a + ivec2(1, 0)) * Lattice + 0.5);
      vec4 e01 = opaqueEnd(vec2(a + ivec2(0, 1)) * Lattice + 0.5);
      vec4 e11 = opaqueEnd(vec2(a + ivec2(1, 1)) * Lattice + 0.5);
      int n = int(Lattice);
      for (int j = 0; j < n && agree; ++j)
      {
        for (int i = 0; i < n && agree; ++i)
        {
          vec2 f = vec2(float(i), float(j)) / Lattice;
          vec4 e = mix(mix(e00, e10, f.x), mix(e01, e11, f.x), f.y);
          vec4 o = opaqueEnd(vec2(a) * Lattice + vec2(float(i), float(j)) + 0.5);
          agree = abs(o.w - e.w) <= 1e-3 && length(o.xyz - e.xyz) <= 0.5;
        }
      }
    }
//PLUME::ENDIF
//PLUME::IF CLASSIFY
    gl_FragData[0] = vec4(agree ? 0.0 : 1.0);
    return;
  }
//PLUME::ENDIF
  vec2 fragLocal = gl_FragCoord.xy - ViewportOrigin; // position in the viewport, pixels
//PLUME::IF COARSE
  // texel i: pixel i L (the texture starts at 0; rows by band)
  fragLocal = (gl_FragCoord.xy - 0.5 + vec2(0.0, LatticeRowOffset)) * Lattice + 0.5;
//PLUME::ENDIF
//PLUME::IF REFINE
  {
    // pixel p lies in cell floor(p / L); at lattice position p / L
    vec2 q = (fragLocal - 0.5) / Lattice;
    ivec2 cell = clamp(ivec2(floor(q)), ivec2(0), ivec2(LatticeSize) - 1);
    // (a cell's four rays lie in one band: the split row is stored in both)
    vec2 stored = q + vec2(0.0, float(cell.y) >= LatticeSplit ? LatticeBandShift : 0.0);
    vec4 v = textureLod(LatticeColor, (stored + 0.5) / vec2(LatticeSize.x, LatticeRows), 0.0);
    if (texelFetch(CellRefine, cell, 0).r != 0.0 || v.a <= 0.0)
    {
      discard; // (the cell's own rays are drawn by the ray program)
    }
    gl_FragData[0] = v;
    return;
  }
//PLUME::ENDIF
  vec2 ndc = 2.0 * fragLocal / ViewportSize - 1.0;
  vec4 a = ClipToIndex * vec4(ndc, -1.0, 1.0);
  vec4 b = ClipToIndex * vec4(ndc, 1.0, 1.0);
  vec3 p0 = a.xyz / a.w;   // ray at the near plane
  vec3 d = b.xyz / b.w - p0; // to the far plane: t in [0, 1]
  float tEnd = 1.0;
//PLUME::IF DEPTH
  float z = texelFetch(OpaqueDepth, clamp(ivec2(fragLocal), ivec2(0), ivec2(ViewportSize) - 1), 0).r;
  if (z < 1.0)
  {
    vec4 q = ClipToIndex * vec4(ndc, 2.0 * z - 1.0, 1.0);
    tEnd = dot(q.xyz / q.w - p0, d) / dot(d, d);
  }
//PLUME::ENDIF
  vec2 t = clipToBox(p0, d, 0.0, tEnd);
  if (!(t.y > t.x))
  {
    discard;
  }
  float dt = StepIndex / length(d);
  if ((t.y - t.x) / dt > float(MaxSteps))
  {
    dt = (t.y - t.x) / float(MaxSteps);
  }
  float worldPerT = length(IndexToWorld * d);
  float first = dt;
//PLUME::IF JITTER
  first = jitter() * dt;
//PLUME::ENDIF

//PLUME::IF ISO SMOKE SHADE
  vec3 viewDir = -normalize(IndexToWorld * d); // world, towards the eye
//PLUME::ENDIF

  vec4 dst = vec4(0.0);
//PLUME::IF MIP
  float uMax = -1.0;
//PLUME::ENDIF
//PLUME::IF ISO
  float tPrev = t.x;
  float fPrev = sampleU(p0 + t.x * d) - IsoValue;
  bool prevInside = true; // the previous sample is inside the data
//PLUME::ENDIF
//PLUME::IF ISO+MASK
  prevInside = sampleUW(p0 + t.x * d).y > 0.0;
//PLUME::ENDIF
//PLUME::IF ISO
  bool hit = false;
  float tHit = 0.0;
//PLUME::ENDIF

  // segment 0 is [t.x, segBase]; segment m >= 1 is [segBase + (m-1) dt, segBase + m dt], clipped to t.y
  float segBase = t.x + first;
  float s0 = t.x;
  float s1 = min(segBase, t.y);
//PLUME::IF SKIP
  float m = 0.0;
  float occupiedUntil = -1.0; // the ray is in an occupied block until this t
  // outside the bounds of the non-transparent blocks nothing contributes: end
  // there, and start at the first segment (of the same lattice) whose midpoint
  // is inside them
  {
    vec3 dd = mix(d, vec3(1e-30), lessThan(abs(d), vec3(1e-30)));
    vec3 ta = (DrawMin - p0) / dd;
    vec3 tb = (DrawMax - p0) / dd;
    vec3 tn = min(ta, tb);
    vec3 tf = max(ta, tb);
    float enter = max(tn.x, max(tn.y, tn.z));
    t.y = min(t.y, min(tf.x, min(tf.y, tf.z)));
    if (enter > 0.5 * (s0 + s1))
    {
      m = ceil((enter - segBase) / dt + 0.5);
      s0 = segBase + (m - 1.0) * dt;
      s1 = min(s0 + dt, t.y);
    }
    s1 = min(s1, t.y);
  }
//PLUME::ENDIF
//PLUME::IF SKIP_PREINT
  float m = 0.0;
  float occupiedUntil = -1.0; // the segments starting before this t are in an occupied block
  {
    // outside the bounds of the non-transparent blocks nothing contributes:
    // start at the segment (of the same lattice) that contains their entry
    vec3 dd = mix(d, vec3(1e-30), lessThan(abs(d), vec3(1e-30)));
    vec3 tn = min((DrawMin - p0) / dd, (DrawMax - p0) / dd);
    float enter = max(tn.x, max(tn.y, tn.z));
    if (enter > s1)
    {
      m = floor((enter - segBase) / dt) + 1.0;
      s0 = segBase + (m - 1.0) * dt;
      s1 = min(s0 + dt, t.y);
    }
  }
//PLUME::ENDIF
//PLUME::IF PREINT
  // segments are pre-integrated between their end samples (the back one is
  // the next segment's front)
  float uFront = sampleU(p0 + s0 * d);
//PLUME::ENDIF
  for (int i = 0; i <= MaxSteps + 1 && s0 < t.y; ++i)
  {
    float tm = 0.5 * (s0 + s1);
    vec3 p = p0 + tm * d;
//PLUME::IF SKIP_PREINT
    if (s0 >= occupiedUntil)
    {
      // the run of transparent blocks the segment starts in (up to 16 blocks;
      // each block is entered just past the previous one's exit: on a face,
      // the one ahead)
      vec3 dd = mix(d, vec3(1e-30), lessThan(abs(d), vec3(1e-30)));
      float eps = 1e-3 * dt;
      float run = s0;  // the run of transparent blocks ends here
      bool occupied = false;
      for (int k = 0; k < 16 && run < t.y; ++k)
      {
        vec3 ps = p0 + (run + eps) * d;
        ivec3 cell = clamp(ivec3(floor(ps / BlockSize)), ivec3(0), ivec3(BlockDims) - 1);
        vec3 lo = vec3(cell) * BlockSize;
        vec3 tf = max((lo - p0) / dd, (lo + BlockSize - p0) / dd);
        float te = max(min(tf.x, min(tf.y, tf.z)), run + eps); // where the ray leaves it
        if (texelFetch(Occupancy, cell, 0).r != 0.0)
        {
          occupied = true;
          if (k == 0)
          {
            occupiedUntil = te; // no more look-ups until a segment starts past this block
          }
          break;
        }
        run = te;
      }
      if (s1 <= run || (!occupied && run >= t.y))
      {
        // this segment and the next ones up to the run's end add nothing: go
        // to the segment that contains its end, its front sampled there
        m = max(m + 1.0, floor((run - segBase) / dt) + 1.0);
        s0 = segBase + (m - 1.0) * dt;
        s1 = min(s0 + dt, t.y);
        uFront = sampleU(p0 + s0 * d);
        continue;
      }
    }
//PLUME::ENDIF
//PLUME::IF SKIP
    if (tm >= occupiedUntil)
    {
      ivec3 cell = clamp(ivec3(floor(p / BlockSize)), ivec3(0), ivec3(BlockDims) - 1);
      // where the ray leaves this block
      vec3 lo = vec3(cell) * BlockSize;
      vec3 dd = mix(d, vec3(1e-30), lessThan(abs(d), vec3(1e-30)));
      vec3 tf = max((lo - p0) / dd, (lo + BlockSize - p0) / dd);
      float te = min(t.y, min(tf.x, min(tf.y, tf.z)));
//PLUME::ENDIF
//PLUME::IF SKIP_MIP
      // no sample in the block can raise the maximum
      bool skip = texelFetch(BlockRanges, cell, 0).g <= uMax;
//PLUME::ENDIF
//PLUME::IF SKIP_ISO
      // every sample in the block is on the side of the iso value the ray is on:
      // no sign change can be found before the block's exit
      vec2 r = texelFetch(BlockRanges, cell, 0).rg;
      bool skip = fPrev < 0.0 ? r.g < IsoValue - PLUME_ISO_MARGIN : r.r > IsoValue + PLUME_ISO_MARGIN;
//PLUME::ENDIF
//PLUME::IF SKIP_TRANSPARENT
      bool skip = texelFetch(Occupancy, cell, 0).r == 0.0;
//PLUME::ENDIF
//PLUME::IF SKIP
      if (skip)
      {
        // every sample whose midpoint lies in this block contributes nothing:
        // go to the first segment whose midpoint is past the block's exit
        m = max(m + 1.0, ceil((te - segBase) / dt + 0.5));
        s0 = segBase + (m - 1.0) * dt;
        s1 = min(s0 + dt, t.y);
//PLUME::ENDIF
//PLUME::IF SKIP_ISO
        // the bisection starts at the last skipped sample, as without skipping
        tPrev = m >= 2.0 ? segBase + (m - 1.5) * dt : 0.5 * (t.x + min(segBase, t.y));
//PLUME::ENDIF
//PLUME::IF SKIP_ISO+MASK
        // ... and whether that sample has valid nodes around, as without skipping
        // (its sign, if it has, is fPrev's: the block's range says so)
        prevInside = sampleUW(p0 + tPrev * d).y > 0.0;
//PLUME::ENDIF
//PLUME::IF SKIP
        continue;
      }
      occupiedUntil = max(te, tm); // no more look-ups until the ray leaves the block
    }
//PLUME::ENDIF
//PLUME::IF PLAIN
    float u = sampleU(p);
    float w = 1.0;
//PLUME::ENDIF
//PLUME::IF GRADIENT
    vec4 ug = sampleUG(p);
    float u = ug.r;
    float w = 1.0;
//PLUME::ENDIF
//PLUME::IF MASK
    vec2 uw = sampleUW(p);
    float u = uw.x;
    float w = uw.y; // weight of the valid nodes: the data fades out over its last voxel
//PLUME::ENDIF
//PLUME::IF POINT
    vec4 c = transfer(u);
    float alpha = 1.0 - exp(-c.a * w * (s1 - s0) * worldPerT);
//PLUME::ENDIF
//PLUME::IF PREINT
    float uBack = sampleU(p0 + s1 * d);
    vec4 c = segment(uFront, uBack, (s1 - s0) * worldPerT);
    float alpha = c.a;
    uFront = uBack;
//PLUME::ENDIF
//PLUME::IF SHADE
    if (alpha > 0.0)
    {
//PLUME::ENDIF
//PLUME::IF GRADIENT
      c.rgb = phong(c.rgb, ug.gba, viewDir);
//PLUME::ENDIF
//PLUME::IF SHADE_NOGRADIENT
      c.rgb = phong(c.rgb, gradientAt(p), viewDir);
//PLUME::ENDIF
//PLUME::IF SHADE
    }
//PLUME::ENDIF
//PLUME::IF COMPOSITE
    dst.rgb += (1.0 - dst.a) * alpha * c.rgb;
    dst.a += (1.0 - dst.a) * alpha;
    if (dst.a >= OpacityThreshold)
    {
      break;
    }
//PLUME::ENDIF
//PLUME::IF SMOKE
    vec4 c = transfer(u);
    float sigma = c.a * w;
    if (sigma > 0.0)
    {
      float alpha = 1.0 - exp(-sigma * (s1 - s0) * worldPerT);
      vec3 light = vec3(Ambient);
//PLUME::IF LIGHT_CACHE
      vec4 cached = textureLod(LightVolume, (p + 0.5) / Dims, 0.0);
//PLUME::ENDIF
      for (int l = 0; l < PLUME_LIGHTS; ++l)
      {
//PLUME::IF LIGHT_CACHE
        float transmittance = cached[l];
//PLUME::ENDIF
//PLUME::IF SHADOW_RAYS
        float transmittance = lightTransmittance(p, l);
//PLUME::ENDIF
        light += Diffuse * LightColor[l] * transmittance;
      }
      dst.rgb += (1.0 - dst.a) * alpha * c.rgb * light;
      dst.a += (1.0 - dst.a) * alpha;
      if (dst.a >= OpacityThreshold)
      {
        break;
      }
    }
//PLUME::ENDIF
//PLUME::IF MIP
    uMax = w > 0.0 ? max(uMax, u) : uMax; // samples with no valid node around do not count
//PLUME::ENDIF
//PLUME::IF ISO
    float f = u - IsoValue;
    bool inside = w > 0.0; // a crossing needs two samples with valid nodes around
    if (inside && prevInside && (fPrev < 0.0) != (f < 0.0))
    {
      // bisection between the previous sample and this one
      float ta = tPrev, tb = tm;
      for (int k = 0; k < 8; ++k)
      {
        float tc = 0.5 * (ta + tb);
        float fc = sampleU(p0 + tc * d) - IsoValue;
        if ((fc < 0.0) == (fPrev < 0.0))
        {
          ta = tc;
        }
        else
        {
          tb = tc;
        }
      }
      hit = true;
      tHit = 0.5 * (ta + tb);
      break;
    }
    if (inside)
    {
      tPrev = tm;
      fPrev = f;
    }
    prevInside = inside;
//PLUME::ENDIF
    s0 = s1;
    s1 = min(s0 + dt, t.y);
//PLUME::IF SKIP SKIP_PREINT
    m += 1.0;
//PLUME::ENDIF
  }

//PLUME::IF MIP
  if (uMax < 0.0)
  {
    discard;
  }
  vec4 c = transfer(uMax);
  float alpha = 1.0 - exp(-c.a * UnitDistance); // the scalar opacity
  dst = vec4(c.rgb * alpha, alpha);
//PLUME::ENDIF
//PLUME::IF ISO
  if (!hit)
  {
    discard;
  }
  vec3 color = phong(transfer(IsoValue).rgb, gradientAt(p0 + tHit * d), viewDir);
  dst = vec4(color, 1.0);
//PLUME::IF ISO_DEPTH
  // The hit's window depth: along the ray the homogeneous index point is
  // (1 - s) a + s b for window depth s (a, b at the near and far planes), and
  // p0 + tHit d is its dehomogenised form, so s = tHit a.w / ((1 - tHit) b.w + tHit a.w).
  gl_FragDepth = clamp(tHit * a.w / ((1.0 - tHit) * b.w + tHit * a.w), 0.0, 1.0);
//PLUME::ENDIF
//PLUME::ENDIF
  if (dst.a <= 0.0)
  {
    discard;
  }
  gl_FragData[0] = dst;
}
