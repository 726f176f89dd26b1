//VTK::System::Dec
//VTK::Output::Dec
// vtkPreIntegratedTetrahedraMapper, fragment stage: the ray segment through one tetrahedron, from
// its front to its back face, integrated and written premultiplied (blended back to front with
// ONE, ONE_MINUS_SRC_ALPHA into a float image).
//
// The scalar is linear along the segment. PartialPreIntegration cuts the segment where the scalar
// crosses a transfer-function node, so extinction and colour are linear on each piece, and
// integrates each piece exactly with the Psi table (uvPreIntegration.h is the CPU twin). AverageScalar
// uses the transfer function at the mean scalar for the whole segment (the paper's basic mode).
// Isosurfaces are further cuts: at each one the segment composites the surface's colour, lit
// (Phong) with the gradient interpolated between the front and back points. With UV_SEGMENT_TABLE
// (no isosurfaces, no shading) one trilinear read of a table of whole segments by front scalar, back
// scalar and length (uvTetrahedronSegmentTable.h) stands in for the cuts.
//
// The segment's ends come one of two ways. UV_FACES (the vertex-pulling route): the fragment lies on
// a face of its tetrahedron (uvBarycentricPullVS.glsl draws its back faces, or its one front face)
// and finds entry and exit from its barycentric coordinates along the ray (uvBarycentricRayLib.glsl,
// shared with vtkBarycentricShellMapper). Otherwise (the geometry-shader route's fan around the
// thick vertex) they are interpolated over the fan's triangles.
#ifdef UV_FACES
//UV::BarycentricRay
#define fragmentTetrahedron cellId
#else
smooth in vec3 frontData; // (scalar, eye z, 1) / w on the front surface
smooth in vec3 backData;
#ifdef UV_GRADIENTS
smooth in vec3 frontGradientOverW;
smooth in vec3 backGradientOverW;
#endif
flat in int rayCastTetrahedron;  // >= 0: intersect the eye ray with this tetrahedron here (UV_NEAR_PLANE_CUTS)
#ifdef UV_CELL_SURFACES
flat in int fragmentTetrahedron;
#endif
uniform int parallelProjection;
#ifdef UV_NEAR_PLANE_CUTS
uniform float nearDepth; // where rays begin
#endif
#endif
// The eye ray at pixel (x, y) is affine in it: perspective, its direction is (dot(rayX, (x, y, 1)),
// dot(rayY, (x, y, 1)), -1) from the eye; parallel, its origin is (those, 0) and it runs along -z.
uniform vec3 rayX;
uniform vec3 rayY;
#ifdef UV_GRADIENTS
uniform samplerBuffer pointGradients;
uniform mat3 modelToEyeNormals;
#endif
#ifdef UV_CELL_SURFACES
// A cell scalar's isosurfaces, the faces between cells on either side of the value: each
// tetrahedron draws those on its front face (the one the ray enters by), over its own segment.
uniform samplerBuffer neighbourValues; // per tetrahedron, the value across the face opposite each corner
#endif

uniform usamplerBuffer tetrahedronPoints;
uniform samplerBuffer pointData;
uniform mat4 modelToEye;
#ifdef UV_OPAQUE_DEPTH
uniform sampler2D opaqueDepth;      // the scene's depth buffer before the volume
uniform mat4 clipToEye;
uniform vec2 viewportSize;
#endif

#ifdef UV_OPAQUE_DEPTH
/// The eye depth (-z) of the opaque geometry in this fragment's pixel (the far plane where none).
float OpaqueEyeDepth()
{
  vec2 ndc = gl_FragCoord.xy / viewportSize * 2.0 - 1.0;
  float depth = texelFetch(opaqueDepth, ivec2(gl_FragCoord.xy), 0).r;
  vec4 opaque = clipToEye * vec4(ndc, 2.0 * depth - 1.0, 1.0);
  return -opaque.z / opaque.w;
}
#endif

//UV::TransferFunction

//UV::Phong

//UV::SegmentIntegration

#ifdef UV_SEGMENT_TABLE
//UV::SegmentLengthTable
#endif

