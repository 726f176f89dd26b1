// Hexahedron geometry shared by the entry and traversal passes of vtkHexahedralRayCastMapper: the
// mesh's cells and points (it declares their buffer textures), a cell's corners, centre and affine
// frame (the GPU twin of uv::MakeHexahedronFrame in uvHexahedronRay.h), the eye ray of a pixel, and
// the orientation of a face's normal.
uniform usamplerBuffer cellPoints; // 8 point ids per cell (two texels), VTK hexahedron order
uniform samplerBuffer pointData;   // recentred model position, normalised scalar

// Corners of each local face in cyclic order, outward (uv::HexahedronFaces).
const int faceCorners[24] = int[24](0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7);

/// Corner k (of 4) of local face `face`, as a cell corner.
int FaceCorner(int face, int k)
{
  return faceCorners[4 * face + k];
}

/// The 8 point ids of `cell`.
void CellPointIds(int cell, out uint ids[8])
{
  uvec4 a = texelFetch(cellPoints, 2 * cell), b = texelFetch(cellPoints, 2 * cell + 1);
  ids = uint[8](a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w);
}

vec3 PointPosition(uint id)
{
  return texelFetch(pointData, int(id)).xyz;
}

/// The mean of the corners.
vec3 CellCentre(vec3 p[8])
{
  vec3 centre = vec3(0.0);
  for (int k = 0; k < 8; ++k)
    centre += 0.125 * p[k];
  return centre;
}

/// x = origin + axes xi: the centre and the averaged edge vectors, exact for every parallelepiped.
struct HexahedronFrame
{
  mat3 axes;
  vec3 origin;
  mat3 toLocal; // inverse of axes
};

/// The averaged edge vectors along r, s and t: the isoparametric map's Jacobian at the centre.
mat3 CentreJacobian(vec3 p[8])
{
  // Edges along r: 0-1, 3-2, 4-5, 7-6; along s: 0-3, 1-2, 4-7, 5-6; along t: 0-4, 1-5, 2-6, 3-7.
  vec3 r = 0.25 * ((p[1] - p[0]) + (p[2] - p[3]) + (p[5] - p[4]) + (p[6] - p[7]));
  vec3 s = 0.25 * ((p[3] - p[0]) + (p[2] - p[1]) + (p[7] - p[4]) + (p[6] - p[5]));
  vec3 t = 0.25 * ((p[4] - p[0]) + (p[5] - p[1]) + (p[6] - p[2]) + (p[7] - p[3]));
  return mat3(r, s, t);
}

HexahedronFrame MakeHexahedronFrame(vec3 p[8])
{
  HexahedronFrame frame;
  frame.axes = CentreJacobian(p);
  frame.origin = CellCentre(p) - 0.5 * (frame.axes[0] + frame.axes[1] + frame.axes[2]);
  frame.toLocal = inverse(frame.axes);
  return frame;
}

/// The frame's coordinates of x (the cell's trilinear coordinates for a parallelepiped).
vec3 FrameCoordinates(HexahedronFrame frame, vec3 x)
{
  return frame.toLocal * (x - frame.origin);
}

//UV::EyeRay

/// The largest absolute component: a vector's size without squares, which underflow or overflow
/// in float on meshes a billionth or a trillion times the unit.
float MaxComponent(vec3 v)
{
  return max(abs(v.x), max(abs(v.y), abs(v.z)));
}

/// v at unit length, by way of v over its largest component (normalize squares its components).
vec3 SafeNormalize(vec3 v)
{
  float size = MaxComponent(v);
  return size > 0.0 ? normalize(v / size) : vec3(0.0);
}

/// Whether m is singular up to float rounding of its columns' size (an absolute bound on the
/// determinant, a cubed length, would hold every cell of a tiny mesh singular).
bool IsSingular(mat3 m)
{
  float size = max(MaxComponent(m[0]), max(MaxComponent(m[1]), MaxComponent(m[2])));
  return !(size > 0.0) || abs(determinant(m / size)) < 1e-30;
}

/// A face's normal at a point, turned to the side of `outward` (the face's mean outward normal), at
/// no particular length. A vanishing normal (a collapsed edge) is replaced by `outward`. Both are
/// scaled to a largest component of 1 first: their dot product goes as a length to the fourth.
vec3 OrientedNormal(vec3 normal, vec3 outward)
{
  float outwardSize = MaxComponent(outward), normalSize = MaxComponent(normal);
  vec3 o = outwardSize > 0.0 ? outward / outwardSize : vec3(0.0);
  vec3 n = normalSize > 1e-3 * outwardSize ? normal / normalSize : o;
  return dot(n, o) < 0.0 ? -n : n;
}

/// A face's normal at a point, `normal`, in the orientation of the face's canonical
/// parameterisation (uvBilinearFaceLib.glsl), turned outward by the one sign that turns that
/// parameterisation's normal at the face's centre, `centreNormal`, to the side of `outward` (the
/// face's mean outward normal). Not turned point by point as OrientedNormal does: on a folded face the
/// outward normal turns past a right angle from the mean, and a ray crossing there enters where it
/// seems to leave. A vanishing normal (a collapsed edge) is replaced by `outward`.
vec3 OutwardNormalAt(vec3 normal, vec3 centreNormal, vec3 outward)
{
  vec3 o = OrientedNormal(outward, outward);
  float normalSize = MaxComponent(normal), centreSize = MaxComponent(centreNormal);
  if (!(normalSize > 1e-3 * MaxComponent(outward)) || !(centreSize > 0.0))
    return o;
  return dot(centreNormal / centreSize, o) < 0.0 ? -normal / normalSize : normal / normalSize;
}

