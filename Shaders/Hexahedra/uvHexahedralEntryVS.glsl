//VTK::System::Dec
// vtkHexahedralRayCastMapper, entry pass: the mesh's boundary quads, 12 vertices (4 triangles) per
// face pulled from buffer textures: split along the diagonal through the face's smallest point id,
// and, for a face that is not flat, along the other diagonal too. The triangles only choose the
// pixels that test the face: where a ray meets it is the exact bilinear patch, found by the fragment
// shader. A curved patch projects within the hull of its corners, which one diagonal's pair may not
// cover: at a curved silhouette, or for a face through the eye, whose triangles there project to
// lines while the patch covers an area.
uniform isamplerBuffer boundaryFaces; // (cell, local face) per boundary face
uniform mat4 modelToClip;
uniform int faceOffset; // the first face of this draw (uvgl::DrawItemsInChunks)
uniform int foldedCells; // 1: some cells of the mesh fold over themselves (else none is tested)

out vec3 modelPosition;
flat out int boundaryFace;
flat out vec3 outwardNormal;
flat out int tangled;  // 1: the face's cell folds over itself (IsTangledCell)
flat out int widening; // 1: a triangle of the other diagonal, which only widens the pixels tested

//UV::Hexahedron

void main()
{
  int face = faceOffset + gl_VertexID / 12;
  int corner = gl_VertexID % 12;
  ivec4 cellFace = texelFetch(boundaryFaces, face);
  int local = cellFace.y;
  uint cellIds[8];
  CellPointIds(cellFace.x, cellIds);
  vec3 corners[8];
  for (int k = 0; k < 8; ++k)
    corners[k] = PointPosition(cellIds[k]);
  uint ids[4];
  vec3 p[4];
  int smallest = 0;
  for (int k = 0; k < 4; ++k)
  {
    ids[k] = cellIds[FaceCorner(local, k)];
    p[k] = corners[FaceCorner(local, k)];
    smallest = ids[k] < ids[smallest] ? k : smallest;
  }
  // A flat boundary cell (a sliver) has its centre in the face's plane up to rounding: the face's
  // corner order orients it there.
  outwardNormal = OutwardFaceNormal(p, CellCentre(corners), CellHandedness(corners));
  tangled = foldedCells == 1 && IsTangledCell(corners) ? 1 : 0;
  int order[12] = int[12](0, 1, 2, 0, 2, 3, 0, 1, 3, 1, 2, 3);
  // Flat within rounding (a triangle's repeated corner included): one pair covers the patch, and
  // the other pair collapses to a point, which draws nothing.
  vec3 e1 = p[1] - p[0], e2 = p[2] - p[0], e3 = p[3] - p[0];
  float size = max(max(length(e1), length(e2)), length(e3));
  bool planar = abs(dot(e1, cross(e2, e3))) <= 1e-6 * size * size * size;
  widening = corner >= 6 ? 1 : 0;
  vec3 position = p[(smallest + (widening == 1 && planar ? 0 : order[corner])) % 4];
  modelPosition = position;
  boundaryFace = face;
  gl_Position = modelToClip * vec4(position, 1.0);
}
