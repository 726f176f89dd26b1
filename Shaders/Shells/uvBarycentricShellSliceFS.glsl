//VTK::System::Dec
//VTK::Output::Dec
// vtkBarycentricShellMapper, slicing stage: this fragment's ray sampled at the shell's equidistant
// slices (UV_SLICES of them, four per float render target) inside its tetrahedron. The tetrahedron's
// stretch of the ray [entry, exit] comes from its barycentric coordinates (where they reach 0), and
// along it the scalar is linear: s(z) = s_face + (z - l) s', so every slice is a few vector operations,
// four at a time, with no per-sample inside test. A slice inside the stretch (with a hair of slack, so
// neighbours' rounding leaves no crack), in front of the eye and of opaque geometry, gets its
// normalised scalar plus one (>= 1); the targets are cleared to 0 and blended with MAX, so across all
// tetrahedra of the shell each slice ends with the scalar of the one holding it, and 0 means
// "outside the mesh" for any scalar range. With a bound image (UV_TEXTURE) the slices inside read it
// through the interpolated texture coordinates instead.
//UV::BarycentricRay

//UV::ShellRecord

uniform float shellStart;     // distance of the shell's first slice
uniform float sampleDistance; // between slices
#ifdef UV_CELL_DENSITIES
// Per tetrahedron, the coincident copies it stands for: its inside slices are raised by
// UV_DENSITY_STRIDE per copy past the first, read back by uvBarycentricShellBlendFS.glsl.
uniform samplerBuffer cellDensities;
#endif

/// The normalised scalar at distance z along the ray, inside the tetrahedron.
float ScalarAt(BarycentricRay ray, float z)
{
#ifdef UV_TEXTURE
  return ImageScalarAt(CoordinatesAt(ray, z));
#else
  return dot(cellScalars, CoordinatesAt(ray, z));
#endif
}

void main()
{
  BarycentricRay ray = FragmentRay();
  float slack = 1e-4 * sampleDistance;
  float entry = EntryDistance(ray), exit = min(ExitDistance(ray), OpaqueDistance());
  float from = entry - slack, to = exit + slack;
#ifdef UV_CELL_DENSITIES
  float raised = UV_DENSITY_STRIDE * (texelFetch(cellDensities, cellId).r - 1.0);
#else
  const float raised = 0.0;
#endif
  float atFace = dot(cellScalars, ray.face) + 1.0 + raised, slope = dot(cellScalars, ray.perUnit);
  // Where the stretch starts and ends between two slices, the slice just outside records it: how
  // much of the segment next to it is inside, and the scalar at the boundary (Record). Inside a
  // neighbour the slice holds >= 1 and the record loses the MAX; among records the MAX keeps the
  // nearest entry and the last exit (several tetrahedra may start or end between the same two
  // slices: the mesh begins at the first and ends at the last). Left alone, a record tells the
  // blending stage where the mesh (or the opaque geometry) begins or ends, and with what scalar: a
  // stretch lying wholly between two slices, as at a silhouette, is still integrated.
  float entrySlice = floor((entry - shellStart) / sampleDistance);
  float entryCode = entry > 0.0
    ? Record(EntryRecords, 1.0 - ((entry - shellStart) / sampleDistance - entrySlice), ScalarAt(ray, entry))
    : 0.0;
  float exitSlice = ceil((exit - shellStart) / sampleDistance);
  float exitCode =
    Record(ExitRecords, 1.0 - (exitSlice - (exit - shellStart) / sampleDistance), ScalarAt(ray, exit));
  vec4 values[UV_TARGETS];
  for (int t = 0; t < UV_TARGETS; ++t)
  {
    vec4 index = vec4(0.0, 1.0, 2.0, 3.0) + float(4 * t);
    vec4 z = shellStart + sampleDistance * index;
    vec4 inside = step(from, z) * step(z, vec4(to));
    vec4 codes = max(entryCode * vec4(equal(index, vec4(entrySlice))), exitCode * vec4(equal(index, vec4(exitSlice))));
#ifdef UV_TEXTURE
    // The bound image at each slice inside (one trilinear read each).
    vec4 scalars = vec4(0.0);
    for (int k = 0; k < 4; ++k)
    {
      if (inside[k] > 0.0)
        scalars[k] = ImageScalarAt(CoordinatesAt(ray, z[k])) + 1.0 + raised;
    }
    values[t] = mix(codes, scalars, inside);
#else
    values[t] = mix(codes, atFace + (z - ray.distance) * slope, inside);
#endif
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