#ifdef UV_CELL_SURFACES
/// The surfaces on the front face of the drawn tetrahedron where the ray along `direction` enters
/// it at eye point `front` (seen along `toEye`), composited in the order the ray meets them:
/// premultiplied colour and alpha. None where `front` is on no face (the near plane cut the
/// tetrahedron there).
vec4 FrontFaceSurfaces(vec3 front, vec3 direction, vec3 toEye)
{
  uvec4 ids = texelFetch(tetrahedronPoints, fragmentTetrahedron);
  vec3 p[4];
  float value = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    vec4 data = texelFetch(pointData, int(ids[k]));
    p[k] = (modelToEye * vec4(data.xyz, 1.0)).xyz;
    value = data.w; // constant in the tetrahedron
  }
  // Barycentric weights at the front point, and how each changes along the ray. The ray enters by
  // the last face plane it crosses inwards: of the corners whose weight grows, the one whose weight
  // is least (0, up to rounding; the other entering planes lie behind it, their weights already
  // grown). Away from 0 the front point is on the near plane, on no face.
  mat3 toLocal = inverse(mat3(p[1] - p[0], p[2] - p[0], p[3] - p[0]));
  vec3 l = toLocal * (front - p[0]), dl = toLocal * direction;
  float weights[4] = float[4](1.0 - l.x - l.y - l.z, l.x, l.y, l.z);
  float growth[4] = float[4](-dl.x - dl.y - dl.z, dl.x, dl.y, dl.z);
  int corner = -1;
  for (int k = 0; k < 4; ++k)
    if (growth[k] > 0.0 && (corner < 0 || weights[k] < weights[corner]))
      corner = k;
  if (corner < 0 || abs(weights[corner]) > 1e-3)
    return vec4(0.0);
  float from = texelFetch(neighbourValues, fragmentTetrahedron)[corner];
  vec3 normal = cross(p[(corner + 2) % 4] - p[(corner + 1) % 4], p[(corner + 3) % 4] - p[(corner + 1) % 4]);
  return SurfacesBetweenCells(from, value, normal, toEye);
}
#endif

#if !defined(UV_FACES) && defined(UV_NEAR_PLANE_CUTS)
/// A tetrahedron too near to project (rayCastTetrahedron): the ray's segment through it, from its
/// four faces; false where the ray misses it.
bool RayCastSegment(vec3 origin, vec3 direction, out vec3 frontPoint, out vec3 backPoint, out float frontScalar,
  out float backScalar, out vec3 frontGradient, out vec3 backGradient)
{
  uvec4 ids = texelFetch(tetrahedronPoints, rayCastTetrahedron);
  vec3 p[4];
  float s[4];
  vec3 g[4];
  for (int k = 0; k < 4; ++k)
  {
    vec4 data = texelFetch(pointData, int(ids[k]));
    p[k] = (modelToEye * vec4(data.xyz, 1.0)).xyz;
    s[k] = data.w;
#ifdef UV_GRADIENTS
    g[k] = modelToEyeNormals * texelFetch(pointGradients, int(ids[k])).xyz;
#else
    g[k] = vec3(0.0);
#endif
  }
  // Ray parameter: eye depth (direction.z = -1); the ray begins on the near plane, as in the
  // reference, so matter between the eye and that plane is not seen.
  float enter = nearDepth, leave = 3.0e38;
  for (int k = 0; k < 4; ++k)
  {
    vec3 a = p[(k + 1) % 4], b = p[(k + 2) % 4], c = p[(k + 3) % 4];
    vec3 n = cross(b - a, c - a);
    n = dot(n, p[k] - a) > 0.0 ? -n : n; // outward
    float along = dot(n, direction);
    float at = dot(n, origin - a);
    if (along < 0.0)
      enter = max(enter, -at / along);
    else if (along > 0.0)
      leave = min(leave, -at / along);
    else if (at > 0.0)
      return false;
  }
  if (!(enter < leave))
  {
    return false;
  }
  frontPoint = origin + enter * direction;
  backPoint = origin + leave * direction;
  // Barycentric weights of both points give scalar and gradient.
  mat3 edges = mat3(p[1] - p[0], p[2] - p[0], p[3] - p[0]);
  mat3 toLocal = inverse(edges);
  vec3 lf = toLocal * (frontPoint - p[0]), lb = toLocal * (backPoint - p[0]);
  vec4 wf = vec4(1.0 - lf.x - lf.y - lf.z, lf), wb = vec4(1.0 - lb.x - lb.y - lb.z, lb);
  frontScalar = dot(wf, vec4(s[0], s[1], s[2], s[3]));
  backScalar = dot(wb, vec4(s[0], s[1], s[2], s[3]));
  frontGradient = wf.x * g[0] + wf.y * g[1] + wf.z * g[2] + wf.w * g[3];
  backGradient = wb.x * g[0] + wb.y * g[1] + wb.z * g[2] + wb.w * g[3];
  return true;
}
#endif

#if defined(UV_OPAQUE_DEPTH) && !defined(UV_FACES)
/// Opaque geometry: nothing behind it; a segment it cuts ends there. False when the segment lies
/// wholly behind it.
bool EndAtOpaqueGeometry(vec3 frontPoint, float frontScalar, vec3 frontGradient, inout vec3 backPoint,
  inout float backScalar, inout vec3 backGradient, inout float segmentLength)
{
  float opaqueZ = -OpaqueEyeDepth();
  if (frontPoint.z <= opaqueZ)
  {
    return false;
  }
  if (backPoint.z < opaqueZ)
  {
    float u = (frontPoint.z - opaqueZ) / (frontPoint.z - backPoint.z);
    backPoint = mix(frontPoint, backPoint, u);
    backScalar = mix(frontScalar, backScalar, u);
    backGradient = mix(frontGradient, backGradient, u);
    segmentLength *= u;
  }
  return true;
}
#endif

