//VTK::System::Dec
// vtkHexahedralRayCastMapper, entry pass: the mesh's boundary quads, 6 vertices (2 triangles) per
// face pulled from buffer textures, split along the diagonal through the face's smallest point id.
// The triangles only choose the pixels that test the face: where a ray meets it is the exact bilinear
// patch, found by the fragment shader.
uniform isamplerBuffer boundaryFaces; // (cell, local face) per boundary face
uniform mat4 modelToClip;
uniform int faceOffset; // the first face of this draw (uvgl::DrawItemsInChunks)

out vec3 modelPosition;
flat out int boundaryFace;
flat out vec3 outwardNormal;

//UV::Hexahedron

void main()
{
  int face = faceOffset + gl_VertexID / 6;
  int corner = gl_VertexID % 6;
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
  outwardNormal = OutwardFaceNormal(p, CellCentre(corners));
  int order[6] = int[6](0, 1, 2, 0, 2, 3);
  vec3 position = p[(smallest + order[corner]) % 4];
  modelPosition = position;
  boundaryFace = face;
  gl_Position = modelToClip * vec4(position, 1.0);
}
