//VTK::System::Dec
// vtkPreIntegratedTetrahedraMapper, geometry stage: one point per tetrahedron in, the four triangles
// of its fan out (or the ray-cast fan). The projection itself is uvProjectedTetrahedronLib.glsl,
// inserted at the marker below.
layout(points) in;
layout(triangle_strip, max_vertices = 12) out;

flat in int tetrahedronId[];

//UV::ProjectedTetrahedron

void main()
{
  int id = tetrahedronId[0];
  LoadTetrahedron(id);
  Projection projection = Project();
  if (projection.mode == 0)
  {
    return;
  }
  for (int triangle = 0; triangle < 4; ++triangle)
  {
    int slots[3] = int[3](4, triangle, (triangle + 1) % 4);
    for (int corner = 0; corner < 3; ++corner)
    {
      if (projection.mode == 2)
        SetRayCastSlot(slots[corner], id, projection.screen[0], projection.screen[1]);
      else
        SetSlot(projection, slots[corner]);
      EmitVertex();
    }
    EndPrimitive();
  }
}
