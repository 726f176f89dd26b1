//VTK::System::Dec
//VTK::Output::Dec
// vtkBarycentricShellMapper, isosurface stage (one pass per layer): per back-face fragment, the
// distance where the ray crosses each isovalue in this tetrahedron (closed form in barycentric
// coordinates, uvBarycentricShell.h IsovalueDistanceFromFace), kept when inside the tetrahedron, in
// front of opaque geometry and beyond the previous layer's hit; the nearest is written with its depth,
// so the depth test leaves each pixel's nearest such hit of any tetrahedron (depth peeling: layer k
// holds the pixel's k-th crossing). Lit (Phong) with the vertex gradients interpolated at the hit:
// target 0 the premultiplied colour, target 1 the hit's distance (the blending stage composites each
// in place). The gradients are the vertex gradients interpolated at the hit (UV_GRADIENTS) or the
// tetrahedron's own (UV_CELL_GRADIENTS).
//UV::BarycentricRay

uniform sampler2D isosurfaces;      // row 0 (r, g, b, opacity), row 1 (normalised value), ascending
uniform int isosurfaceCount;
#ifdef UV_GRADIENTS
uniform usamplerBuffer tetrahedronPoints;
uniform samplerBuffer pointGradients; // scalar gradient, model coordinates
uniform mat3 modelToEyeNormals;
#endif
uniform mat4 eyeToClip;
uniform float insideTolerance;
uniform int layer;
uniform sampler2D previousLayer; // r: the previous layer's hit distance (layer > 0)

//UV::Phong

void main()
{
  BarycentricRay ray = FragmentRay();
  float slope = dot(cellScalars, ray.perUnit);
  if (slope == 0.0)
  {
    discard;
  }
  float limit = OpaqueDistance();
  float at = dot(cellScalars, ray.face);
  float nearest = 3.0e38;
  int which = -1;
  float after = -1.0;
  if (layer > 0)
  {
    // Beyond the previous layer's hit, by a relative margin: a crossing on a face shared by two
    // tetrahedra is found by both, a float rounding apart.
    float previous = texelFetch(previousLayer, ivec2(gl_FragCoord.xy), 0).r;
    after = previous + 1e-5 * max(previous, 1e-3);
  }
  for (int i = 0; i < isosurfaceCount; ++i)
  {
    float value = texelFetch(isosurfaces, ivec2(i, 1), 0).r;
    float z = ray.distance + (value - at) / slope;
    if (z >= NearDistance(ray) && z > after && z < nearest && z <= limit &&
      SmallestCoordinate(CoordinatesAt(ray, z)) >= -insideTolerance)
    {
      nearest = z;
      which = i;
    }
  }
  if (which < 0)
  {
    discard;
  }
  vec4 b = CoordinatesAt(ray, nearest);
#ifdef UV_GRADIENTS
  uvec4 ids = texelFetch(tetrahedronPoints, cellId);
  vec3 gradient = vec3(0.0);
  for (int k = 0; k < 4; ++k)
    gradient += b[k] * texelFetch(pointGradients, int(ids[k])).xyz;
  gradient = modelToEyeNormals * gradient;
#else
  vec3 gradient = cellGradient; // per tetrahedron: flat facets, no gradient array needed
#endif
  vec3 point = EyePointAt(nearest);
  vec3 toEye = parallelProjection == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-point);
  vec4 surface = texelFetch(isosurfaces, ivec2(which, 0), 0);
  vec3 lit = Light(surface.rgb, gradient, toEye);
  vec4 clip = eyeToClip * vec4(point, 1.0);
  gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
  gl_FragData[0] = vec4(lit * surface.a, surface.a);
  gl_FragData[1] = vec4(nearest, 0.0, 0.0, 0.0);
}
