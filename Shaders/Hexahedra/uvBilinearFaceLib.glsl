// Exact ray / bilinear-patch intersection for hexahedron faces, shared by the entry and traversal
// passes of vtkHexahedralRayCastMapper (the GPU twin of IntersectBilinearPatch in
// uvRayCellGeometry.h). Every cell, and the boundary pass, parameterises a face the same way --
// corner a the smallest point id, b its neighbour with the smaller id, c opposite a -- so two cells
// sharing a face compute bitwise the same crossing: the walk is watertight. A face with a repeated
// corner (of a tetrahedron, pyramid or wedge stored as a collapsed hexahedron) is a flat triangle,
// its corners ordered by id.

/// Canonical corners of a quad given in cyclic order with their point ids.
void CanonicalQuad(vec3 p[4], uint ids[4], out vec3 a, out vec3 b, out vec3 c, out vec3 d)
{
  int k = 0;
  for (int i = 1; i < 4; ++i)
    k = ids[i] < ids[k] ? i : k;
  int next = (k + 1) % 4, previous = (k + 3) % 4;
  bool forward = ids[next] < ids[previous];
  a = p[k];
  b = forward ? p[next] : p[previous];
  c = p[(k + 2) % 4];
  d = forward ? p[previous] : p[next];
}

/// The ray's point on the patch at root v of HitPatchAt's quadratic: false where it lies off the
/// patch (beyond the slack), else its ray parameter and patch coordinates.
bool PatchPointAt(float v, vec3 origin, vec3 direction, vec3 a, vec3 e1, vec3 e2, vec3 e3, vec4 plane1,
  vec4 plane2, out float t, out vec2 uv)
{
  const float slack = 1e-5;
  t = -3.0e38;
  uv = vec2(0.0);
  if (v < -slack || v > 1.0 + slack)
    return false;
  // plane = (A, B, C, D): A + u B + v C + u v D = 0 on each plane through the ray.
  float denominator1 = plane1.y + v * plane1.w, denominator2 = plane2.y + v * plane2.w;
  float u = abs(denominator1) > abs(denominator2) ? -(plane1.x + v * plane1.z) / denominator1
                                                  : -(plane2.x + v * plane2.z) / denominator2;
  if (!(u >= -slack && u <= 1.0 + slack))
    return false;
  vec3 hit = a + u * e1 + v * e2 + u * v * e3;
  t = dot(hit - origin, direction);
  uv = vec2(u, v);
  return true;
}

/// HitPatch, with the hits' patch coordinates (u, v). The quadratic's roots are scalars, and each is
/// taken by its own call, not through an array: softpipe writes an array element at the index of the
/// first pixel of a 2x2 quad for all four, even for pixels whose branch does not run.
int HitPatchAt(vec3 origin, vec3 direction, vec3 a, vec3 b, vec3 c, vec3 d, out float t0, out float t1,
  out vec2 uv0, out vec2 uv1)
{
  vec3 e1 = b - a, e2 = d - a, e3 = a - b + c - d;
  // Two planes through the ray.
  vec3 n1 = abs(direction.x) > abs(direction.z) ? vec3(-direction.y, direction.x, 0.0)
                                                : vec3(0.0, -direction.z, direction.y);
  n1 = normalize(n1);
  vec3 n2 = cross(direction, n1);
  vec3 ao = a - origin;
  vec4 plane1 = vec4(dot(n1, ao), dot(n1, e1), dot(n1, e2), dot(n1, e3));
  vec4 plane2 = vec4(dot(n2, ao), dot(n2, e1), dot(n2, e2), dot(n2, e3));
  // Eliminating u leaves qa v^2 + qb v + qc = 0.
  float qa = plane2.z * plane1.w - plane1.z * plane2.w;
  float qb = plane2.x * plane1.w + plane2.z * plane1.y - plane1.x * plane2.w - plane1.z * plane2.y;
  float qc = plane2.x * plane1.y - plane1.x * plane2.y;
  t0 = -3.0e38;
  t1 = -3.0e38;
  uv0 = vec2(0.0);
  uv1 = vec2(0.0);
  float scale = abs(qa) + abs(qb) + abs(qc);
  if (!(scale > 0.0))
    return 0;
  // The coefficients go as a length squared, the discriminant as its fourth power: it underflows
  // in float on tiny cells and overflows on huge ones. Divided by their scale, the roots stay.
  qa /= scale;
  qb /= scale;
  qc /= scale;
  float root0 = 0.0, root1 = 0.0;
  bool has0 = false, has1 = false;
  if (abs(qa) <= 1e-6)
  {
    has0 = qb != 0.0;
    root0 = has0 ? -qc / qb : 0.0;
  }
  else
  {
    float discriminant = qb * qb - 4.0 * qa * qc;
    if (discriminant >= 0.0)
    {
      float q = -0.5 * (qb + (qb >= 0.0 ? 1.0 : -1.0) * sqrt(discriminant));
      has0 = true;
      root0 = q / qa;
      has1 = q != 0.0;
      root1 = has1 ? qc / q : 0.0;
    }
  }
  float tA, tB;
  vec2 uvA, uvB;
  bool hitA = has0 && PatchPointAt(root0, origin, direction, a, e1, e2, e3, plane1, plane2, tA, uvA);
  bool hitB = has1 && PatchPointAt(root1, origin, direction, a, e1, e2, e3, plane1, plane2, tB, uvB);
  if (hitA)
  {
    t0 = tA;
    uv0 = uvA;
  }
  if (hitB && hitA)
  {
    t1 = tB;
    uv1 = uvB;
  }
  else if (hitB)
  {
    t0 = tB;
    uv0 = uvB;
  }
  return (hitA ? 1 : 0) + (hitB ? 1 : 0);
}

