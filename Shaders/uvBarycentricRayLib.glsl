// vtkBarycentricShellMapper: a fragment's ray in its tetrahedron's barycentric coordinates, from the
// attributes uvBarycentricTetrahedronLib.glsl emits (marker //UV::BarycentricRay). The GLSL twin of
// uvBarycentricShell.h: samples are taken from the face's own coordinates, b(z) = b_face + (z - l) b / l
// (ShellSampleFromFace), which keeps float's digits that the eye's large coordinates would cost.
// "Distance" z is the eye distance under perspective (spherical shells) and the depth -z_eye under
// parallel projection (planar ones).
in vec3 eyePosition;
in vec4 faceCoordinates;
in vec4 rayDirection;
flat in vec4 cellScalars;
flat in vec4 parallelPerUnit;
flat in int cellId;

uniform int parallelProjection;
uniform sampler2D opaqueDepth; // the scene's depth buffer before the volume
uniform mat4 clipToEye;
uniform vec2 viewportSize;

struct BarycentricRay
{
  vec4 face;    // coordinates at the fragment's point on the face
  vec4 perUnit; // their change per unit of distance
  float length; // that point's distance
};

BarycentricRay FragmentRay()
{
  BarycentricRay ray;
  ray.face = faceCoordinates;
  ray.length = parallelProjection == 1 ? -eyePosition.z : length(eyePosition);
  ray.perUnit = parallelProjection == 1 ? parallelPerUnit : rayDirection / ray.length;
  return ray;
}

vec4 CoordinatesAt(BarycentricRay ray, float z)
{
  return ray.face + (z - ray.length) * ray.perUnit;
}

/// Where the ray enters the tetrahedron: the last distance at which a coordinate growing along the
/// ray is 0 (0 when the eye is inside).
float EntryDistance(BarycentricRay ray)
{
  float entry = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    if (ray.perUnit[i] > 0.0)
      entry = max(entry, ray.length - ray.face[i] / ray.perUnit[i]);
  }
  return entry;
}

/// Where it leaves: the first distance at which a falling coordinate reaches 0. The fragment's own
/// distance on a back face, up to rounding; computed so any face of the tetrahedron will do.
float ExitDistance(BarycentricRay ray)
{
  float exit = 3.0e38;
  for (int i = 0; i < 4; ++i)
  {
    if (ray.perUnit[i] < 0.0)
      exit = min(exit, ray.length - ray.face[i] / ray.perUnit[i]);
  }
  return exit;
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

/// The distance of the scene's opaque geometry along this pixel's ray (the far plane where none).
float OpaqueDistance()
{
  vec2 ndc = gl_FragCoord.xy / viewportSize * 2.0 - 1.0;
  float depth = texelFetch(opaqueDepth, ivec2(gl_FragCoord.xy), 0).r;
  vec4 opaque = clipToEye * vec4(ndc, 2.0 * depth - 1.0, 1.0);
  vec3 point = opaque.xyz / opaque.w;
  return parallelProjection == 1 ? -point.z : length(point);
}
