// vtkBarycentricShellMapper: a fragment's ray in its tetrahedron's barycentric coordinates, from the
// attributes uvBarycentricTetrahedronLib.glsl emits (marker //UV::BarycentricRay). The GLSL twin of
// uvBarycentricShell.h: samples are taken from the face's own coordinates, b(z) = b_face + (z - l) b / l
// (ShellSampleFromFace), which keeps float's digits that the eye's large coordinates would cost.
// "Distance" z is the eye distance under perspective (spherical shells) and the depth -z_eye under
// parallel projection (planar ones).
//
// With UV_DEPTH_RAY (vtkPreIntegratedTetrahedraMapper) the ray is measured instead in eye depth from
// the fragment's point on the face: every quantity is an offset from that point, so the eye's
// distance is neither added nor cancelled, and the fragment needs no eye-space position at all.
#ifndef UV_DEPTH_RAY
in vec3 eyePosition;
#endif
in vec4 faceCoordinates;
in vec4 rayDirection; // parallel projection: the coordinates' change per unit along -z
flat in vec4 cellScalars;
flat in int cellId;
#ifdef UV_RAY_ATTRIBUTE
noperspective in vec2 pixelRay; // the eye ray through this pixel (uvBarycentricTetrahedronLib.glsl)
#endif
#ifdef UV_CELL_GRADIENTS
flat in vec3 cellGradient;
#endif
#ifdef UV_TEXTURE
flat in mat4 cellTextureCoordinates;
uniform sampler3D volumeTexture;  // the bound image, normalised scalar
uniform vec3 volumeTextureSize;   // its points along each axis

/// The image's value at barycentric coordinates b of this fragment's tetrahedron: texture coordinates
/// 0 and 1 are the image's first and last points (texel centres).
float ImageScalarAt(vec4 b)
{
  vec3 coordinates = (cellTextureCoordinates * b).xyz;
  return textureLod(volumeTexture, (coordinates * (volumeTextureSize - 1.0) + 0.5) / volumeTextureSize, 0.0).r;
}
#endif

uniform int parallelProjection;
uniform float nearDepth; // eye-space depth of the near clipping plane, where rays begin
#ifdef UV_OPAQUE_GEOMETRY
uniform sampler2D opaqueDistances; // r: the distance of the scene's opaque geometry, per pixel
#endif

/// The least rate of change along the ray that lets a coordinate set the entry or the exit. A ray
/// lying in a face's plane changes that face's coordinate only by rounding, which may give it either
/// sign and put its zero anywhere along the ray, dropping the segment; yet the coordinate stays
/// within rounding of its value at the fragment's point, which the rasteriser found inside the
/// tetrahedron, so it bounds nothing. A coordinate this much slower than the fastest changes by a
/// negligible fraction of the tetrahedron over the whole segment.
float RateFloor(vec4 rate)
{
  vec4 size = abs(rate);
  return 1e-5 * max(max(size.x, size.y), max(size.z, size.w));
}

#ifdef UV_DEPTH_RAY
/// A fragment's ray from its point on the face: the barycentric coordinates there and their change per
/// unit of eye depth. Perspective: rayDirection is M^-1 applied to the eye-space point, exact under
/// perspective-correct interpolation, and the ray through that point has depth rate point / depth;
/// gl_FragCoord.w is 1 / depth. Parallel: rayDirection already is the rate, and gl_FragCoord.w is 1.
struct FaceRay
{
  vec4 face;
  vec4 rate;
};

FaceRay FragmentFaceRay()
{
  return FaceRay(faceCoordinates, rayDirection * gl_FragCoord.w);
}

/// The depth offsets from the face point at which each coordinate reaches 0 (infinite or NaN where
/// it does not change; the callers mask those out).
vec4 ZeroOffsets(FaceRay ray)
{
  return -ray.face / ray.rate;
}

/// Where the ray enters the tetrahedron: the last offset at which a growing coordinate is 0. (The
/// coordinates' rates sum to 0, so some coordinate grows and some falls.)
float EntryOffset(FaceRay ray)
{
  vec4 entries = mix(vec4(-3.0e38), ZeroOffsets(ray), greaterThan(ray.rate, vec4(RateFloor(ray.rate))));
  return max(max(entries.x, entries.y), max(entries.z, entries.w));
}

