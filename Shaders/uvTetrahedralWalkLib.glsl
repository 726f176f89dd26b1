// The tetrahedron a ray walks through, for the tetrahedra mapper's ray-casting passes (entry and
// walk; uvTetrahedralWalk.h is the CPU twin). Marker //UV::TetrahedralWalk, after the samplers
// tetrahedronPoints and pointData.
//
// Plücker products: the ray against each edge as the triple product d . ((a - o) x (b - o)), each
// edge's computed from the same end first whichever tetrahedron asks, so the two tetrahedra sharing
// a face find bitwise the same numbers for it. Around a face they are the barycentric
// weights of the ray's crossing of its plane, all of one sign where the ray passes through it.

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

/// Whether position a comes before b (lexicographically): the order an edge's product is computed
/// in. By position rather than point id, so a point repeated at the same place (a seam, a cell
/// scalar's copies) orders the same in every tetrahedron around it.
bool Before(vec3 a, vec3 b)
{
  return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.z < b.z);
}

/// The ray's product with edge a -> b, from the earlier corner (Before) whichever way it is asked.
/// Corners are relative to the ray's origin: the same subtraction in every tetrahedron. A product
/// of exactly 0 (the ray meets the edge's line: through a vertex, along an edge or a face) is the
/// first-order term once the ray's direction is turned by a tiny fixed generic amount, scaled far
/// below any other product (positive where that is 0 too): every tetrahedron round the edge then
/// sees the same line in general position, and a face that holds the ray's line gets weights in
/// the ratio of where that turned line crosses it.
float EdgeProduct(vec3 pa, vec3 pb, vec3 direction)
{
  bool flip = Before(pb, pa);
  vec3 moment = cross(flip ? pb : pa, flip ? pa : pb);
  float product = dot(direction, moment);
  // Without a branch: CPU rasterisers run a branch's body for every lane whenever one takes it.
  float tie = dot(vec3(0.3112, 0.5697, 0.7607), moment) * 1e-20;
  tie = tie != 0.0 ? tie : 1e-30;
  product = product != 0.0 ? product : tie;
  return flip ? -product : product;
}

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


/// The sign of the tetrahedron's volume, +1 or -1.
float VolumeSign(WalkedTetrahedron t)
{
  vec3 e1 = t.corner[1] - t.corner[0], e2 = t.corner[2] - t.corner[0], e3 = t.corner[3] - t.corner[0];
  return dot(e1, cross(e2, e3)) < 0.0 ? -1.0 : 1.0;
}
