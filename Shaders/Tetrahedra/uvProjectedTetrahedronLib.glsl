// vtkPreIntegratedTetrahedraMapper: projection of one tetrahedron for the geometry-shader route
// (uvPreIntegratedTetrahedraGS.glsl, fed one point per tetrahedron). It
// classifies the projection and finds the fan of triangles around the thick vertex: the GPU twin of
// uvProjectedTetrahedron.h (same steps, same names). Every attribute is carried as value/w and 1/w
// of the surface it lies on, linear in screen space, so the fragment stage recovers exact eye-space
// points on the front and back faces under any projection. Emitted vertices have clip w = 1, so
// 'smooth' interpolation is already linear in screen space; 'noperspective' would say the same but
// Mesa's clipper recomputes such attributes from screen x along near-vertical edges it clips at the
// viewport's border, which gave wrong values there. A tetrahedron
// crossing the near plane (where rays begin) is drawn as the screen rectangle of its part beyond the
// plane, whose fragments intersect the eye ray with the tetrahedron's faces instead; one wholly
// before the near plane is not drawn.
uniform usamplerBuffer tetrahedronPoints; // 4 point ids per tetrahedron
uniform samplerBuffer pointData;          // model position (recentred) and normalised scalar
#ifdef UV_GRADIENTS
uniform samplerBuffer pointGradients;     // scalar gradient, model coordinates
uniform mat3 modelToEyeNormals;
#endif
uniform mat4 modelToEye;
uniform mat4 eyeToClip;
uniform float nearDepth;                  // the near plane's eye depth: rays begin there
uniform float zeroTolerance;              // relative size of a dependency coefficient taken as zero

smooth out vec3 frontData;        // (scalar, eye z, 1) / w on the front surface
smooth out vec3 backData;         // the same on the back surface
#ifdef UV_GRADIENTS
smooth out vec3 frontGradientOverW;
smooth out vec3 backGradientOverW;
#endif
flat out int rayCastTetrahedron;         // -1, or the tetrahedron each fragment intersects itself
#ifdef UV_CELL_SURFACES
flat out int fragmentTetrahedron;        // the tetrahedron drawn (its front face may hold surfaces)
#endif
int loadedTetrahedron;

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

void SetPoint(vec2 screen, SurfacePoint front, SurfacePoint back)
{
  gl_Position = vec4(screen, 0.0, 1.0); // depth is not used: no clipping against near/far here
  frontData = vec3(front.scalar, front.position.z, 1.0) / front.w;
  backData = vec3(back.scalar, back.position.z, 1.0) / back.w;
#ifdef UV_GRADIENTS
  frontGradientOverW = front.gradient / front.w;
  backGradientOverW = back.gradient / back.w;
#endif
  rayCastTetrahedron = -1;
#ifdef UV_CELL_SURFACES
  fragmentTetrahedron = loadedTetrahedron;
#endif
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

/// Corner `slot` of the rectangle [low, high] (normalised device coordinates) drawn for a tetrahedron
/// that crosses the near plane: the fragments intersect the eye ray with tetrahedron `id` themselves.
void SetRayCastSlot(int slot, int id, vec2 low, vec2 high)
{
  vec2 corners[5] = vec2[5](low, vec2(high.x, low.y), high, vec2(low.x, high.y), 0.5 * (low + high));
  gl_Position = vec4(corners[slot], 0.0, 1.0);
  frontData = vec3(0.0, 0.0, 1.0);
  backData = vec3(0.0, 0.0, 1.0);
#ifdef UV_GRADIENTS
  frontGradientOverW = vec3(0.0);
  backGradientOverW = vec3(0.0);
#endif
  rayCastTetrahedron = id;
#ifdef UV_CELL_SURFACES
  fragmentTetrahedron = id;
#endif
}

/// The projection of the loaded tetrahedron as a fan of four triangles (thick vertex, hull[i],
/// hull[i + 1 mod 4]) around the projected outline; repeated hull entries make empty triangles.
struct Projection
{
  int mode;            // 0: nothing to draw, 1: the fan, 2: crosses the near plane, ray-cast
  int hull[4];         // vertex indices around the outline
  vec2 screen[4];      // mode 2: screen[0] and screen[1] bound the part beyond the near plane
  vec2 thick;
  SurfacePoint thickFront;
  SurfacePoint thickBack;
};

/// Loads tetrahedron `id` into eye[], clip[], scalar[], gradient[].
void LoadTetrahedron(int id)
{
  loadedTetrahedron = id;
  uvec4 ids = texelFetch(tetrahedronPoints, id);
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
  }
}
/// Screen bounds of the loaded tetrahedron's part beyond the near plane: the hull of its vertices
/// there and of its edges' crossings of the plane, projected (slightly widened, clamped to the screen).
void NearClippedBounds(out vec2 low, out vec2 high)
{
  low = vec2(1.0);
  high = vec2(-1.0);
  for (int k = 0; k < 4; ++k)
  {
    for (int j = k; j < 4; ++j)
    {
      float dk = -eye[k].z - nearDepth, dj = -eye[j].z - nearDepth;
      vec3 point;
      if (j == k && dk >= 0.0)
        point = eye[k];
      else if (j != k && dk * dj < 0.0)
        point = mix(eye[k], eye[j], dk / (dk - dj));
      else
        continue;
      vec4 c = eyeToClip * vec4(point, 1.0);
      vec2 p = c.xy / c.w;
      low = min(low, p);
      high = max(high, p);
    }
  }
  vec2 margin = 1e-3 * (vec2(1.0) + abs(low) + abs(high));
  low = clamp(low - margin, vec2(-1.0), vec2(1.0));
  high = clamp(high + margin, vec2(-1.0), vec2(1.0));
}

