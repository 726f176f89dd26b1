// A whole segment along which the scalar is linear, from one trilinear read of the table by front
// scalar, back scalar and length (vtkUnstructuredVolumeSegmentLengthTable; uvTetrahedronSegmentTable.h
// is the CPU twin): premultiplied colour and opacity, whatever the number of transfer-function nodes.
// Marker //UV::SegmentLengthTable.
uniform sampler3D segmentLengthTable;
uniform vec2 scalarToTexture; // texture coordinate = scalar * x + y (texel centres at 0 and 1)
// A length's coordinate: log(1 + length * x) * y + z (lengths spaced evenly in that logarithm, texel
// centres at 0 and the table's longest).
uniform vec3 lengthToTexture;

vec4 TableSegment(float frontScalar, float backScalar, float segmentLength)
{
  vec2 scalars = clamp(vec2(frontScalar, backScalar), 0.0, 1.0) * scalarToTexture.x + scalarToTexture.y;
  // Beyond the last texel's centre the clamped edge repeats it: lengths past the longest read it.
  float along = min(log(1.0 + segmentLength * lengthToTexture.x) * lengthToTexture.y + lengthToTexture.z, 1.0);
  return texture(segmentLengthTable, vec3(scalars, along));
}