void main()
{
  vec3 frontPoint, backPoint;
  float frontScalar, backScalar;
  vec3 frontGradient = vec3(0.0), backGradient = vec3(0.0);
  float segmentLength;
#ifdef UV_RAY_ATTRIBUTE
  vec2 ray = pixelRay; // the same ray, carried by the face: cheaper on CPU rasterisers
#else
  vec2 ray = vec2(dot(rayX, vec3(gl_FragCoord.xy, 1.0)), dot(rayY, vec3(gl_FragCoord.xy, 1.0)));
#endif
#ifdef UV_FACES
  // Offsets in eye depth from the fragment's point on the face (uvBarycentricRayLib.glsl).
  vec3 direction = parallelProjection == 1 ? vec3(0.0, 0.0, -1.0) : vec3(ray, -1.0);
  FaceRay faceRay = FragmentFaceRay();
  float entry = EntryOffset(faceRay), exit = ExitOffset(faceRay);
  float faceDepth = FaceDepth();
#ifdef UV_NEAR_PLANE_CUTS
  // Only compiled in when the near plane cuts the mesh's bounds: rays begin there.
  entry = max(entry, nearDepth - faceDepth);
#endif
#ifdef UV_OPAQUE_DEPTH
  // Opaque geometry ends the ray: the exit moves up to it, and the scalars, length and gradients
  // below follow from the moved exit. (A segment wholly behind it is discarded just below.)
  exit = min(exit, OpaqueEyeDepth() - faceDepth);
#endif
  if (!(entry < exit))
  {
    discard;
  }
  vec4 frontWeights = faceRay.face + entry * faceRay.rate, backWeights = faceRay.face + exit * faceRay.rate;
  frontScalar = dot(cellScalars, frontWeights);
  backScalar = dot(cellScalars, backWeights);
  // Perspective: a unit of depth is |direction| of length along the ray.
  segmentLength = (exit - entry) * (parallelProjection == 1 ? 1.0 : length(direction));
  vec3 origin = parallelProjection == 1 ? vec3(ray, 0.0) : vec3(0.0);
  frontPoint = origin + (faceDepth + entry) * direction;
  backPoint = origin + (faceDepth + exit) * direction;
#ifdef UV_GRADIENTS
  VertexGradientsAt(tetrahedronPoints, pointGradients, modelToEyeNormals, cellId, frontWeights, backWeights,
    frontGradient, backGradient);
#endif
#else
  vec3 origin = parallelProjection == 1 ? vec3(ray, 0.0) : vec3(0.0);
  vec3 direction = parallelProjection == 1 ? vec3(0.0, 0.0, -1.0) : vec3(ray, -1.0);
#ifdef UV_NEAR_PLANE_CUTS
  // Only compiled in when the near plane cuts the mesh's bounds: CPU rasterisers pay for a branch's
  // body in every fragment, taken or not.
  if (rayCastTetrahedron >= 0)
  {
    if (!RayCastSegment(origin, direction, frontPoint, backPoint, frontScalar, backScalar, frontGradient,
          backGradient))
    {
      discard;
    }
  }
  else
#endif
  {
    // Each surface's (scalar, z, 1) / w interpolates linearly on screen: divide back out.
    frontScalar = frontData.x / frontData.z;
    backScalar = backData.x / backData.z;
    float frontZ = frontData.y / frontData.z, backZ = backData.y / backData.z;
    frontPoint = origin + -frontZ * direction;
    backPoint = origin + -backZ * direction;
#ifdef UV_GRADIENTS
    frontGradient = frontGradientOverW / frontData.z;
    backGradient = backGradientOverW / backData.z;
#endif
  }
  segmentLength = distance(frontPoint, backPoint);
#endif

#if defined(UV_OPAQUE_DEPTH) && !defined(UV_FACES)
  // (Only compiled in where the scene may have drawn opaque geometry: the read and unprojection are
  // a large share of a cheap fragment.)
  if (!EndAtOpaqueGeometry(frontPoint, frontScalar, frontGradient, backPoint, backScalar, backGradient,
        segmentLength))
  {
    discard;
  }
#endif
#ifdef UV_SEGMENT_TABLE
  vec4 result = TableSegment(frontScalar, backScalar, segmentLength);
#else
  vec3 toEye = parallelProjection == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-frontPoint);
  vec4 result = IntegrateSegment(frontScalar, backScalar, frontGradient, backGradient, segmentLength, toEye);
#endif
#ifdef UV_CELL_SURFACES
  vec4 surfaces = FrontFaceSurfaces(frontPoint, direction, toEye);
  result = surfaces + (1.0 - surfaces.a) * result;
#endif
  if (!(result.a > 0.0))
  {
    discard;
  }
  gl_FragData[0] = result;
}
