// The colour of one ray segment through a tetrahedron whose scalar (and gradient) is linear along it,
// premultiplied, front to back: the segment is cut where its scalar crosses a transfer-function node
// (PartialPreIntegration: colour and extinction linear on each piece, each piece integrated exactly
// with the Psi table; uvPreIntegration.h is the CPU twin) or integrated at the mean scalar
// (AverageScalar), and at each isovalue it crosses the surface's colour is composited, lit (Phong)
// with the gradient interpolated there. Shared by the fragment stages that integrate whole segments
// (marker //UV::SegmentIntegration, after //UV::TransferFunction and //UV::Phong).
uniform sampler2D isosurfaces;      // row 0 (r, g, b, opacity), row 1 (normalised value), ascending
uniform int isosurfaceCount;
uniform int averageScalar;          // 1: the paper's basic mode
uniform int shadeVolume;            // 1: light the volume's colours too (vtkVolumeProperty::Shade)

struct Sample
{
  vec3 color;
  float extinction;
};

Sample NodeSample(int k)
{
  vec4 n = NodeValue(k);
  return Sample(n.rgb, n.a);
}

/// The transfer function at s, given `below` = the number of nodes <= s.
Sample SampleBetween(float s, int below)
{
  vec4 n = EvaluateBetween(s, below);
  return Sample(n.rgb, n.a);
}

void CompositePiece(Sample front, Sample back, float pieceLength, inout vec4 result, inout float transmittance)
{
  float a = front.extinction * pieceLength, b = back.extinction * pieceLength;
  if (!(a + b > 0.0))
  {
    return;
  }
  float psi = Psi(a, b);
  float zeta = exp(-0.5 * (a + b));
  vec3 color = front.color * (1.0 - psi) + back.color * (psi - zeta);
  result.rgb += transmittance * color;
  transmittance *= zeta;
}

/// The segment from frontScalar to backScalar, `segmentLength` long, seen along `toEye`: premultiplied
/// (r, g, b, alpha).
vec4 IntegrateSegment(float frontScalar, float backScalar, vec3 frontGradient, vec3 backGradient,
  float segmentLength, vec3 toEye)
{
  vec4 result = vec4(0.0);
  float transmittance = 1.0;
  // Walk the cuts from front to back: nodes strictly between the end scalars, isovalues within.
  // One search per fragment: afterwards the walk knows which nodes bracket every cut.
  float span = backScalar - frontScalar;
  bool rising = span >= 0.0;
  int frontBelow = NodesAtOrBelow(frontScalar);
  // The next node along the walk: the first above the front (rising) or the last strictly below.
  int node = rising ? frontBelow : frontBelow - 1;
  if (!rising && node >= 0 && NodeScalar(node) >= frontScalar)
    node--;
  int iso = rising ? 0 : isosurfaceCount - 1;
  while (iso >= 0 && iso < isosurfaceCount)
  {
    float v = texelFetch(isosurfaces, ivec2(iso, 1), 0).r;
    if (rising ? v >= frontScalar : v <= frontScalar)
      break;
    iso += rising ? 1 : -1;
  }
  Sample previous;
  Sample constant;
  if (averageScalar == 1)
  {
    float middle = 0.5 * (frontScalar + backScalar);
    constant = SampleBetween(middle, NodesAtOrBelow(middle));
    previous = constant;
  }
  else
  {
    previous = SampleBetween(frontScalar, frontBelow);
  }
  if (shadeVolume == 1 && averageScalar == 0)
    previous.color = Light(previous.color, frontGradient, toEye);
  float previousFraction = 0.0;
  for (int guard = 0; guard < nodeCount + isosurfaceCount + 1; ++guard)
  {
    bool nodeValid = averageScalar == 0 && node >= 0 && node < nodeCount;
    float nodeValue = nodeValid ? NodeScalar(node) : backScalar;
    bool nodeInside = nodeValid && (rising ? nodeValue < backScalar : nodeValue > backScalar);
    bool isoValid = iso >= 0 && iso < isosurfaceCount;
    float isoValue = isoValid ? texelFetch(isosurfaces, ivec2(iso, 1), 0).r : backScalar;
    bool isoInside = isoValid && (rising ? isoValue <= backScalar : isoValue >= backScalar);
    bool takeIso = isoInside && (!nodeInside || (rising ? isoValue <= nodeValue : isoValue >= nodeValue));
    float cut = takeIso ? isoValue : (nodeInside ? nodeValue : backScalar);
    float fraction = span != 0.0 ? clamp((cut - frontScalar) / span, 0.0, 1.0) : 1.0;
    // Nodes at or below the cut: before reaching `node` rising, `node` of them; falling, node + 1.
    Sample next;
    if (averageScalar == 1)
      next = constant;
    else if (!takeIso && nodeInside)
      next = NodeSample(node);
    else
      next = SampleBetween(cut, rising ? node : node + 1);
    vec3 gradientHere = mix(frontGradient, backGradient, fraction);
    if (shadeVolume == 1 && averageScalar == 0)
      next.color = Light(next.color, gradientHere, toEye);
    CompositePiece(previous, next, segmentLength * (fraction - previousFraction), result, transmittance);
    previous = next;
    previousFraction = fraction;
    if (takeIso)
    {
      vec4 surface = texelFetch(isosurfaces, ivec2(iso, 0), 0);
      vec3 lit = Light(surface.rgb, gradientHere, toEye);
      result.rgb += transmittance * surface.a * lit;
      transmittance *= 1.0 - surface.a;
      iso += rising ? 1 : -1;
    }
    else if (nodeInside)
    {
      node += rising ? 1 : -1;
    }
    else
    {
      break;
    }
  }
  result.a = 1.0 - transmittance;
  return result;
}

/// A cell scalar's isosurfaces on the face a ray crosses from a cell of value `from` into one of
/// value `to` (uv::ForEachSurfaceBetweenCells: each value that separates them), composited in the
/// order the ray meets them and lit with the face's eye-space `normal`: premultiplied colour and alpha.
vec4 SurfacesBetweenCells(float from, float to, vec3 normal, vec3 toEye)
{
  vec4 surfaces = vec4(0.0);
  for (int i = 0; i < isosurfaceCount; ++i)
  {
    int k = from < to ? i : isosurfaceCount - 1 - i;
    float v = texelFetch(isosurfaces, ivec2(k, 1), 0).r;
    if ((from < v) != (to < v))
    {
      vec4 surface = texelFetch(isosurfaces, ivec2(k, 0), 0);
      surfaces.rgb += (1.0 - surfaces.a) * surface.a * Light(surface.rgb, normal, toEye);
      surfaces.a += (1.0 - surfaces.a) * surface.a;
    }
  }
  return surfaces;
}
