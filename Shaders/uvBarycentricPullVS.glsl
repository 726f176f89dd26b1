//VTK::System::Dec
// vtkBarycentricShellMapper, vertex-pulling route (the default; geometry shaders are slow on some
// GPUs and CPU rasterisers): vertex 4q + k is vertex k of the tetrahedron at place listOffset + q of a
// cell list
// (a buffer texture), drawn as its four faces by a fixed index pattern whose windings face outwards
// for positively oriented tetrahedra (the mapper orients them); the rasteriser culls front faces,
// leaving each tetrahedron's back faces, as the geometry route emits. A flat tetrahedron's vertices
// are all put outside the clip volume.
uniform usamplerBuffer cellList;
uniform int listOffset; // the list place of this draw's first tetrahedron

//UV::BarycentricTetrahedron

void main()
{
  int id = int(texelFetch(cellList, listOffset + (gl_VertexID >> 2)).r);
  EyeTetrahedron tet = LoadEyeTetrahedron(id);
  EmitAttributes(tet, gl_VertexID & 3, id);
  if (!tet.valid)
  {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
  }
}