/// Ray parameters where origin + t direction meets the patch a + u(b-a) + v(d-a) + uv(a-b+c-d),
/// u and v in [0, 1] (a small slack keeps shared edges covered); returns how many (0, 1 or 2).
int HitPatch(vec3 origin, vec3 direction, vec3 a, vec3 b, vec3 c, vec3 d, out float t0, out float t1)
{
  vec2 uv0, uv1;
  return HitPatchAt(origin, direction, a, b, c, d, t0, t1, uv0, uv1);
}

/// The patch's normal at (u, v) (orientation of the canonical parameterisation).
vec3 PatchNormalAt(vec3 a, vec3 b, vec3 c, vec3 d, vec2 uv)
{
  vec3 e1 = b - a, e2 = d - a, e3 = a - b + c - d;
  return cross(e1 + uv.y * e3, e2 + uv.x * e3);
}

/// The face with corners p (cyclic order) and point ids `ids` as every cell sharing it sees it: a
/// quad (CanonicalQuad) or, with a repeated corner, the triangle a, b, c by ascending id (d = c).
/// Returns how many distinct corners it has: under 3 it is collapsed, no face.
int CanonicalFace(vec3 p[4], uint ids[4], out vec3 a, out vec3 b, out vec3 c, out vec3 d)
{
  // Which corners repeat an earlier one, and the first three distinct ones, without writing an
  // array at a per-pixel index (see HitPatchAt).
  bool repeated1 = ids[1] == ids[0];
  bool repeated2 = ids[2] == ids[0] || ids[2] == ids[1];
  bool repeated3 = ids[3] == ids[0] || ids[3] == ids[1] || ids[3] == ids[2];
  int count = 1 + (repeated1 ? 0 : 1) + (repeated2 ? 0 : 1) + (repeated3 ? 0 : 1);
  int second = !repeated1 ? 1 : (!repeated2 ? 2 : 3);
  int third = (second < 2 && !repeated2) ? 2 : 3;
  if (count == 4)
  {
    CanonicalQuad(p, ids, a, b, c, d);
    return 4;
  }
  a = p[0];
  b = p[0];
  c = p[0];
  d = p[0];
  if (count < 3)
    return count;
  int i0 = 0, i1 = second, i2 = third, swap;
  if (ids[i1] < ids[i0]) { swap = i0; i0 = i1; i1 = swap; }
  if (ids[i2] < ids[i1]) { swap = i1; i1 = i2; i2 = swap; }
  if (ids[i1] < ids[i0]) { swap = i0; i0 = i1; i1 = swap; }
  a = p[i0];
  b = p[i1];
  c = p[i2];
  d = c;
  return 3;
}

/// Where the ray meets triangle (a, b, c), with the patches' slack on its edges: 0 or 1 hits.
int HitTriangle(vec3 origin, vec3 direction, vec3 a, vec3 b, vec3 c, out float t)
{
  const float slack = 1e-5;
  vec3 e1 = b - a, e2 = c - a;
  vec3 pv = cross(direction, e2);
  float determinant = dot(e1, pv);
  t = -3.0e38;
  if (determinant == 0.0)
    return 0; // along the plane
  vec3 s = origin - a;
  float u = dot(s, pv) / determinant;
  vec3 q = cross(s, e1);
  float v = dot(direction, q) / determinant;
  if (!(u >= -slack && v >= -slack && u + v <= 1.0 + slack))
    return 0;
  t = dot(e2, q) / determinant;
  return 1;
}

/// The hits of the ray on a canonical face of `corners` (3 or 4) corners, and the face's normal at
/// each (either orientation; zero where a patch's edge is collapsed).
int HitFace(vec3 origin, vec3 direction, vec3 a, vec3 b, vec3 c, vec3 d, int corners, out float t0,
  out float t1, out vec3 n0, out vec3 n1)
{
  t1 = -3.0e38;
  if (corners == 3)
  {
    n0 = cross(b - a, c - a);
    n1 = n0;
    return HitTriangle(origin, direction, a, b, c, t0);
  }
  vec2 uv0, uv1;
  int hits = HitPatchAt(origin, direction, a, b, c, d, t0, t1, uv0, uv1);
  n0 = PatchNormalAt(a, b, c, d, uv0);
  n1 = PatchNormalAt(a, b, c, d, uv1);
  return hits;
}
