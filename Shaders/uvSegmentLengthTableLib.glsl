// A whole segment along which the scalar is linear, from one trilinear read of the table by front
// scalar, back scalar and length (vtkUnstructuredVolumeSegmentLengthTable; uvTetrahedronSegmentTable.h
// is the CPU twin): premultiplied colour and opacity, whatever the number of transfer-function nodes.
// Marker //UV::SegmentLengthTable.
uniform sampler3D segmentLengthTable;
uniform vec2 scalarToTexture; // texture coordinate = scalar * x + y (texel centres at 0 and 1)
uniform vec2 lengthToTexture; // the same for a length up to the table's longest

vec4 TableSegment(float frontScalar, float backScalar, float segmentLength)
{
  vec2 scalars = clamp(vec2(frontScalar, backScalar), 0.0, 1.0) * scalarToTexture.x + scalarToTexture.y;
  // Beyond the last texel's centre the clamped edge repeats it: lengths past the longest read it.
  return texture(segmentLengthTable, vec3(scalars, min(segmentLength * lengthToTexture.x + lengthToTexture.y, 1.0)));
}
