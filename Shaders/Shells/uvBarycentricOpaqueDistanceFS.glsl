//VTK::System::Dec
//VTK::Output::Dec
// vtkBarycentricShellMapper, once a frame: the distance of the scene's opaque geometry along each
// pixel's ray (eye distance under perspective, depth under parallel projection), from the depth VTK
// drew, so the passes over the tetrahedra read one float instead of unprojecting a depth per
// fragment. Pixels at the far plane (no geometry) are discarded: the target keeps its clear value
// (3e38), and an occlusion query counting the rest tells the mapper whether there is any geometry.
in vec2 texCoord;
uniform sampler2D opaqueDepth; // the scene's depth buffer before the volume
uniform mat4 clipToEye;
uniform vec2 viewportSize;
uniform int parallelProjection;

void main()
{
  float depth = texelFetch(opaqueDepth, ivec2(gl_FragCoord.xy), 0).r;
  if (depth >= 1.0)
  {
    discard;
  }
  vec2 ndc = gl_FragCoord.xy / viewportSize * 2.0 - 1.0;
  vec4 opaque = clipToEye * vec4(ndc, 2.0 * depth - 1.0, 1.0);
  vec3 point = opaque.xyz / opaque.w;
  gl_FragData[0] = vec4(parallelProjection == 1 ? -point.z : length(point), 0.0, 0.0, 0.0);
}
