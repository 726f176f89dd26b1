//VTK::System::Dec
//VTK::Output::Dec
// vtkHexahedralRayCastMapper, entry pass: keeps, per pixel, the nearest boundary face where the eye
// ray enters the mesh beyond where the previous traversal left it (depth peeling: a ray that leaves
// a non-convex mesh or crosses a hole is picked up again by the next peel).
in vec3 modelPosition;
flat in int boundaryFace;
flat in vec3 outwardNormal;

uniform mat4 clipToModel;
uniform vec2 viewportSize;
uniform sampler2D previousExit; // ray parameter where the previous peel's traversal ended
uniform int firstPeel;

void main()
{
  vec2 ndc = gl_FragCoord.xy / viewportSize * 2.0 - 1.0;
  vec4 nearPoint = clipToModel * vec4(ndc, -1.0, 1.0);
  vec4 farPoint = clipToModel * vec4(ndc, 1.0, 1.0);
  vec3 origin = nearPoint.xyz / nearPoint.w;
  vec3 direction = normalize(farPoint.xyz / farPoint.w - origin);
  if (dot(outwardNormal, direction) >= 0.0)
  {
    discard; // the ray leaves the mesh here
  }
  float t = dot(modelPosition - origin, direction);
  if (firstPeel == 0 && !(t > texelFetch(previousExit, ivec2(gl_FragCoord.xy), 0).r))
  {
    discard; // already traversed
  }
  gl_FragData[0] = vec4(t, float(boundaryFace), 0.0, 1.0);
}
