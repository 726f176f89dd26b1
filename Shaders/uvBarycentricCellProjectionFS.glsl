//VTK::System::Dec
//VTK::Output::Dec
// vtkBarycentricShellMapper, cell projection: from the back-face fragment, the ray's entry into and
// exit from the tetrahedron in barycentric coordinates, the segment's scalars and gradients at both
// ends, and its colour integrated exactly as vtkPreIntegratedTetrahedraMapper does
// (uvSegmentIntegrationLib.glsl).
// Drawn back to front, blended with ONE, ONE_MINUS_SRC_ALPHA.
//UV::BarycentricRay

#ifdef UV_GRADIENTS
uniform usamplerBuffer tetrahedronPoints;
uniform samplerBuffer pointGradients;
uniform mat3 modelToEyeNormals;
#endif

//UV::TransferFunction

//UV::Phong

//UV::SegmentIntegration

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
  uvec4 ids = texelFetch(tetrahedronPoints, cellId);
  for (int k = 0; k < 4; ++k)
  {
    vec3 g = modelToEyeNormals * texelFetch(pointGradients, int(ids[k])).xyz;
    frontGradient += front[k] * g;
    backGradient += back[k] * g;
  }
#endif
#ifdef UV_CELL_GRADIENTS
  frontGradient = backGradient = cellGradient;
#endif
  vec3 toEye = parallelProjection == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-EyePointAt(entry));
  vec4 result = IntegrateSegment(
    dot(cellScalars, front), dot(cellScalars, back), frontGradient, backGradient, exit - entry, toEye);
  if (!(result.a > 0.0))
  {
    discard;
  }
  gl_FragData[0] = result;
}
