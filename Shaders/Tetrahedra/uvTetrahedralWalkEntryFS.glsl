//VTK::System::Dec
//VTK::Output::Dec
// vtkPreIntegratedTetrahedraMapper, ray-casting route, entry pass: per pixel the nearest boundary
// face the eye ray enters the mesh by, beyond where the previous walk left it (depth peeling: a ray
// that leaves a non-convex mesh, or crosses a hole or a gap between cells, is picked up again by the
// next peel). The test is exact, by the walk's own Plücker products (two boundary faces sharing an
// edge leave no crack between them), and the ray parameter the same the walk computes. Writes
// (boundary face, ray parameter); the depth test, on a depth made from that parameter, keeps the
// nearest.
flat in int boundaryFace;
flat in vec3 faceCorners[3];
flat in vec3 outwardNormal;

uniform vec3 nearPlane[3];
uniform vec3 rayDirection[3];
uniform vec2 viewportSize;
uniform mat4 modelToClip;
// The previous walk: (ray parameter where it left the mesh, 1, the face it entered by), or 0: done.
uniform sampler2D previousExit;
uniform int firstPeel;
uniform vec3 boundsLow; // the mesh's bounding box
uniform vec3 boundsHigh;

//UV::EyeRay

//UV::TetrahedralWalk

void main()
{
  float after = -3.0e38;
  if (firstPeel == 0)
  {
    vec4 exit = texelFetch(previousExit, ivec2(gl_FragCoord.xy), 0);
    if (!(exit.g > 0.5) || boundaryFace == int(exit.b))
    {
      // The ray stopped for good (opaque, at opaque geometry, or never entered), or this is the
      // face the last walk began at: a piece thinner than the margin below would be walked again.
      discard;
    }
    after = exit.r;
  }
  vec3 origin, direction;
  EyeRay(PixelNdc(gl_FragCoord.xy, viewportSize), nearPlane, rayDirection, origin, direction);
  // The products from a point of the ray near the mesh, the same for every face at this pixel (so
  // faces sharing an edge agree on it bitwise): where the ray enters the mesh's box, or where the
  // last walk left. From the near plane they would be rounded at the scale of the camera's
  // distance rather than of the mesh.
  float from = after;
  if (firstPeel == 1)
  {
    vec3 inverse = 1.0 / direction;
    vec3 low = (boundsLow - origin) * inverse, high = (boundsHigh - origin) * inverse;
    vec3 near = min(low, high);
    from = max(max(near.x, near.y), max(near.z, 0.0));
  }
  vec3 start = origin + from * direction;
  vec3 p[3];
  float along[3];
  for (int k = 0; k < 3; ++k)
  {
    p[k] = faceCorners[k] - start;
    along[k] = dot(p[k], direction);
  }
  // The walk's products around the face, each at the corner it does not touch: through the face
  // where none has the other sign; entering where the face looks at the ray.
  vec3 weights = vec3(EdgeProduct(p[1], p[2], direction), EdgeProduct(p[2], p[0], direction),
    EdgeProduct(p[0], p[1], direction));
  float sum = weights.x + weights.y + weights.z;
  vec3 oriented = weights * sign(sum);
  if (!(min(oriented.x, min(oriented.y, oriented.z)) >= 0.0) || !(dot(outwardNormal, direction) < 0.0))
  {
    discard;
  }
  float at = from + dot(weights / sum, vec3(along[0], along[1], along[2]));
  // A face touching the exit point counts (cells meeting there without sharing the face), by a
  // margin in proportion to the distance and the tetrahedron; the face just left faces away.
  float wall = 1e-5 * (abs(after) + abs(along[0] - along[1]) + abs(along[0] - along[2]));
  if (!(at > after - wall))
  {
    discard;
  }
  gl_FragDepth =
    RayParameterDepth(at, dot(0.5 * (boundsLow + boundsHigh) - origin, direction), 0.5 * length(boundsHigh - boundsLow));
  gl_FragData[0] = vec4(float(boundaryFace), at, 0.0, 1.0);
}
