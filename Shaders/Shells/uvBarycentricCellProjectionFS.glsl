//VTK::System::Dec
//VTK::Output::Dec
// vtkBarycentricShellMapper, cell projection: from the back-face fragment, the ray's entry into and
// exit from the tetrahedron in barycentric coordinates, the segment's scalars and gradients at both
// ends, and its colour integrated exactly as vtkPreIntegratedTetrahedraMapper does
// (uvSegmentIntegrationLib.glsl), or with UV_SEGMENT_TABLE read whole from the table of segments by
// front scalar, back scalar and length (no lighting, no isosurfaces then).
// Drawn back to front, blended with ONE, ONE_MINUS_SRC_ALPHA. A cell scalar's isosurfaces are the
// faces between cells on either side of the value: each tetrahedron draws those on the face the ray
// enters it by, over its own segment, lit with the face's normal.
//UV::BarycentricRay

#if defined(UV_GRADIENTS) || defined(UV_CELL_SURFACES)
uniform usamplerBuffer tetrahedronPoints;
#endif
#ifdef UV_GRADIENTS
uniform samplerBuffer pointGradients;
uniform mat3 modelToEyeNormals;
#endif
#ifdef UV_CELL_SURFACES
uniform samplerBuffer pointData;
uniform mat4 modelToEye;
uniform samplerBuffer neighbourValues; // per tetrahedron, the value across the face opposite each corner
#endif

//UV::TransferFunction

//UV::Phong

//UV::SegmentIntegration

#ifdef UV_SEGMENT_TABLE
//UV::SegmentLengthTable
#endif

#ifdef UV_CELL_SURFACES
/// The surfaces on the face the ray enters the tetrahedron by (the last plane it crosses inwards,
/// as EntryDistance finds it), seen along `toEye`, in the order the ray meets them: premultiplied
/// colour and alpha. None when the ray starts inside (the eye is in the cell).
vec4 EntryFaceSurfaces(BarycentricRay ray, vec3 toEye)
{
  vec4 entries = mix(vec4(-1.0), ZeroCrossings(ray), greaterThan(ray.perUnit, vec4(RateFloor(ray.perUnit))));
  int corner = 0;
  for (int k = 1; k < 4; ++k)
    corner = entries[k] > entries[corner] ? k : corner;
  if (!(entries[corner] > 0.0))
    return vec4(0.0);
  uvec4 ids = texelFetch(tetrahedronPoints, cellId);
  vec3 p[4];
  for (int k = 0; k < 4; ++k)
    p[k] = (modelToEye * vec4(texelFetch(pointData, int(ids[k])).xyz, 1.0)).xyz;
  vec3 normal = cross(p[(corner + 2) % 4] - p[(corner + 1) % 4], p[(corner + 3) % 4] - p[(corner + 1) % 4]);
  float from = texelFetch(neighbourValues, cellId)[corner], value = cellScalars[0];
  return SurfacesBetweenCells(from, value, normal, toEye);
}
#endif

void main()
{
  BarycentricRay ray = FragmentRay();
  float entry = EntryDistance(ray);
  float exit = min(ExitDistance(ray), OpaqueDistance());
  if (!(entry < exit))
  {
    discard;
  }
  vec4 front = CoordinatesAt(ray, entry), back = CoordinatesAt(ray, exit);
  vec3 frontGradient = vec3(0.0), backGradient = vec3(0.0);
#ifdef UV_GRADIENTS
  VertexGradientsAt(
    tetrahedronPoints, pointGradients, modelToEyeNormals, cellId, front, back, frontGradient, backGradient);
#endif
#ifdef UV_CELL_GRADIENTS
  frontGradient = backGradient = cellGradient;
#endif
#ifdef UV_SEGMENT_TABLE
  vec4 result = TableSegment(dot(cellScalars, front), dot(cellScalars, back), exit - entry);
#else
  vec3 toEye = parallelProjection == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-EyePointAt(entry));
  vec4 result = IntegrateSegment(
    dot(cellScalars, front), dot(cellScalars, back), frontGradient, backGradient, exit - entry, toEye);
#endif
#ifdef UV_CELL_SURFACES
  vec4 surfaces = EntryFaceSurfaces(ray, toEye);
  result = surfaces + (1.0 - surfaces.a) * result;
#endif
  if (!(result.a > 0.0))
  {
    discard;
  }
  gl_FragData[0] = result;
}
