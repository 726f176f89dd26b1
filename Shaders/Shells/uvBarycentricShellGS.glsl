//VTK::System::Dec
// vtkBarycentricShellMapper, geometry-shader route (the paper's): one point per tetrahedron in
// (uvBarycentricCellListVS.glsl passes its id), its back faces out, with the attributes of
// uvBarycentricTetrahedronLib.glsl. Back faces, not front faces: every ray through the tetrahedron
// leaves it through exactly one, also when the eye is inside it.
layout(points) in;
layout(triangle_strip, max_vertices = 12) out;

flat in int tetrahedronId[];

//UV::BarycentricTetrahedron

void main()
{
  int id = tetrahedronId[0];
  EyeTetrahedron tet = LoadEyeTetrahedron(id);
  if (!tet.valid)
  {
    return;
  }
  for (int face = 0; face < 4; ++face)
  {
    int corners[3] = int[3]((face + 1) % 4, (face + 2) % 4, (face + 3) % 4);
    vec3 a = tet.v[corners[0]];
    vec3 normal = cross(tet.v[corners[1]] - a, tet.v[corners[2]] - a);
    normal = dot(normal, tet.v[face] - a) > 0.0 ? -normal : normal; // outward
    bool back = parallelProjection == 1 ? normal.z < 0.0 : dot(normal, a) > 0.0;
    if (!back)
    {
      continue;
    }
    for (int corner = 0; corner < 3; ++corner)
    {
      EmitAttributes(tet, corners[corner], id);
      EmitVertex();
    }
    EndPrimitive();
  }
}
