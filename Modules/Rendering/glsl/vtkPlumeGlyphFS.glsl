//VTK::System::Dec

// vtkPlumeVelocityGlyphMapper fragment shader. Outputs non-premultiplied
// colour; the mapper blends with (SRC_ALPHA, ONE_MINUS_SRC_ALPHA).
//
// The glyph colour is looked up once per glyph (in the geometry shader, or in
// the vertex shader of the straight-line path), so a fragment does no texture
// fetch: on llvmpipe the fragment shader runs once per 4x4 pixel block a line
// touches, which makes per-fragment work the dominant cost of dense glyphs.

//PLUME::Defines

in float glyphAlpha;
flat in vec4 glyphColor; // LUT colour of |v(root)| or the solid colour

uniform float Opacity;

//VTK::Output::Dec

void main()
{
  vec4 color = glyphColor;
  float alpha = glyphAlpha * color.a * Opacity;
  if (alpha < 1.0 / 512.0)
  {
    discard; // fully transparent fragments write no depth
  }
  gl_FragData[0] = vec4(color.rgb, alpha);
}
