//VTK::System::Dec
// vtkBarycentricShellMapper's and vtkPreIntegratedTetrahedraMapper's vertex-pulling route (the
// default; geometry shaders are slow on some GPUs and on CPU rasterisers): vertex 4q + k is vertex k
// of the tetrahedron at place listOffset + q of a cell list (a buffer texture), drawn as its four
// faces by a fixed index pattern whose windings face outwards for positively oriented tetrahedra
// (others swap two vertices). The rasteriser culls front faces, leaving each tetrahedron's back
// faces, as the geometry route emits, or its one front face where that is fewer triangles
// (DrawsFrontFaces). A flat tetrahedron's vertices are all put outside the clip volume.
uniform usamplerBuffer cellList;
uniform int listOffset; // the list place of this draw's first tetrahedron

//UV::BarycentricTetrahedron

uniform float nearDepth; // eye-space depth of the near clipping plane

/// Whether to draw the tetrahedron's front faces instead of its back faces: where it has one front
/// face and three back faces (its outline is a triangle with the fourth vertex behind). Either side
/// covers its outline once and the fragment stages find entry and exit from any face, so the side
/// with fewer triangles costs less setup and fewer shaded blocks. Not where a vertex is before the
/// near plane: clipping would cut front faces where rays still cross the tetrahedron beyond it.
bool DrawsFrontFaces(EyeTetrahedron tet)
{
  // Face k is a back face where the ray leaves by it: where coordinate k falls along the ray.
  vec4 backFaces = parallelProjection == 1 ? vec4(lessThan(tet.parallelPerUnit, vec4(0.0)))
                                           : vec4(greaterThan(tet.eyeCoordinates, vec4(0.0)));
  float nearest = max(max(tet.v[0].z, tet.v[1].z), max(tet.v[2].z, tet.v[3].z));
  return dot(backFaces, vec4(1.0)) > 2.5 && -nearest >= nearDepth;
}

void main()
{
  int id = int(texelFetch(cellList, listOffset + (gl_VertexID >> 2)).r);
  EyeTetrahedron tet = LoadEyeTetrahedron(id);
  int slot = gl_VertexID & 3;
  // Swapping the vertices of slots 1 and 2 turns every face's winding: a negatively oriented
  // tetrahedron is wound as a positive one, and culling keeps the front faces where they are drawn.
  bool swapped = (DrawsFrontFaces(tet) != !tet.positive) && (slot == 1 || slot == 2);
  EmitAttributes(tet, swapped ? 3 - slot : slot, id);
  if (!tet.valid)
  {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
  }
}
