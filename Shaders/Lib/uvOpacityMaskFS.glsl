//VTK::System::Dec
// Early ray termination (vtkUnstructuredVolumeOpacityMask): pixels whose accumulated opacity reached
// the threshold get depth 0 (colour writes off), so the depth test (LESS) keeps later passes from
// shading them.
in vec2 texCoord;
uniform sampler2D accumulated;
uniform float opacityThreshold;

void main()
{
  if (texelFetch(accumulated, ivec2(gl_FragCoord.xy), 0).a < opacityThreshold)
  {
    discard;
  }
  gl_FragDepth = 0.0;
}
