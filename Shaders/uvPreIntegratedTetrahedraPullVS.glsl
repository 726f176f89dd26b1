//VTK::System::Dec
// vtkPreIntegratedTetrahedraMapper, vertex-pulling route: 5 vertex slots per tetrahedron (the 4
// outline vertices and the thick vertex), drawn by a fixed index buffer of 4 triangles per
// tetrahedron (thick, slot i, slot i+1 mod 4), so vertex caches shade each slot once. Vertex v
// projects tetrahedron drawOrder[v / 5] (visibility order) and becomes its slot v % 5. No geometry
// shader: faster where geometry shaders are slow (Mesa's llvmpipe).
// The projection itself is uvProjectedTetrahedronLib.glsl, inserted at the marker below.
uniform usamplerBuffer drawOrder;

//UV::ProjectedTetrahedron

void main()
{
  int slot = gl_VertexID % 5;
  int id = int(texelFetch(drawOrder, gl_VertexID / 5).r);
  LoadTetrahedron(id);
  Projection projection = Project();
  if (projection.mode == 1)
  {
    SetSlot(projection, slot);
  }
  else if (projection.mode == 2)
  {
    SetRayCastSlot(slot, id, projection.screen[0], projection.screen[1]);
  }
  else
  {
    SetRayCastSlot(4, id, vec2(2.0), vec2(2.0)); // every slot at one point: no area, no fragment
  }
}
