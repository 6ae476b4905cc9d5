//VTK::System::Dec

// vtkPlumeVelocityGlyphMapper fragment shader. Outputs non-premultiplied
// colour; the mapper blends with (SRC_ALPHA, ONE_MINUS_SRC_ALPHA).
//
// The glyph colour is looked up once per glyph (in the geometry shader, or in
// the vertex shader of the straight-line path), so a fragment does no texture
// fetch: on llvmpipe the fragment shader runs once per 4x4 pixel block a line
// touches, which makes per-fragment work the dominant cost of dense glyphs.
//
// Variant blocks: FADE (alpha from RootAlpha at the root to 1 at the tip,
// blended) | OPAQUE (see the mapper: no alpha varying, no discard).

//PLUME::Defines

//PLUME::IF FADE
in float glyphAlpha;
//PLUME::ENDIF
flat in vec4 glyphColor; // LUT colour of |v(root)| or the solid colour

uniform float Opacity;

// VTK's translucent passes (OIT, depth peeling) insert their code at these tags
//VTK::DepthPeeling::Dec

//VTK::Output::Dec

void main()
{
  //VTK::Depth::Impl
  //VTK::DepthPeeling::PreColor
//PLUME::IF FADE
  vec4 color = glyphColor;
  float alpha = glyphAlpha * color.a * Opacity;
  if (alpha < 1.0 / 512.0)
  {
    discard; // fully transparent fragments write no depth
  }
  gl_FragData[0] = vec4(color.rgb, alpha);
//PLUME::ENDIF
//PLUME::IF OPAQUE
  // RootAlpha, Opacity and the colour's alpha are all 1: no varying alpha,
  // no discard (llvmpipe can then test depth before shading)
  gl_FragData[0] = vec4(glyphColor.rgb, 1.0);
//PLUME::ENDIF
  //VTK::DepthPeeling::Impl
}
