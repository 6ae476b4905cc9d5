// A textured spot light's image (vtkPlumeAirlightPass::SetLightTexture), one
// definition for the airlight's full-screen pass and for the surfaces'
// lighting (injected into VTK's polydata shaders), so that the pattern in
// the air and on the walls is the same.

// Where the direction v (from the light, any length) meets the image: the
// cone's square, the cone's circle inscribed. axis: the light's unit axis;
// right, up: the image's axes divided by tan(cone); all in eye coordinates.
vec2 plumeLightTextureCoordinates(vec3 v, vec3 axis, vec3 right, vec3 up)
{
  float z = max(dot(v, axis), 1e-30); // > 0 inside a cone of at most 90 degrees
  return clamp(0.5 + 0.5 * vec2(dot(v, right), dot(v, up)) / z, 0.0, 1.0);
}

// The image (RGB) at image coordinates uv, bilinear between texel centres,
// clamped to the light's own rectangle of the atlas (no bleeding from a
// neighbour). rect: atlas texels x0, y0, width, height.
vec3 plumeLightTexel(sampler2D atlas, vec4 rectangle, vec2 uv)
{
  ivec4 rect = ivec4(rectangle);
  vec2 s = uv * vec2(rect.zw) - 0.5;
  vec2 s0 = floor(s);
  vec2 f = s - s0;
  ivec2 i0 = clamp(ivec2(s0), ivec2(0), rect.zw - 1);
  ivec2 i1 = clamp(ivec2(s0) + 1, ivec2(0), rect.zw - 1);
  vec3 t00 = texelFetch(atlas, rect.xy + i0, 0).rgb;
  vec3 t10 = texelFetch(atlas, rect.xy + ivec2(i1.x, i0.y), 0).rgb;
  vec3 t01 = texelFetch(atlas, rect.xy + ivec2(i0.x, i1.y), 0).rgb;
  vec3 t11 = texelFetch(atlas, rect.xy + i1, 0).rgb;
  return mix(mix(t00, t10, f.x), mix(t01, t11, f.x), f.y);
}
