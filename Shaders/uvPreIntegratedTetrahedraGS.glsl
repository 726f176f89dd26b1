//VTK::System::Dec
// vtkPreIntegratedTetrahedraMapper, geometry stage: classifies the projection of one tetrahedron
// and emits the fan of triangles around its thick vertex (the GPU twin of uvProjectedTetrahedron.h:
// same steps, same names). Every attribute is interpolated without perspective (noperspective) as
// value/w and 1/w of the surface it lies on, so the fragment stage recovers exact eye-space points on
// the front and back faces under any projection. A tetrahedron reaching behind the near limit
// cannot be projected; it is drawn as a screen-covering quad that intersects the eye ray with the
// tetrahedron's faces per fragment instead.
layout(points) in;
layout(triangle_strip, max_vertices = 12) out;

flat in int tetrahedronId[];

uniform usamplerBuffer tetrahedronPoints; // 4 point ids per tetrahedron
uniform samplerBuffer pointData;          // model position (recentred) and normalised scalar
#ifdef UV_GRADIENTS
uniform samplerBuffer pointGradients;     // scalar gradient, model coordinates
uniform mat3 modelToEyeNormals;
#endif
uniform mat4 modelToEye;
uniform mat4 eyeToClip;
uniform float minimumClipW;               // below it (perspective), a vertex is too near to project
uniform float zeroTolerance;              // relative size of a dependency coefficient taken as zero

noperspective out vec4 frontOverW;        // (eye position, scalar) / w on the front surface
noperspective out float frontInverseW;
noperspective out vec4 backOverW;
noperspective out float backInverseW;
#ifdef UV_GRADIENTS
noperspective out vec3 frontGradientOverW;
noperspective out vec3 backGradientOverW;
flat out vec4 gradientRows[3];            // ray-cast path: gradient = rows * (eye, 1)
#endif
flat out int rayCast;                     // 1: intersect per fragment with the planes below
flat out vec4 facePlanes[4];              // outward eye-space planes: dot(n, x) + d > 0 is outside
flat out vec4 scalarPlane;                // scalar = dot(xyz, x) + w

vec3 eye[4];
vec4 clip[4];
float scalar[4];
vec3 gradient[4];

float Orient2D(vec2 a, vec2 b, vec2 c)
{
  vec2 u = b - a, v = c - a;
  return u.x * v.y - u.y * v.x;
}

struct SurfacePoint
{
  vec3 position;
  float scalar;
  vec3 gradient;
  float w;
};

void EmitPoint(vec2 screen, SurfacePoint front, SurfacePoint back)
{
  gl_Position = vec4(screen, 0.0, 1.0); // depth is not used: no clipping against near/far here
  frontOverW = vec4(front.position, front.scalar) / front.w;
  frontInverseW = 1.0 / front.w;
  backOverW = vec4(back.position, back.scalar) / back.w;
  backInverseW = 1.0 / back.w;
#ifdef UV_GRADIENTS
  frontGradientOverW = front.gradient / front.w;
  backGradientOverW = back.gradient / back.w;
#endif
  rayCast = 0;
  EmitVertex();
}

SurfacePoint Vertex(int k)
{
  return SurfacePoint(eye[k], scalar[k], gradient[k], clip[k].w);
}

/// The point where the eye ray through the thick vertex meets one side's simplex:
/// screen weights over clip w, renormalised (perspective-correct barycentric coordinates).
SurfacePoint SidePoint(float side, float sides[4], float weights[4])
{
  float mu[4];
  float sum = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    mu[k] = sides[k] == side ? weights[k] / clip[k].w : 0.0;
    sum += mu[k];
  }
  SurfacePoint p = SurfacePoint(vec3(0.0), 0.0, vec3(0.0), 0.0);
  for (int k = 0; k < 4; ++k)
  {
    float m = mu[k] / sum;
    p.position += m * eye[k];
    p.scalar += m * scalar[k];
    p.gradient += m * gradient[k];
    p.w += m * clip[k].w;
  }
  return p;
}

