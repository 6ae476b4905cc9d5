//VTK::System::Dec

// vtkPlumeSheetMapper composite pass: the accumulated optical depth tau (RGB)
// becomes transmittance T = exp(-tau). Two blend modes:
//  MULTIPLY: blend (ZERO, SRC_COLOR), output T: the scene is darkened by T
//            (zero-albedo smoke, the paper's model);
//  ADD:      blend (ONE, ONE), output SmokeColor (1 - T): the light the smoke
//            itself sends back. MULTIPLY then ADD gives dst T + c (1 - T), which
//            does not depend on the order of the triangles.

//PLUME::Defines

uniform sampler2D OpticalDepth;
uniform vec2 ViewportOrigin; // window pixels of the viewport's lower-left corner
//PLUME::IF ADD
uniform vec3 SmokeColor;
//PLUME::ENDIF

//VTK::Output::Dec

void main()
{
  vec3 tau = texelFetch(OpticalDepth, ivec2(gl_FragCoord.xy - ViewportOrigin), 0).rgb;
  vec3 T = exp(-max(tau, vec3(0.0)));
  float Tmean = (T.r + T.g + T.b) / 3.0;
//PLUME::IF MULTIPLY
  // Alpha 1 - T (blended as ONE, ONE_MINUS_SRC_ALPHA): the frame's alpha
  // becomes its coverage, a_dst T + (1 - T), so a frame drawn over a
  // transparent background (ParaView's ranks before compositing) composites
  // "over" what lies behind it exactly for grey smoke. Opaque frames keep 1.
  gl_FragData[0] = vec4(T, 1.0 - Tmean);
//PLUME::ENDIF
//PLUME::IF ADD
  gl_FragData[0] = vec4(SmokeColor * (1.0 - T), 1.0 - Tmean);
//PLUME::ENDIF
}