/// The normal of a face from its corners p in cyclic order (the cross product of its diagonals,
/// outward by VTK's convention for a cell of positive volume; zero for a collapsed face).
vec3 CyclicNormal(vec3 p[4])
{
  return cross(p[2] - p[0], p[3] - p[1]);
}

/// Whether `centre` lies in the plane of the face with cyclic corners p up to rounding, relative to
/// the face's size: the face of a flat cell (a sliver, a collapsed layer), whose centre cannot tell
/// its sides apart.
bool CentreInFacePlane(vec3 p[4], vec3 centre)
{
  float height = dot(SafeNormalize(CyclicNormal(p)), 0.25 * (p[0] + p[1] + p[2] + p[3]) - centre);
  return abs(height) <= 1e-4 * max(MaxComponent(p[2] - p[0]), MaxComponent(p[3] - p[1]));
}

/// The sign of the Jacobian of the cell with corners p at its centre: 1 where the corners' cyclic
/// order of each face is outward (VTK's orientation), -1 for an inverted cell, 0 where it is
/// singular (a flat cell, or a fold through the centre).
float CellHandedness(vec3 p[8])
{
  mat3 jacobian = CentreJacobian(p);
  if (IsSingular(jacobian))
    return 0.0;
  float size = max(MaxComponent(jacobian[0]), max(MaxComponent(jacobian[1]), MaxComponent(jacobian[2])));
  return determinant(jacobian / size) > 0.0 ? 1.0 : -1.0;
}

/// The outward normal of the face with cyclic corners p of a cell centred at `centre` whose
/// CellHandedness is `handedness`: the cyclic order's normal, turned by that handedness. The sign of
/// the map decides, not the side the centre lies on: a crushed cell's centre can lie beyond one of its
/// faces. Where the handedness is 0, the face is turned away from the centre; where the centre lies in
/// its plane (a flat cell), the corners' cyclic order decides.
vec3 OutwardFaceNormal(vec3 p[4], vec3 centre, float handedness)
{
  vec3 n = CyclicNormal(p);
  if (CentreInFacePlane(p, centre))
    return n;
  if (handedness != 0.0)
    return handedness * n;
  return dot(SafeNormalize(n), 0.25 * (p[0] + p[1] + p[2] + p[3]) - centre) < 0.0 ? -n : n;
}

/// The Jacobian of the isoparametric map of the cell with corners p at xi.
mat3 MapJacobian(vec3 p[8], vec3 xi)
{
  float r = xi.x, s = xi.y, t = xi.z;
  vec3 dr = (1.0 - s) * (1.0 - t) * (p[1] - p[0]) + s * (1.0 - t) * (p[2] - p[3]) + (1.0 - s) * t * (p[5] - p[4]) +
    s * t * (p[6] - p[7]);
  vec3 ds = (1.0 - r) * (1.0 - t) * (p[3] - p[0]) + r * (1.0 - t) * (p[2] - p[1]) + (1.0 - r) * t * (p[7] - p[4]) +
    r * t * (p[6] - p[5]);
  vec3 dt = (1.0 - r) * (1.0 - s) * (p[4] - p[0]) + r * (1.0 - s) * (p[5] - p[1]) + r * s * (p[6] - p[2]) +
    (1.0 - r) * s * (p[7] - p[3]);
  return mat3(dr, ds, dt);
}

/// The isoparametric map of the cell with corners p at xi.
vec3 MapPoint(vec3 p[8], vec3 xi)
{
  vec3 bottom = mix(mix(p[0], p[1], xi.x), mix(p[3], p[2], xi.x), xi.y);
  vec3 top = mix(mix(p[4], p[5], xi.x), mix(p[7], p[6], xi.x), xi.y);
  return mix(bottom, top, xi.z);
}

/// Whether the cell with corners p folds over itself: its map's Jacobian takes both signs over its
/// corners and centre (uv::IsTangledHexahedron's test; zeros, as at a collapsed edge, do not count).
/// Its faces' normals then do not tell where a ray enters it and where it leaves.
bool IsTangledCell(vec3 p[8])
{
  float scale = 0.0;
  for (int k = 1; k < 8; ++k)
    scale = max(scale, MaxComponent(p[k] - p[0]));
  float tiny = 1e-6 * scale * scale * scale; // relative to float rounding of the products
  bool positive = false, negative = false;
  for (int corner = 0; corner < 9; ++corner)
  {
    vec3 xi = corner < 8 ? vec3(float(corner & 1), float((corner >> 1) & 1), float((corner >> 2) & 1)) : vec3(0.5);
    float d = determinant(MapJacobian(p, xi));
    positive = positive || d > tiny;
    negative = negative || d < -tiny;
  }
  return positive && negative;
}