void EmitRayCastQuad()
{
  // Faces: the plane through the three vertices other than k, oriented away from vertex k.
  for (int k = 0; k < 4; ++k)
  {
    vec3 a = eye[(k + 1) % 4], b = eye[(k + 2) % 4], c = eye[(k + 3) % 4];
    vec3 n = cross(b - a, c - a);
    float d = -dot(n, a);
    if (dot(n, eye[k]) + d > 0.0)
    {
      n = -n;
      d = -d;
    }
    facePlanes[k] = vec4(n, d);
  }
  // The scalar's affine function: solve [e1 e2 e3]^T g = [s1-s0, s2-s0, s3-s0].
  mat3 edges = mat3(eye[1] - eye[0], eye[2] - eye[0], eye[3] - eye[0]);
  mat3 inverseEdgesT = inverse(transpose(edges));
  vec3 g = inverseEdgesT * vec3(scalar[1] - scalar[0], scalar[2] - scalar[0], scalar[3] - scalar[0]);
  scalarPlane = vec4(g, scalar[0] - dot(g, eye[0]));
#ifdef UV_GRADIENTS
  for (int row = 0; row < 3; ++row)
  {
    vec3 r = inverseEdgesT * vec3(gradient[1][row] - gradient[0][row], gradient[2][row] - gradient[0][row],
      gradient[3][row] - gradient[0][row]);
    gradientRows[row] = vec4(r, gradient[0][row] - dot(r, eye[0]));
  }
#endif
  vec2 corners[4] = vec2[4](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));
  for (int i = 0; i < 4; ++i)
  {
    gl_Position = vec4(corners[i], 0.0, 1.0);
    frontOverW = vec4(0.0);
    frontInverseW = 1.0;
    backOverW = vec4(0.0);
    backInverseW = 1.0;
#ifdef UV_GRADIENTS
    frontGradientOverW = vec3(0.0);
    backGradientOverW = vec3(0.0);
#endif
    rayCast = 1;
    EmitVertex();
  }
  EndPrimitive();
}

void main()
{
  uvec4 ids = texelFetch(tetrahedronPoints, tetrahedronId[0]);
  bool tooNear = false;
  for (int k = 0; k < 4; ++k)
  {
    vec4 data = texelFetch(pointData, int(ids[k]));
    eye[k] = (modelToEye * vec4(data.xyz, 1.0)).xyz;
    clip[k] = eyeToClip * vec4(eye[k], 1.0);
    scalar[k] = data.w;
#ifdef UV_GRADIENTS
    gradient[k] = modelToEyeNormals * texelFetch(pointGradients, int(ids[k])).xyz;
#else
    gradient[k] = vec3(0.0);
#endif
    tooNear = tooNear || !(clip[k].w >= minimumClipW);
  }
  if (tooNear)
  {
    EmitRayCastQuad();
    return;
  }
  vec2 p[4];
  for (int k = 0; k < 4; ++k)
  {
    p[k] = clip[k].xy / clip[k].w;
  }
  // The affine dependency sum A_k p_k = 0 and its signs: the projection's class.
  float A[4] = float[4](Orient2D(p[1], p[2], p[3]), -Orient2D(p[0], p[2], p[3]), Orient2D(p[0], p[1], p[3]),
    -Orient2D(p[0], p[1], p[2]));
  float total = abs(A[0]) + abs(A[1]) + abs(A[2]) + abs(A[3]);
  if (!(total > 0.0))
  {
    return; // projects onto a line
  }
  float sides[4];
  float weights[4];
  int positives = 0, negatives = 0;
  float positiveSum = 0.0, negativeSum = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    sides[k] = abs(A[k]) <= zeroTolerance * total ? 0.0 : sign(A[k]);
    positives += sides[k] > 0.0 ? 1 : 0;
    negatives += sides[k] < 0.0 ? 1 : 0;
    positiveSum += sides[k] > 0.0 ? A[k] : 0.0;
    negativeSum -= sides[k] < 0.0 ? A[k] : 0.0;
  }
  if (positives == 0 || negatives == 0)
  {
    return;
  }
  vec2 thick = vec2(0.0);
  for (int k = 0; k < 4; ++k)
  {
    weights[k] = sides[k] > 0.0 ? A[k] / positiveSum : (sides[k] < 0.0 ? -A[k] / negativeSum : 0.0);
    thick += sides[k] > 0.0 ? weights[k] * p[k] : vec2(0.0);
  }
  SurfacePoint plus = SidePoint(1.0, sides, weights);
  SurfacePoint minus = SidePoint(-1.0, sides, weights);
  // Eye space looks down -z: the point with the larger z is nearer.
  bool plusInFront = plus.position.z > minus.position.z;
  SurfacePoint thickFront = plusInFront ? plus : minus;
  SurfacePoint thickBack = plusInFront ? minus : plus;

  float lone = positives <= negatives ? 1.0 : -1.0;
  int loneCount = min(positives, negatives), otherCount = max(positives, negatives);
  int zero = -1;
  for (int k = 3; k >= 0; --k)
  {
    zero = sides[k] == 0.0 ? k : zero;
  }
  // Fan triangles (thick vertex, P_i, P_j), by class (see uvProjectedTetrahedron.h).
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      bool emit;
      if (loneCount == 1 && otherCount == 3)
      {
        emit = sides[i] == -lone && sides[j] == -lone; // class 1
      }
      else if (loneCount == 2)
      {
        emit = sides[i] != sides[j]; // class 2
      }
      else if (otherCount == 2)
      {
        emit = (i == zero && sides[j] == -lone) || (j == zero && sides[i] == -lone); // class 3
      }
      else
      {
        emit = sides[i] == 0.0 && sides[j] == 0.0; // class 4
      }
      if (emit)
      {
        EmitPoint(thick, thickFront, thickBack);
        EmitPoint(p[i], Vertex(i), Vertex(i));
        EmitPoint(p[j], Vertex(j), Vertex(j));
        EndPrimitive();
      }
    }
  }
}
