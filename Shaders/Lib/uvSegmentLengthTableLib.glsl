// A whole segment along which the scalar is linear, from one trilinear read of the table by front
// scalar, back scalar and length (vtkUnstructuredVolumeSegmentLengthTable; uvTetrahedronSegmentTable.h
// is the CPU twin): premultiplied colour and opacity, whatever the number of transfer-function nodes.
// Marker //UV::SegmentLengthTable.
uniform sampler3D segmentLengthTable;
uniform vec2 scalarToTexture; // texture coordinate = scalar * x + y (texel centres at 0 and 1)
// A length's coordinate: log(1 + length * x) * y + z (lengths spaced evenly in that logarithm, texel
// centres at 0 and the table's longest).
uniform vec3 lengthToTexture;

/// The table trilinearly interpolated at `coordinates` (texel centres at (i + 0.5) / size, clamped to
/// the edge), with float weights from eight texel fetches: a texture unit's own filter may round its
/// weights (GL leaves their precision to the implementation; GPUs and softpipe keep a few bits),
/// unless the driver is known to filter exactly (UV_TEXTURE_UNIT_FILTER).
vec4 TrilinearTable(vec3 coordinates)
{
#ifdef UV_TEXTURE_UNIT_FILTER
  return textureLod(segmentLengthTable, coordinates, 0.0); // exact on this driver (uvgl::ExactTextureFilter)
#else
  ivec3 size = textureSize(segmentLengthTable, 0);
  vec3 x = coordinates * vec3(size) - 0.5;
  vec3 below = floor(x), f = x - below;
  ivec3 i0 = clamp(ivec3(below), ivec3(0), size - 1), i1 = clamp(ivec3(below) + 1, ivec3(0), size - 1);
  vec4 c00 = mix(texelFetch(segmentLengthTable, i0, 0), texelFetch(segmentLengthTable, ivec3(i1.x, i0.yz), 0), f.x);
  vec4 c10 = mix(texelFetch(segmentLengthTable, ivec3(i0.x, i1.y, i0.z), 0),
    texelFetch(segmentLengthTable, ivec3(i1.xy, i0.z), 0), f.x);
  vec4 c01 = mix(texelFetch(segmentLengthTable, ivec3(i0.xy, i1.z), 0),
    texelFetch(segmentLengthTable, ivec3(i1.x, i0.y, i1.z), 0), f.x);
  vec4 c11 = mix(texelFetch(segmentLengthTable, ivec3(i0.x, i1.yz), 0), texelFetch(segmentLengthTable, i1, 0), f.x);
  return mix(mix(c00, c10, f.y), mix(c01, c11, f.y), f.z);
#endif
}

vec4 TableSegment(float frontScalar, float backScalar, float segmentLength)
{
  vec2 scalars = clamp(vec2(frontScalar, backScalar), 0.0, 1.0) * scalarToTexture.x + scalarToTexture.y;
  // Beyond the last texel's centre the clamped edge repeats it: lengths past the longest read it.
  float along = min(log(1.0 + segmentLength * lengthToTexture.x) * lengthToTexture.y + lengthToTexture.z, 1.0);
  return TrilinearTable(vec3(scalars, along));
}
