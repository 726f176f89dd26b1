//VTK::System::Dec
//VTK::Output::Dec
// vtkHexahedralRayCastMapper, entry pass: keeps, per pixel, the nearest boundary face where the eye
// ray enters the mesh beyond where the previous traversal left it (depth peeling: a ray that leaves
// a non-convex mesh or crosses a hole is picked up again by the next peel).
in vec3 modelPosition;
flat in int boundaryFace;
flat in vec3 outwardNormal;
flat in int tangled; // the face's cell folds over itself (uvHexahedralEntryVS.glsl)
flat in int widening; // from a triangle of the face's other diagonal (uvHexahedralEntryVS.glsl)

uniform vec3 nearPlane[3];    // the rays (EyeRay)
uniform vec3 rayDirection[3];
uniform isamplerBuffer boundaryFaces;
uniform vec2 viewportSize;
uniform sampler2D previousExit; // the previous peel's traversal: where and how it stopped, the
                                // boundary face it entered by
uniform int firstPeel;
uniform float meshRadius;       // the mesh's bounding radius about the model origin (its centre)

//UV::BilinearFace

//UV::Hexahedron

/// The boundary face as the exact bilinear patch or triangle, parameterised as every cell sharing it
/// would, and the cell it bounds; returns its corner count.
int BoundaryPatch(out vec3 a, out vec3 b, out vec3 c, out vec3 d, out int cell)
{
  ivec4 cellFace = texelFetch(boundaryFaces, boundaryFace);
  cell = cellFace.x;
  uint cellIds[8];
  CellPointIds(cellFace.x, cellIds);
  vec3 q[4];
  uint qi[4];
  for (int k = 0; k < 4; ++k)
  {
    qi[k] = cellIds[FaceCorner(cellFace.y, k)];
    q[k] = PointPosition(qi[k]);
  }
  return CanonicalFace(q, qi, a, b, c, d);
}

/// The nearest ray parameter beyond `after` where the ray enters the mesh through the patch (with
/// `anyCrossing`, or leaves it beyond t = 0: `leaving`), or 3e38.
float EntryParameter(vec3 origin, vec3 direction, vec3 a, vec3 b, vec3 c, vec3 d, int corners, float after,
  bool anyCrossing, out bool leaving)
{
  leaving = false;
  float h0, h1;
  vec3 n0, n1;
  int hits = HitFace(origin, direction, a, b, c, d, corners, h0, h1, n0, n1);
  if (hits == 0)
  {
    // Rasterisation put this pixel on this face's own triangles, the exact patch just misses it (its
    // centre is within rounding of the face's edge): take the triangle's point where the ray enters
    // here; the walk sorts out the cell. The other diagonal's triangles reach beyond the patch where
    // it is curved: a miss there is a miss.
    float nearby = dot(modelPosition - origin, direction);
    return widening == 0 && dot(outwardNormal, direction) < 0.0 && nearby > after ? nearby : 3.0e38;
  }
  // Only where the ray enters the mesh: the patch's own normal there, turned outward (a curved
  // boundary face can be entered on one part and left on another).
  vec3 centreNormal = PatchNormalAt(a, b, c, d, vec2(0.5));
  vec3 normal0 = OutwardNormalAt(n0, centreNormal, outwardNormal);
  vec3 normal1 = OutwardNormalAt(n1, centreNormal, outwardNormal);
  // Leaving faces only beyond the near-plane point (t = 0), which the traversal walks back to. A folded
  // cell's face may be entered either way: the traversal finds where the cell's part starts
  // (FindExitThroughParts).
  bool leaves0 = tangled == 0 && dot(normal0, direction) >= 0.0;
  bool leaves1 = tangled == 0 && dot(normal1, direction) >= 0.0;
  float t = 3.0e38;
  if (h0 > after && (!leaves0 || (anyCrossing && h0 > 0.0)))
  {
    t = h0;
    leaving = leaves0;
  }
  if (hits > 1 && h1 > after && h1 < t && (!leaves1 || (anyCrossing && h1 > 0.0)))
  {
    t = h1;
    leaving = leaves1;
  }
  return t;
}

void main()
{
  // A later peel starts where the last walk stopped (uvHexahedralTraverseFS.glsl's stopKind); a ray
  // that stopped for good (opaque, or no entry) is done before its face is fetched. Where the walk
  // left the mesh through a boundary face, or lost the ray at an edge, a face entered right there
  // counts too: the other side of an internal wall of the mesh (two layers of cells on coincident,
  // unshared points), whose crossing rounds to either side of the stop -- but not the face the lost
  // walk entered by, which would lose it again.
  vec4 exit = texelFetch(previousExit, ivec2(gl_FragCoord.xy), 0);
  if (firstPeel == 0 && (!(exit.r < 3.0e38) || (exit.g > 1.5 && exit.g < 2.5 && boundaryFace == int(exit.b))))
    discard;
  vec3 origin, direction;
  EyeRay(PixelNdc(gl_FragCoord.xy, viewportSize), nearPlane, rayDirection, origin, direction);
  vec3 a, b, c, d;
  int cell;
  int corners = BoundaryPatch(a, b, c, d, cell);
  // In proportion to the ray parameter and the face, not absolute: meshes of any size and distance.
  float wall = exit.g > 0.5 ? 1e-5 * (abs(exit.r) + length(c - a)) : 0.0;
  float after = firstPeel == 1 ? -3.0e38 : exit.r - wall;
  // Not back into the cell the walk left the mesh from, where it left it (exit.a, -1: none); further
  // on, a curved face of that cell may be entered again.
  if (firstPeel == 0 && exit.g > 0.5 && exit.g < 1.5 && cell == int(exit.a))
    after = exit.r + wall;
  // Where the first peel did not locate the ray's near-plane point (uvHexahedralTraverseFS.glsl's
  // UNLOCATED), the nearest crossing of either kind: where the ray leaves, the point is in the mesh.
  bool leaving;
  float t = EntryParameter(origin, direction, a, b, c, d, corners, after, firstPeel == 0 && exit.g > 2.5, leaving);
  if (!(t < 3.0e38))
  {
    discard; // the ray leaves the mesh here, or this face was traversed already
  }
  gl_FragDepth = RayParameterDepth(t, dot(-origin, direction), meshRadius); // the model origin is the centre
  gl_FragData[0] = vec4(t, float(boundaryFace), leaving ? 1.0 : 0.0, 1.0);
}
