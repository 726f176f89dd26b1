//VTK::System::Dec
//VTK::Output::Dec
// vtkHexahedralRayCastMapper, entry pass: keeps, per pixel, the nearest boundary face where the eye
// ray enters the mesh beyond where the previous traversal left it (depth peeling: a ray that leaves
// a non-convex mesh or crosses a hole is picked up again by the next peel).
in vec3 modelPosition;
flat in int boundaryFace;
flat in vec3 outwardNormal;

uniform mat4 clipToModel;
uniform mat4 modelToClip;
uniform isamplerBuffer boundaryFaces;
uniform usamplerBuffer cellPoints;
uniform samplerBuffer pointData;

const int faceCorners[24] = int[24](0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7);

//UV::BilinearFace
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
  // Where the ray meets the face exactly (the rasterised triangles only choose the pixels).
  ivec4 cellFace = texelFetch(boundaryFaces, boundaryFace);
  uvec4 idsA = texelFetch(cellPoints, 2 * cellFace.x), idsB = texelFetch(cellPoints, 2 * cellFace.x + 1);
  uint cellIds[8] = uint[8](idsA.x, idsA.y, idsA.z, idsA.w, idsB.x, idsB.y, idsB.z, idsB.w);
  vec3 q[4];
  uint qi[4];
  for (int k = 0; k < 4; ++k)
  {
    qi[k] = cellIds[faceCorners[4 * cellFace.y + k]];
    q[k] = texelFetch(pointData, int(qi[k])).xyz;
  }
  vec3 a, b, c, d;
  CanonicalQuad(q, qi, a, b, c, d);
  float h0, h1;
  vec2 uv0, uv1;
  int hits = HitPatchAt(origin, direction, a, b, c, d, h0, h1, uv0, uv1);
  float after = firstPeel == 1 ? -3.0e38 : texelFetch(previousExit, ivec2(gl_FragCoord.xy), 0).r;
  // Only where the ray enters the mesh: the patch's own normal there, turned outward (a curved
  // boundary face can be entered on one part and left on another).
  vec3 normal0 = PatchNormalAt(a, b, c, d, uv0), normal1 = PatchNormalAt(a, b, c, d, uv1);
  // Where a collapsed edge makes the patch's normal vanish, the face's mean normal decides.
  float tiny = 1e-6 * dot(outwardNormal, outwardNormal);
  normal0 = dot(normal0, normal0) > tiny ? normal0 : outwardNormal;
  normal1 = dot(normal1, normal1) > tiny ? normal1 : outwardNormal;
  normal0 = dot(normal0, outwardNormal) < 0.0 ? -normal0 : normal0;
  normal1 = dot(normal1, outwardNormal) < 0.0 ? -normal1 : normal1;
  float t = 3.0e38;
  if (hits > 0 && h0 > after && dot(normal0, direction) < 0.0)
    t = h0;
  if (hits > 1 && h1 > after && dot(normal1, direction) < 0.0)
    t = min(t, h1);
  if (hits == 0)
  {
    if (dot(outwardNormal, direction) >= 0.0)
    {
      discard; // the ray leaves the mesh here
    }
    // Rasterisation put this pixel on this face, the exact patch just misses it (its centre is
    // within rounding of the face's edge): take the triangle's point; the walk sorts out the cell.
    float nearby = dot(modelPosition - origin, direction);
    t = nearby > after ? nearby : t;
  }
  if (!(t < 3.0e38))
  {
    discard; // traversed already
  }
  vec4 clip = modelToClip * vec4(origin + t * direction, 1.0);
  gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
  gl_FragData[0] = vec4(t, float(boundaryFace), 0.0, 1.0);
}