/// Where it leaves: the first offset at which a falling coordinate reaches 0 (about 0 on a back face).
float ExitOffset(FaceRay ray)
{
  vec4 exits = mix(vec4(3.0e38), ZeroOffsets(ray), lessThan(ray.rate, vec4(-RateFloor(ray.rate))));
  return min(min(exits.x, exits.y), min(exits.z, exits.w));
}

/// The eye depth of the fragment's point on the face. Parallel projection: affine in the window
/// depth, depth = windowDepthToEyeDepth.x * gl_FragCoord.z + windowDepthToEyeDepth.y.
uniform vec2 windowDepthToEyeDepth;
float FaceDepth()
{
  return parallelProjection == 1 ? windowDepthToEyeDepth.x * gl_FragCoord.z + windowDepthToEyeDepth.y
                                 : 1.0 / gl_FragCoord.w;
}
#else
struct BarycentricRay
{
  vec4 face;      // coordinates at the fragment's point on the face
  vec4 perUnit;   // their change per unit of distance
  float distance; // that point's distance
};

BarycentricRay FragmentRay()
{
  BarycentricRay ray;
  ray.face = faceCoordinates;
  ray.distance = parallelProjection == 1 ? -eyePosition.z : length(eyePosition);
  ray.perUnit = parallelProjection == 1 ? rayDirection : rayDirection / ray.distance;
  return ray;
}

vec4 CoordinatesAt(BarycentricRay ray, float z)
{
  return ray.face + (z - ray.distance) * ray.perUnit;
}

/// The distances at which each coordinate reaches 0 along the ray (infinite or NaN where it does
/// not change; the callers mask those out).
vec4 ZeroCrossings(BarycentricRay ray)
{
  return ray.distance - ray.face / ray.perUnit;
}

/// The distance along this fragment's ray of the near clipping plane.
float NearDistance(BarycentricRay ray)
{
  return parallelProjection == 1 ? nearDepth : nearDepth * ray.distance / max(-eyePosition.z, 1e-30);
}

/// Where the ray enters the tetrahedron: the last distance at which a coordinate growing along the
/// ray is 0, or the near plane where the tetrahedron begins in front of it.
float EntryDistance(BarycentricRay ray)
{
  vec4 entries = mix(vec4(0.0), ZeroCrossings(ray), greaterThan(ray.perUnit, vec4(RateFloor(ray.perUnit))));
  return max(max(entries.x, entries.y), max(max(entries.z, entries.w), NearDistance(ray)));
}

/// Where it leaves: the first distance at which a falling coordinate reaches 0. The fragment's own
/// distance on a back face, up to rounding; computed so any face of the tetrahedron will do.
float ExitDistance(BarycentricRay ray)
{
  vec4 exits = mix(vec4(3.0e38), ZeroCrossings(ray), lessThan(ray.perUnit, vec4(-RateFloor(ray.perUnit))));
  return min(min(exits.x, exits.y), min(exits.z, exits.w));
}

float SmallestCoordinate(vec4 b)
{
  return min(min(b.x, b.y), min(b.z, b.w));
}

/// The eye-space point at distance z along this fragment's ray.
vec3 EyePointAt(float z)
{
  return parallelProjection == 1 ? vec3(eyePosition.xy, -z) : eyePosition * (z / length(eyePosition));
}

#endif

/// Tetrahedron `cell`'s vertex gradients (`gradients` per point of `cellPoints`, model space) at
/// barycentric coordinates `front` and `back`, in eye space (`toEye`, the normal matrix).
void VertexGradientsAt(usamplerBuffer cellPoints, samplerBuffer gradients, mat3 toEye, int cell, vec4 front,
  vec4 back, out vec3 frontGradient, out vec3 backGradient)
{
  uvec4 ids = texelFetch(cellPoints, cell);
  frontGradient = backGradient = vec3(0.0);
  for (int k = 0; k < 4; ++k)
  {
    vec3 g = toEye * texelFetch(gradients, int(ids[k])).xyz;
    frontGradient += front[k] * g;
    backGradient += back[k] * g;
  }
}

/// The distance of the scene's opaque geometry along this pixel's ray (uvBarycentricOpaqueDistanceFS.glsl
/// computes them once a frame; a constant when the scene has none).
float OpaqueDistance()
{
#ifdef UV_OPAQUE_GEOMETRY
  return texelFetch(opaqueDistances, ivec2(gl_FragCoord.xy), 0).r;
#else
  return 3.0e38;
#endif
}
