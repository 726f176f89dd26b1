//VTK::System::Dec
// vtkPreIntegratedTetrahedraMapper, vertex stage: one point per tetrahedron, drawn in visibility
// order through an index buffer of tetrahedron ids; gl_VertexID is that id. The geometry stage
// fetches the tetrahedron itself from buffer textures.
flat out int tetrahedronId;

void main()
{
  tetrahedronId = gl_VertexID;
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
