//VTK::System::Dec
// vtkPreIntegratedTetrahedraMapper, ray-casting route, entry pass: the mesh's boundary faces (3
// vertices each, pulled from the buffer textures: faceOffset + gl_VertexID / 3 is the face, drawn in
// chunks (uvgl::DrawItemsInChunks)), each widened on
// screen by half a pixel so that every pixel whose ray may cross the face tests it exactly:
// rasterising the face as it is would round thin faces away. Faces that turn their back on every
// ray are culled here (for a flat face the side the eye is on is the same at every pixel). The near
// plane cuts no face: the mapper projects frames where it may cut the mesh's bounds.
uniform isamplerBuffer boundaryFaces; // tetrahedron * 4 + the corner opposite the face
uniform usamplerBuffer tetrahedronPoints;
uniform samplerBuffer pointData;
uniform mat4 modelToClip;
uniform vec2 viewportSize;
uniform vec4 eyeInModel; // (eye, 1) in perspective, (direction of view, 0) in parallel projection
uniform int faceOffset;  // the first face of this draw

flat out int boundaryFace;
flat out vec3 faceCorners[3];
flat out vec3 outwardNormal;

/// Where the corner at `p` moves when the triangle's edges move outward by `margin` pixels: the
/// meeting point of the two moved edges through it (`previous` and `next` are the other corners,
/// in pixels, counter-clockwise), at most a few pixels away at a sharp corner.
vec2 Widened(vec2 previous, vec2 p, vec2 next, float margin)
{
  vec2 inEdge = normalize(p - previous), outEdge = normalize(next - p);
  vec2 n1 = vec2(inEdge.y, -inEdge.x), n2 = vec2(outEdge.y, -outEdge.x); // outward, counter-clockwise
  vec2 miter = (n1 + n2) / max(1.0 + dot(n1, n2), 0.05);
  float reach = length(miter);
  return p + margin * (reach > 4.0 ? miter * (4.0 / reach) : miter);
}

void main()
{
  int local = gl_VertexID / 3, vertex = gl_VertexID - 3 * local;
  int face = faceOffset + local;
  int record = texelFetch(boundaryFaces, face).r;
  int corner = record & 3;
  uvec4 ids = texelFetch(tetrahedronPoints, record >> 2);
  vec3 p[3];
  for (int k = 0; k < 3; ++k)
    p[k] = texelFetch(pointData, int(ids[(corner + 1 + k) & 3])).xyz;
  vec3 opposite = texelFetch(pointData, int(ids[corner])).xyz;
  vec3 normal = cross(p[1] - p[0], p[2] - p[0]);
  normal = dot(normal, opposite - p[0]) > 0.0 ? -normal : normal;
  faceCorners = p;
  outwardNormal = normal;
  boundaryFace = face;
  vec3 toFace = eyeInModel.w > 0.0 ? p[0] - eyeInModel.xyz : eyeInModel.xyz;
  if (dot(normal, toFace) > 0.0)
  {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // every ray leaves here: nothing to draw
    return;
  }
  vec4 clip[3];
  vec2 pixel[3];
  for (int k = 0; k < 3; ++k)
  {
    clip[k] = modelToClip * vec4(p[k], 1.0);
    pixel[k] = clip[k].xy / clip[k].w * 0.5 * viewportSize;
  }
  // Counter-clockwise on screen for the outward edge normals.
  vec2 e1 = pixel[1] - pixel[0], e2 = pixel[2] - pixel[0];
  bool clockwise = e1.x * e2.y - e1.y * e2.x < 0.0;
  int previous = clockwise ? (vertex + 1) % 3 : (vertex + 2) % 3;
  int next = clockwise ? (vertex + 2) % 3 : (vertex + 1) % 3;
  vec2 moved = Widened(pixel[previous], pixel[vertex], pixel[next], 0.5);
  gl_Position = vec4(moved / (0.5 * viewportSize) * clip[vertex].w, clip[vertex].z, clip[vertex].w);
}
