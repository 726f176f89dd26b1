//VTK::System::Dec
// vtkHexahedralRayCastMapper, entry pass: the mesh's boundary quads, 6 vertices (2 triangles) per
// face pulled from buffer textures. Each quad is split along the diagonal through its smallest
// point id, as every pass does, so the surfaces rays cross are the same everywhere (watertight).
uniform isamplerBuffer boundaryFaces; // (cell, local face) per boundary face
uniform usamplerBuffer cellPoints;    // 8 point ids per cell, two texels
uniform samplerBuffer pointData;      // model position (recentred) and normalised scalar
uniform mat4 modelToClip;

out vec3 modelPosition;
flat out int boundaryFace;
flat out vec3 outwardNormal;

const int faceCorners[24] = int[24](0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7);

uint CellPoint(int cell, int k)
{
  uvec4 ids = texelFetch(cellPoints, 2 * cell + k / 4);
  return ids[k % 4];
}

void main()
{
  int face = gl_VertexID / 6;
  int corner = gl_VertexID % 6;
  ivec4 cellFace = texelFetch(boundaryFaces, face);
  int cell = cellFace.x, local = cellFace.y;
  uint ids[4];
  vec3 p[4];
  int smallest = 0;
  for (int k = 0; k < 4; ++k)
  {
    ids[k] = CellPoint(cell, faceCorners[4 * local + k]);
    p[k] = texelFetch(pointData, int(ids[k])).xyz;
    smallest = ids[k] < ids[smallest] ? k : smallest;
  }
  vec3 centre = vec3(0.0);
  for (int k = 0; k < 8; ++k)
  {
    centre += 0.125 * texelFetch(pointData, int(CellPoint(cell, k))).xyz;
  }
  // Newell normal of the quad, turned away from the cell's centre.
  vec3 n = cross(p[2] - p[0], p[3] - p[1]);
  vec3 faceCentre = 0.25 * (p[0] + p[1] + p[2] + p[3]);
  outwardNormal = dot(n, faceCentre - centre) < 0.0 ? -n : n;
  int order[6] = int[6](0, 1, 2, 0, 2, 3);
  vec3 position = p[(smallest + order[corner]) % 4];
  modelPosition = position;
  boundaryFace = face;
  gl_Position = modelToClip * vec4(position, 1.0);
}
