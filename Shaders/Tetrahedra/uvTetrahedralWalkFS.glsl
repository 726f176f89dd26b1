//VTK::System::Dec
//VTK::Output::Dec
// vtkPreIntegratedTetrahedraMapper, ray-casting route: per pixel, full screen, the ray walks the
// tetrahedra by face adjacency from the boundary face the entry pass found, integrating each
// segment as the projected route's fragments do, front to back, until it leaves the mesh, reaches
// the opacity threshold or opaque geometry. Output 0: the peel's premultiplied colour (blended under
// what earlier peels left); output 1: where the ray left the mesh (ray parameter, 1, the boundary
// face it entered by), for the next peel's entry pass, or nothing (cleared to 0: done).
//
// Exit faces come from the signs of Plücker products (the ray against each edge, as a triple
// product relative to the ray's origin), each edge's computed from its lower point id first, so the
// two tetrahedra sharing a face find the same numbers for it: the walk cannot slip between them,
// and the exit point one finds (the products are its barycentric weights on the face) is the entry
// point of the next, carried on rather than computed again.
uniform sampler2D entry;              // (boundary face, ray parameter), or green < 0: no entry
uniform isamplerBuffer boundaryFaces; // tetrahedron * 4 + the corner opposite the face
uniform usamplerBuffer tetrahedronPoints;
uniform samplerBuffer pointData;      // recentred position, normalised scalar
uniform isamplerBuffer faceNeighbours; // per corner: neighbour * 4 + its corner opposite the shared face, or -1
uniform vec3 nearPlane[3];
uniform vec3 rayDirection[3];
uniform vec2 viewportSize;
uniform mat4 modelToEye;
uniform float opacityThreshold;
uniform int maximumSteps;
#ifdef UV_OPAQUE_DEPTH
uniform sampler2D opaqueDepth; // the scene's depth buffer before the volume
uniform mat4 clipToModel;
#endif
#ifdef UV_GRADIENTS
uniform samplerBuffer pointGradients;
uniform mat3 modelToEyeNormals;
#endif

//UV::EyeRay

//UV::TransferFunction

//UV::Phong

//UV::SegmentIntegration

#ifdef UV_SEGMENT_TABLE
//UV::SegmentLengthTable
#endif

//UV::TetrahedralWalk

/// One tetrahedron as the walk sees it: corners relative to the ray's origin, their scalars and
/// their distances along the ray, and the ray's products with its six edges (i to j, i < j locally:
/// 01, 02, 03, 12, 13, 23).
struct WalkedTetrahedron
{
  uvec4 ids;
  vec3 corner[4];
  vec4 scalars;
  vec4 along;
  float edges[6];
};

WalkedTetrahedron LoadTetrahedron(int cell, vec3 origin, vec3 direction)
{
  WalkedTetrahedron t;
  t.ids = texelFetch(tetrahedronPoints, cell);
  for (int k = 0; k < 4; ++k)
  {
    vec4 data = texelFetch(pointData, int(t.ids[k]));
    t.corner[k] = data.xyz - origin;
    t.scalars[k] = data.w;
    t.along[k] = dot(t.corner[k], direction);
  }
  t.edges[0] = EdgeProduct(t.corner[0], t.corner[1], direction);
  t.edges[1] = EdgeProduct(t.corner[0], t.corner[2], direction);
  t.edges[2] = EdgeProduct(t.corner[0], t.corner[3], direction);
  t.edges[3] = EdgeProduct(t.corner[1], t.corner[2], direction);
  t.edges[4] = EdgeProduct(t.corner[1], t.corner[3], direction);
  t.edges[5] = EdgeProduct(t.corner[2], t.corner[3], direction);
  return t;
}

/// The ray's products with the edges of the face opposite `corner`, around it outward for a
/// positive tetrahedron, each standing at the corner it does not touch: the (unnormalised)
/// barycentric weights of the ray's crossing of the face's plane, 0 at `corner`. All >= 0 (times
/// the sign of the volume) where the ray leaves through the face, all <= 0 where it enters.
vec4 FaceWeights(WalkedTetrahedron t, int corner)
{
  if (corner == 0)
    return vec4(0.0, t.edges[5], -t.edges[4], t.edges[3]);
  if (corner == 1)
    return vec4(-t.edges[5], 0.0, t.edges[2], -t.edges[1]);
  if (corner == 2)
    return vec4(t.edges[4], -t.edges[2], 0.0, t.edges[0]);
  return vec4(-t.edges[3], t.edges[1], -t.edges[0], 0.0);
}

/// Normalised weights (a ray parallel to the face, all 0: its centre).
vec4 Normalised(vec4 weights)
{
  float sum = weights.x + weights.y + weights.z + weights.w;
  return sum != 0.0 ? weights / sum : vec4(1.0 / 3.0);
}

