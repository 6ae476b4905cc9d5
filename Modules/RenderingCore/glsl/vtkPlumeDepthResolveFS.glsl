//VTK::System::Dec

// vtkPlumeOpaqueDepthTexture: resolves a multisampled depth buffer to the
// NEAREST of each pixel's samples. A resolving blit takes one sample, so an
// anti-aliased edge pixel of a thin line whose chosen sample missed the line
// gets the background's depth and a volume is drawn over the line there
// (dashed lines). With the nearest sample, rays stop at the line in every
// pixel it touches.

uniform sampler2DMS Source; // the opaque scene's depth, copied sample for sample
uniform int Samples;
in vec2 texCoord; // the full-screen quad's (0..1 over the texture)

//VTK::Output::Dec

void main()
{
  // from texCoord rather than gl_FragCoord: the quad's vertex shader needs its attribute used
  ivec2 pixel = min(ivec2(texCoord * vec2(textureSize(Source))), textureSize(Source) - 1);
  float depth = 1.0;
  for (int i = 0; i < Samples; ++i)
  {
    depth = min(depth, texelFetch(Source, pixel, i).r);
  }
  gl_FragDepth = depth;
}
