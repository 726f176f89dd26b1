//VTK::System::Dec
// vtkBarycentricShellMapper, geometry-shader route, vertex stage: one point per entry of a cell list
// (a shell's tetrahedra, the isosurfaces' or the visibility order; a buffer texture), drawn with
// glDrawArrays; the geometry stage fetches the tetrahedron itself.
uniform usamplerBuffer cellList;
uniform int listOffset; // the list place of this draw's first tetrahedron
flat out int tetrahedronId;

void main()
{
  tetrahedronId = int(texelFetch(cellList, listOffset + gl_VertexID).r);
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