/// The face the ray leaves by, not the one it entered by: the one whose least weight (oriented) is
/// largest, so rounding at an edge still picks a face and the walk goes on (-1 when no weight
/// compares). The orientation comes from the entry face's weights (of the sign opposite to leaving),
/// not from the volume, whose sign rounding can flip on a sliver: the walk then keeps to the signs
/// its neighbours saw.
int ExitCorner(WalkedTetrahedron t, int entered, out vec4 weights)
{
  float orientation = dot(FaceWeights(t, entered), vec4(1.0)) > 0.0 ? -1.0 : 1.0;
  int best = -1;
  float bestLeast = -3.0e38;
  for (int k = 0; k < 4; ++k)
  {
    if (k == entered)
      continue;
    vec4 w = FaceWeights(t, k) * orientation;
    w[k] = 3.0e38;
    float least = min(min(w.x, w.y), min(w.z, w.w));
    if (least > bestLeast)
    {
      bestLeast = least;
      best = k;
    }
  }
  // No face at all: every weight is NaN (non-finite corners). -1, and the walk ends there.
  weights = best >= 0 ? Normalised(FaceWeights(t, best)) : vec4(1.0 / 3.0);
  return best;
}

#ifdef UV_GRADIENTS
vec3 GradientAt(WalkedTetrahedron t, vec4 weights)
{
  vec3 g = vec3(0.0);
  for (int k = 0; k < 4; ++k)
    g += weights[k] * texelFetch(pointGradients, int(t.ids[k])).xyz;
  return modelToEyeNormals * g;
}
#endif

/// The ray parameter of the scene's opaque geometry at this pixel (3e38 where there is none).
float OpaqueParameter(vec3 origin, vec3 direction)
{
#ifdef UV_OPAQUE_DEPTH
  float depth = texelFetch(opaqueDepth, ivec2(gl_FragCoord.xy), 0).r;
  if (depth >= 1.0)
    return 3.0e38;
  vec4 p = clipToModel * vec4(PixelNdc(gl_FragCoord.xy, viewportSize), 2.0 * depth - 1.0, 1.0);
  return dot(p.xyz / p.w - origin, direction);
#else
  return 3.0e38;
#endif
}

void main()
{
  vec4 entered = texelFetch(entry, ivec2(gl_FragCoord.xy), 0);
  if (entered.g < 0.0)
  {
    discard;
  }
  vec3 origin, direction;
  EyeRay(PixelNdc(gl_FragCoord.xy, viewportSize), nearPlane, rayDirection, origin, direction);
  // Lengths in eye units, as the projected route's (the volume's matrix may scale).
  float eyeUnits = length(mat3(modelToEye) * direction);
  vec3 toEye = normalize(-(mat3(modelToEye) * direction));
  float opaqueAt = OpaqueParameter(origin, direction);

  // Ray parameters from the entry point on: the products' terms then stay about the size of the
  // mesh rather than of the camera's distance, and so do their rounding errors (the products do
  // not change as the origin moves along the ray).
  float base = entered.g;
  vec3 start = origin + base * direction;
  float nearAt = -base;
  opaqueAt -= base;
  int record = texelFetch(boundaryFaces, int(entered.r)).r;
  int cell = record >> 2, enteredBy = record & 3;
  WalkedTetrahedron t = LoadTetrahedron(cell, start, direction);
  vec4 weights = Normalised(FaceWeights(t, enteredBy));
  float frontAt = dot(weights, t.along), frontScalar = dot(weights, t.scalars);
  vec3 frontGradient = vec3(0.0), backGradient = vec3(0.0);
#ifdef UV_GRADIENTS
  frontGradient = GradientAt(t, weights);
#endif
  vec4 result = vec4(0.0);
  float leftAt = 0.0, leaves = 0.0;
  for (int walked = 0; walked < maximumSteps; ++walked)
  {
    int exitCorner = ExitCorner(t, enteredBy, weights);
    if (exitCorner < 0)
    {
      leftAt = base + frontAt;
      leaves = 1.0; // lost here: the next peel may pick the ray up beyond
      break;
    }
    float backAt = dot(weights, t.along), backScalar = dot(weights, t.scalars);
#ifdef UV_GRADIENTS
    backGradient = GradientAt(t, weights);
#endif
    // The part of the segment beyond the near plane and before opaque geometry.
    float from = max(frontAt, nearAt), to = min(backAt, opaqueAt);
    if (to > from)
    {
      float span = backAt - frontAt;
      float u0 = span > 0.0 ? (from - frontAt) / span : 0.0, u1 = span > 0.0 ? (to - frontAt) / span : 1.0;
      float s0 = mix(frontScalar, backScalar, u0), s1 = mix(frontScalar, backScalar, u1);
      float segmentLength = (to - from) * eyeUnits;
#ifdef UV_SEGMENT_TABLE
      vec4 segment = TableSegment(s0, s1, segmentLength);
#else
      vec4 segment = IntegrateSegment(s0, s1, mix(frontGradient, backGradient, u0),
        mix(frontGradient, backGradient, u1), segmentLength, toEye);
#endif
      result += (1.0 - result.a) * segment;
      if (result.a >= opacityThreshold)
        break;
    }
    if (backAt >= opaqueAt)
      break;
    int next = texelFetch(faceNeighbours, cell)[exitCorner];
    if (next < 0)
    {
      leftAt = base + backAt;
      leaves = 1.0; // through the boundary: the next peel may pick the ray up
      break;
    }
    cell = next >> 2;
    enteredBy = next & 3;
    frontAt = backAt;
    frontGradient = backGradient;
    t = LoadTetrahedron(cell, start, direction);
    // The entry scalar from the new tetrahedron's own corners: a cell scalar jumps at the face.
    frontScalar = dot(Normalised(FaceWeights(t, enteredBy)), t.scalars);
  }
  gl_FragData[0] = result;
  gl_FragData[1] = vec4(leftAt, leaves, entered.r, leaves);
}
