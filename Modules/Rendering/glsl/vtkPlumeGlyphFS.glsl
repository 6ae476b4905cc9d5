//VTK::System::Dec

// vtkPlumeVelocityGlyphMapper fragment shader. Outputs non-premultiplied
// colour; the mapper blends with (SRC_ALPHA, ONE_MINUS_SRC_ALPHA).
//
// Variant blocks: LUT (colour by |v| through a 1-row lookup texture) or SOLID.

//PLUME::Defines

in float glyphAlpha;
flat in float glyphColorCoord; // |v(root)| mapped to [0, 1] over the colour range

uniform float Opacity;
//PLUME::IF LUT
uniform sampler2D ColorLUT;
uniform float LUTSize;
//PLUME::ENDIF
//PLUME::IF SOLID
uniform vec3 SolidColor;
//PLUME::ENDIF

//VTK::Output::Dec

void main()
{
  vec4 color = vec4(1.0);
//PLUME::IF LUT
  // exact table entries at texel centres, linear in between
  float s = (glyphColorCoord * (LUTSize - 1.0) + 0.5) / LUTSize;
  color = texture(ColorLUT, vec2(s, 0.5));
//PLUME::ENDIF
//PLUME::IF SOLID
  color = vec4(SolidColor, 1.0);
//PLUME::ENDIF
  float alpha = glyphAlpha * color.a * Opacity;
  if (alpha < 1.0 / 512.0)
  {
    discard; // fully transparent fragments write no depth
  }
  gl_FragData[0] = vec4(color.rgb, alpha);
}
