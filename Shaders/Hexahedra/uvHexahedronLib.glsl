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

HexahedronFrame MakeHexahedronFrame(vec3 p[8])
{
  // Edges along r: 0-1, 3-2, 4-5, 7-6; along s: 0-3, 1-2, 4-7, 5-6; along t: 0-4, 1-5, 2-6, 3-7.
  vec3 r = 0.25 * ((p[1] - p[0]) + (p[2] - p[3]) + (p[5] - p[4]) + (p[6] - p[7]));
  vec3 s = 0.25 * ((p[3] - p[0]) + (p[2] - p[1]) + (p[7] - p[4]) + (p[6] - p[5]));
  vec3 t = 0.25 * ((p[4] - p[0]) + (p[5] - p[1]) + (p[6] - p[2]) + (p[7] - p[3]));
  HexahedronFrame frame;
  frame.axes = mat3(r, s, t);
  frame.origin = CellCentre(p) - 0.5 * (r + s + t);
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

/// The outward normal of the face with cyclic corners p of a cell centred at `centre`: turned away
/// from the centre (inverted cells' corner order is inward), unless the centre lies in its plane,
/// where the corners' cyclic order decides.
vec3 OutwardFaceNormal(vec3 p[4], vec3 centre)
{
  vec3 n = CyclicNormal(p);
  if (CentreInFacePlane(p, centre))
    return n;
  return dot(SafeNormalize(n), 0.25 * (p[0] + p[1] + p[2] + p[3]) - centre) < 0.0 ? -n : n;
}
