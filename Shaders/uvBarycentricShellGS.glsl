//VTK::System::Dec
// vtkBarycentricShellMapper, geometry stage: one point per tetrahedron in (uvPreIntegratedTetrahedraVS
// passes its id), its back faces out. Per tetrahedron it computes the eye's barycentric coordinates
// b_eye from the eye-space vertices (uvBarycentricShell.h: the edge inverse about v0, not the 4x4
// inverse, which float cannot afford); per vertex it emits the vertex's own coordinates e_i and the
// barycentric direction e_i - b_eye, both linear in the eye-space point, so perspective-correct
// interpolation makes them exact at every fragment. Back faces, not front faces: every ray through the
// tetrahedron leaves it through exactly one, also when the eye is inside it.
layout(points) in;
layout(triangle_strip, max_vertices = 12) out;

flat in int tetrahedronId[];

uniform usamplerBuffer tetrahedronPoints; // 4 point ids per tetrahedron
uniform samplerBuffer pointData;          // model position (recentred) and normalised scalar
uniform mat4 modelToEye;
uniform mat4 eyeToClip;
uniform int parallelProjection;

out vec3 eyePosition;          // the fragment's eye-space point on the back face
out vec4 faceCoordinates;      // its barycentric coordinates
out vec4 rayDirection;         // perspective: M^-1 (x, 0), the direction attribute b
flat out vec4 cellScalars;     // normalised scalar at the four vertices
flat out vec4 parallelPerUnit; // parallel projection: the coordinates' change per unit along -z
flat out int cellId;

void main()
{
  int id = tetrahedronId[0];
  uvec4 ids = texelFetch(tetrahedronPoints, id);
  vec3 v[4];
  vec4 scalars;
  for (int k = 0; k < 4; ++k)
  {
    vec4 data = texelFetch(pointData, int(ids[k]));
    v[k] = (modelToEye * vec4(data.xyz, 1.0)).xyz;
    scalars[k] = data.w;
  }
  mat3 edges = mat3(v[1] - v[0], v[2] - v[0], v[3] - v[0]);
  float scale = max(length(edges[0]), max(length(edges[1]), length(edges[2])));
  if (!(abs(determinant(edges)) > 16.0 * 1.1920929e-7 * scale * scale * scale))
  {
    return; // flat: no volume, no inverse
  }
  mat3 edgeInverse = inverse(edges);
  vec3 q = edgeInverse * -v[0];
  vec4 eyeCoordinates = vec4(1.0 - q.x - q.y - q.z, q);
  vec3 p = edgeInverse * vec3(0.0, 0.0, -1.0);
  vec4 perUnit = vec4(-p.x - p.y - p.z, p);

  for (int face = 0; face < 4; ++face)
  {
    int corners[3] = int[3]((face + 1) % 4, (face + 2) % 4, (face + 3) % 4);
    vec3 a = v[corners[0]];
    vec3 normal = cross(v[corners[1]] - a, v[corners[2]] - a);
    normal = dot(normal, v[face] - a) > 0.0 ? -normal : normal; // outward
    bool back = parallelProjection == 1 ? normal.z < 0.0 : dot(normal, a) > 0.0;
    if (!back)
    {
      continue;
    }
    for (int corner = 0; corner < 3; ++corner)
    {
      int k = corners[corner];
      vec4 unit = vec4(0.0);
      unit[k] = 1.0;
      eyePosition = v[k];
      faceCoordinates = unit;
      rayDirection = unit - eyeCoordinates;
      cellScalars = scalars;
      parallelPerUnit = perUnit;
      cellId = id;
      gl_Position = eyeToClip * vec4(v[k], 1.0);
      EmitVertex();
    }
    EndPrimitive();
  }
}
