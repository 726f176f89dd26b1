//VTK::System::Dec
//VTK::Output::Dec
// vtkBarycentricShellMapper, slicing stage: this fragment's ray sampled at the shell's equidistant
// slices (UV_SLICES of them, four per float render target) in its tetrahedron's barycentric
// coordinates, only at the slices inside the tetrahedron's stretch of the ray. A sample inside the tetrahedron, and in front of the opaque geometry, writes its
// normalised scalar plus one (>= 1); the targets are cleared to 0 and blended with MAX, so across all
// tetrahedra of the shell each slice ends with the scalar of the one holding it, and 0 means
// "outside the mesh" for any scalar range.
//UV::BarycentricRay

uniform float shellStart;     // distance of the shell's first slice
uniform float sampleDistance; // between slices
uniform float insideTolerance;

void main()
{
  BarycentricRay ray = FragmentRay();
  float opaque = OpaqueDistance();
  vec4 values[8];
  for (int t = 0; t < 8; ++t)
    values[t] = vec4(0.0);
  // Only the slices between where the ray enters this tetrahedron and its back face.
  float entry = EntryDistance(ray);
  int first = max(0, int(ceil((entry - shellStart) / sampleDistance - 1e-3)));
  int last = min(UV_SLICES - 1, int(floor((ExitDistance(ray) - shellStart) / sampleDistance + 1e-3)));
  for (int k = first; k <= last; ++k)
  {
    float z = shellStart + float(k) * sampleDistance;
    vec4 b = CoordinatesAt(ray, z);
    if (SmallestCoordinate(b) >= -insideTolerance && z <= opaque && z >= 0.0)
      values[k >> 2][k & 3] = dot(cellScalars, b) + 1.0;
  }
  gl_FragData[0] = values[0];
#if UV_TARGETS > 1
  gl_FragData[1] = values[1];
#endif
#if UV_TARGETS > 2
  gl_FragData[2] = values[2];
#endif
#if UV_TARGETS > 3
  gl_FragData[3] = values[3];
#endif
#if UV_TARGETS > 4
  gl_FragData[4] = values[4];
#endif
#if UV_TARGETS > 5
  gl_FragData[5] = values[5];
#endif
#if UV_TARGETS > 6
  gl_FragData[6] = values[6];
#endif
#if UV_TARGETS > 7
  gl_FragData[7] = values[7];
#endif
}
