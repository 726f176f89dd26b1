// The ray's products with edges, which the tetrahedra mapper's two ray-casting passes (entry and
// walk) must compute alike; uvTetrahedralWalk.h is the CPU twin. Marker //UV::TetrahedralWalk.
//
// Plücker products: the ray against each edge as the triple product d . ((a - o) x (b - o)), each
// edge's computed from the same end first whichever tetrahedron asks, so the two tetrahedra sharing
// a face find bitwise the same numbers for it. Around a face they are the barycentric
// weights of the ray's crossing of its plane, all of one sign where the ray passes through it.

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
