// vtkBarycentricShellMapper: one tetrahedron made ready for barycentric ray sampling in eye space, by
// either route that feeds the fragment stages (uvBarycentricShellGS.glsl, uvBarycentricPullVS.glsl;
// marker //UV::BarycentricTetrahedron). The eye's barycentric coordinates b_eye come from the edge
// inverse about v0 (uvBarycentricShell.h: the 4x4 inverse in float loses the digits the eye's distance
// costs); a vertex k then carries its own coordinates e_k and the direction attribute e_k - b_eye, both
// linear in the eye-space point, so perspective-correct interpolation makes them exact everywhere on
// a face.
uniform usamplerBuffer tetrahedronPoints; // 4 point ids per tetrahedron
uniform samplerBuffer pointData;          // model position (recentred) and normalised scalar
uniform mat4 modelToEye;
uniform mat4 eyeToClip;
uniform int parallelProjection;

#ifndef UV_DEPTH_RAY
out vec3 eyePosition;          // the fragment's eye-space point on the face (UV_DEPTH_RAY: not needed)
#endif
out vec4 faceCoordinates;      // its barycentric coordinates
// Perspective: M^-1 (x, 0), the direction attribute b. Parallel projection: the coordinates' change
// per unit along -z, the same at every vertex. (One output serves both: on CPU rasterisers each
// output costs every triangle's setup and memory.)
out vec4 rayDirection;
flat out vec4 cellScalars;     // normalised scalar at the four vertices
#ifdef UV_RAY_ATTRIBUTE
// The eye ray through the fragment's pixel: perspective, its (x, y) per unit of depth, x / -z; parallel
// projection, its origin (x, y). Either is affine on screen, so interpolated without perspective it is
// exact, and the fragment stage need not rebuild it from its window position.
noperspective out vec2 pixelRay;
#endif
flat out int cellId;
#ifdef UV_CELL_GRADIENTS
flat out vec3 cellGradient;    // the linear field's gradient, eye space (normalised scalar units)
#endif
#ifdef UV_TEXTURE
uniform samplerBuffer pointTextureCoordinates;
flat out mat4 cellTextureCoordinates; // column k: vertex k's texture coordinates
#endif

struct EyeTetrahedron
{
  vec3 v[4];
  vec4 scalars;
  vec4 eyeCoordinates;
  vec4 parallelPerUnit;
  vec3 gradient; // of the linear field, eye space
  uvec4 ids;
  bool valid;    // false when flat (no inverse)
  bool positive; // v1 - v0, v2 - v0, v3 - v0 positively oriented in eye space
};

EyeTetrahedron LoadEyeTetrahedron(int id)
{
  EyeTetrahedron tet;
  uvec4 ids = texelFetch(tetrahedronPoints, id);
  tet.ids = ids;
  for (int k = 0; k < 4; ++k)
  {
    vec4 data = texelFetch(pointData, int(ids[k]));
    tet.v[k] = (modelToEye * vec4(data.xyz, 1.0)).xyz;
    tet.scalars[k] = data.w;
  }
  mat3 edges = mat3(tet.v[1] - tet.v[0], tet.v[2] - tet.v[0], tet.v[3] - tet.v[0]);
  float scale = max(length(edges[0]), max(length(edges[1]), length(edges[2])));
  float volume = determinant(edges);
  tet.valid = abs(volume) > 16.0 * 1.1920929e-7 * scale * scale * scale;
  tet.positive = volume > 0.0;
  mat3 edgeInverse = tet.valid ? inverse(edges) : mat3(0.0);
  vec3 q = edgeInverse * -tet.v[0];
  tet.eyeCoordinates = vec4(1.0 - q.x - q.y - q.z, q);
  vec3 p = edgeInverse * vec3(0.0, 0.0, -1.0);
  tet.parallelPerUnit = vec4(-p.x - p.y - p.z, p);
  // s(x) = s0 + (s_k - s0) . E^-1 (x - v0): its gradient is E^-T (s_k - s0).
  tet.gradient = transpose(edgeInverse) * (tet.scalars.yzw - tet.scalars.x);
  return tet;
}

/// Sets every output for vertex k of the tetrahedron.
void EmitAttributes(EyeTetrahedron tet, int k, int id)
{
  vec4 unit = vec4(0.0);
  unit[k] = 1.0;
#ifndef UV_DEPTH_RAY
  eyePosition = tet.v[k];
#endif
  faceCoordinates = unit;
  rayDirection = parallelProjection == 1 ? tet.parallelPerUnit : unit - tet.eyeCoordinates;
  cellScalars = tet.scalars;
  cellId = id;
#ifdef UV_CELL_GRADIENTS
  cellGradient = tet.gradient;
#endif
#ifdef UV_TEXTURE
  for (int v = 0; v < 4; ++v)
    cellTextureCoordinates[v] = texelFetch(pointTextureCoordinates, int(tet.ids[v]));
#endif
#ifdef UV_RAY_ATTRIBUTE
  pixelRay = parallelProjection == 1 ? tet.v[k].xy : tet.v[k].xy / -tet.v[k].z;
#endif
  gl_Position = eyeToClip * vec4(tet.v[k], 1.0);
}