/// The projected outline's vertices in order, by the projection's class (see
/// uvProjectedTetrahedron.h), from each vertex's side of the affine dependency (+1, -1, 0).
void OutlineByClass(float sides[4], int positives, int negatives, out int hull[4])
{
  float lone = positives <= negatives ? 1.0 : -1.0;
  int loneCount = min(positives, negatives), otherCount = max(positives, negatives);
  int loneVertex = -1, zeroA = -1, zeroB = -1, otherA = -1, otherB = -1, otherC = -1;
  for (int k = 3; k >= 0; --k)
  {
    if (sides[k] == 0.0)
    {
      zeroB = zeroA;
      zeroA = k;
    }
    else if (sides[k] == lone)
    {
      loneVertex = loneVertex < 0 ? k : loneVertex;
    }
    else
    {
      otherC = otherB;
      otherB = otherA;
      otherA = k;
    }
  }
  if (loneCount == 1 && otherCount == 3)
  {
    hull = int[4](otherA, otherB, otherC, otherC); // class 1: the others' triangle
  }
  else if (loneCount == 2)
  {
    // Class 2: the outline alternates sides (its diagonals join equal sides).
    int plusA = -1, plusB = -1, minusA = -1, minusB = -1;
    for (int k = 3; k >= 0; --k)
    {
      if (sides[k] > 0.0)
      {
        plusB = plusA;
        plusA = k;
      }
      else
      {
        minusB = minusA;
        minusA = k;
      }
    }
    hull = int[4](plusA, minusA, plusB, minusB);
  }
  else if (otherCount == 2)
  {
    hull = int[4](otherA, otherB, zeroA, zeroA); // class 3: (T on the edge), the zero vertex
  }
  else
  {
    hull = int[4](loneVertex, zeroA, zeroB, zeroB); // class 4: T on the lone vertex
  }
}

Projection Project()
{
  Projection result;
  result.mode = 0;
  int beyond = 0;
  for (int k = 0; k < 4; ++k)
  {
    beyond += -eye[k].z >= nearDepth ? 1 : 0;
  }
  if (beyond < 4)
  {
    result.mode = beyond == 0 ? 0 : 2; // wholly before the near plane: no ray reaches it
#ifdef UV_NEAR_PLANE_CUTS
    if (beyond > 0)
    {
      NearClippedBounds(result.screen[0], result.screen[1]);
    }
#else
    result.mode = 0; // the mapper found no tetrahedron can cross the plane; rounding aside, none does
#endif
    return result;
  }
  vec2 p[4];
  for (int k = 0; k < 4; ++k)
  {
    p[k] = clip[k].xy / clip[k].w;
    result.screen[k] = p[k];
  }
  // The affine dependency sum A_k p_k = 0 and its signs: the projection's class.
  float A[4] = float[4](Orient2D(p[1], p[2], p[3]), -Orient2D(p[0], p[2], p[3]), Orient2D(p[0], p[1], p[3]),
    -Orient2D(p[0], p[1], p[2]));
  float total = abs(A[0]) + abs(A[1]) + abs(A[2]) + abs(A[3]);
  if (!(total > 0.0))
  {
    return result; // projects onto a line
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
    return result;
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
  result.thick = thick;
  result.thickFront = plusInFront ? plus : minus;
  result.thickBack = plusInFront ? minus : plus;

  OutlineByClass(sides, positives, negatives, result.hull);
  result.mode = 1;
  return result;
}

/// Slot 0-3: the outline's vertices; slot 4: the thick vertex.
void SetSlot(Projection projection, int slot)
{
  if (slot == 4)
  {
    SetPoint(projection.thick, projection.thickFront, projection.thickBack);
  }
  else
  {
    int k = projection.hull[slot];
    SetPoint(projection.screen[k], Vertex(k), Vertex(k));
  }
}
