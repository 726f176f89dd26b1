//VTK::System::Dec
//VTK::Output::Dec
// vtkBarycentricShellMapper, blending stage (one full-screen pass per shell): the shell's slices of
// this pixel (uvBarycentricShellSliceFS.glsl: scalar + 1 inside the mesh; below 1 outside, with a
// record of where the mesh begins or ends when that is within a sample distance) composited front to
// back. Between two inside samples the scalar is taken as linear and the segment integrated with the
// transfer function (exactly, uvSegmentIntegrationLib.glsl, or by a read of the fixed-length segment
// table, UV_SEGMENT_TABLE); a segment with one inside end counts its recorded inside part (half when
// there is no record) at that end's scalar. The pixel's isosurface hits (uvBarycentricShellIsosurfaceFS.glsl, one layer
// each, nearest first) are composited in place, inside the segments that hold them. The result is
// blended under what earlier shells left (front to back: ONE_MINUS_DST_ALPHA, ONE).
in vec2 texCoord;

uniform sampler2D slices0;
#if UV_TARGETS > 1
uniform sampler2D slices1;
#endif
#if UV_TARGETS > 2
uniform sampler2D slices2;
#endif
#if UV_TARGETS > 3
uniform sampler2D slices3;
#endif
#if UV_TARGETS > 4
uniform sampler2D slices4;
#endif
#if UV_TARGETS > 5
uniform sampler2D slices5;
#endif
#if UV_TARGETS > 6
uniform sampler2D slices6;
#endif
#if UV_TARGETS > 7
uniform sampler2D slices7;
#endif
uniform sampler3D isosurfaceColor;    // per layer: premultiplied, lit
uniform sampler3D isosurfaceDistance; // per layer: r, the hit's distance (3e38: none)
uniform int isosurfaceLayers;         // layers drawn (0: no isosurface)
uniform float shellStart;
uniform float sampleDistance;
#ifdef UV_SEGMENT_TABLE
uniform sampler2D segmentTable; // (r, g, b, opacity) of a whole segment, front scalar x, back scalar y
uniform float segmentTableSize;
#endif

//UV::TransferFunction

//UV::Phong

//UV::SegmentIntegration

//UV::ShellRecord

/// An inside slice's scalar and density: its value is scalar + 1, raised by UV_DENSITY_STRIDE per
/// coincident copy past the first where the cell stands for several (uvBarycentricShellSliceFS.glsl).
vec2 ScalarAndDensity(float value)
{
#ifdef UV_CELL_DENSITIES
  float copies = floor((value - 1.5) / UV_DENSITY_STRIDE + 0.5); // the scalar is within [0, 1]
  return vec2(value - 1.0 - UV_DENSITY_STRIDE * copies, copies + 1.0);
#else
  return vec2(value - 1.0, 1.0);
#endif
}

#ifdef UV_SEGMENT_TABLE
/// A whole segment of one copy of the medium between two samples: the table's bilinear read.
vec4 TableSegment(float front, float back)
{
#ifdef UV_TEXTURE_UNIT_FILTER
  vec2 scalars = clamp(vec2(front, back), 0.0, 1.0);
  return textureLod(segmentTable, (scalars * (segmentTableSize - 1.0) + 0.5) / segmentTableSize, 0.0);
#else
  // Bilinear with float weights from four fetches: a texture unit's own filter may round its
  // weights (GL leaves their precision to the implementation; uvgl::ExactTextureFilter).
  vec2 x = clamp(vec2(front, back), 0.0, 1.0) * (segmentTableSize - 1.0);
  vec2 below = floor(x), f = x - below;
  int last = int(segmentTableSize) - 1;
  ivec2 i0 = min(ivec2(below), ivec2(last)), i1 = min(i0 + 1, ivec2(last));
  vec4 near = mix(texelFetch(segmentTable, i0, 0), texelFetch(segmentTable, ivec2(i1.x, i0.y), 0), f.x);
  vec4 far = mix(texelFetch(segmentTable, ivec2(i0.x, i1.y), 0), texelFetch(segmentTable, i1, 0), f.x);
  return mix(near, far, f.y);
#endif
}

/// `piece` (premultiplied) over `times` its length at the same scalars: the opacity compounds, the
/// colour follows in proportion (exact where the scalar is constant).
vec4 Compounded(vec4 piece, float times)
{
  float opacity = 1.0 - pow(max(1.0 - piece.a, 0.0), times);
  return vec4(piece.a > 0.0 ? piece.rgb * (opacity / piece.a) : vec3(0.0), opacity);
}
#endif

/// A whole segment between two samples through `density` copies of the medium: the table's read
/// (compounded), or the exact walk (density scales extinction and emission alike: the same as a
/// segment that much longer).
vec4 WholeSegment(float front, float back, float density)
{
#ifdef UV_SEGMENT_TABLE
  vec4 one = TableSegment(front, back);
  return density == 1.0 ? one : Compounded(one, density);
#else
  return IntegrateSegment(front, back, vec3(0.0), vec3(0.0), density * sampleDistance, vec3(0.0, 0.0, 1.0));
#endif
}

/// A stretch of `fraction` of a segment, the scalar linear from `front` to `back` along it.
vec4 ShortSegment(float front, float back, float fraction)
{
#ifdef UV_SEGMENT_TABLE
  return Compounded(TableSegment(front, back), fraction);
#else
  return IntegrateSegment(front, back, vec3(0.0), vec3(0.0), fraction * sampleDistance, vec3(0.0, 0.0, 1.0));
#endif
}

/// A fraction of a segment at a constant scalar (where the ray enters or leaves the mesh between two
/// samples; `fraction` counts copies of the medium too): from the table's whole constant segment
/// (opacity a over the whole: 1 - (1 - a)^f over the fraction f, colour in proportion), or from the
/// transfer function at the scalar.
vec4 PartialSegment(float scalar, float fraction)
{
#ifdef UV_SEGMENT_TABLE
  return Compounded(TableSegment(scalar, scalar), fraction);
#else
  vec4 node = EvaluateBetween(scalar, NodesAtOrBelow(scalar));
  float opacity = 1.0 - exp(-fraction * sampleDistance * node.a);
  return vec4(node.rgb * opacity, opacity);
#endif
}

/// How much of the segment next to an outside slice is inside the mesh, from the slice's record
/// (uvBarycentricShellRecordLib.glsl): an entry record when the mesh starts after it, an exit record
/// when it ended before it; half a segment when the slice holds no such record.
float InsideFraction(float record, bool entering)
{
  float base = entering ? EntryRecords : ExitRecords;
  return IsRecord(record, base) ? ReadRecord(record, base).x : 0.5;
}

vec4 result = vec4(0.0);
float transmittance = 1.0;

void Add(vec4 piece)
{
  result.rgb += transmittance * piece.rgb;
  transmittance *= 1.0 - piece.a;
}

/// Isosurface layer `layer`'s distance along the ray (3e38: none) and premultiplied, lit colour.
float HitDistance(ivec2 pixel, int layer)
{
  return texelFetch(isosurfaceDistance, ivec3(pixel, layer), 0).r;
}
vec4 HitColour(ivec2 pixel, int layer)
{
  return texelFetch(isosurfaceColor, ivec3(pixel, layer), 0);
}

/// The segment [near, far] between two samples inside the mesh: the scalar linear between them, cut
/// at each hit inside it (hits from `hit` on, up to hitCount; `hit` moves past them). Where the two
/// samples lie in cells of different densities (the segment crosses their face), each counts for
/// half.
void AddInsideSegment(ivec2 pixel, float previous, float next, float near, float far, inout int hit, int hitCount)
{
  const vec3 zero = vec3(0.0), toEye = vec3(0.0, 0.0, 1.0); // the volume is not lit here
  vec2 front = ScalarAndDensity(previous), back = ScalarAndDensity(next);
  float a = front.x, b = back.x, density = 0.5 * (front.y + back.y), from = 0.0;
  for (; hit < hitCount && HitDistance(pixel, hit) < far; ++hit)
  {
    float to = clamp((HitDistance(pixel, hit) - near) / sampleDistance, from, 1.0);
    Add(IntegrateSegment(
      mix(a, b, from), mix(a, b, to), zero, zero, density * (to - from) * sampleDistance, toEye));
    Add(HitColour(pixel, hit));
    from = to;
  }
  if (from == 0.0)
    Add(WholeSegment(a, b, density));
  else
    Add(IntegrateSegment(mix(a, b, from), b, zero, zero, density * (1.0 - from) * sampleDistance, toEye));
}

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 slice[8];
  slice[0] = texelFetch(slices0, pixel, 0);
#if UV_TARGETS > 1
  slice[1] = texelFetch(slices1, pixel, 0);
#endif
#if UV_TARGETS > 2
  slice[2] = texelFetch(slices2, pixel, 0);
#endif
#if UV_TARGETS > 3
  slice[3] = texelFetch(slices3, pixel, 0);
#endif
#if UV_TARGETS > 4
  slice[4] = texelFetch(slices4, pixel, 0);
#endif
#if UV_TARGETS > 5
  slice[5] = texelFetch(slices5, pixel, 0);
#endif
#if UV_TARGETS > 6
  slice[6] = texelFetch(slices6, pixel, 0);
#endif
#if UV_TARGETS > 7
  slice[7] = texelFetch(slices7, pixel, 0);
#endif
  // Most pixels of most shells hold no sample: nothing to integrate.
  vec4 any = slice[0];
  for (int t = 1; t < UV_TARGETS; ++t)
    any = max(any, slice[t]);
  if (max(max(any.x, any.y), max(any.z, any.w)) == 0.0 && isosurfaceLayers == 0)
  {
    discard;
  }
  // The layers come nearest first (depth peeling) and end in 3e38: this shell's hits are the layers
  // from the first at or beyond its start to the last that holds one, read in place (no array is
  // written at a per-pixel index: see uvHexahedralTraverseFS.glsl's cuts).
  int hit = 0, hitCount = 0; // the next hit, in distance order, and the end of the hits
  for (int layer = 0; layer < isosurfaceLayers; ++layer)
  {
    float distance = texelFetch(isosurfaceDistance, ivec3(pixel, layer), 0).r;
    hit += distance < shellStart ? 1 : 0; // composited by an earlier shell
    hitCount += distance < 1e37 ? 1 : 0;
  }
  float previous = slice[0].x;
  for (int k = 0; k + 1 < UV_SLICES; ++k)
  {
    float next = slice[(k + 1) >> 2][(k + 1) & 3];
    float near = shellStart + float(k) * sampleDistance, far = near + sampleDistance;
    bool previousInside = previous > 0.9, nextInside = next > 0.9;
    if (previousInside && nextInside)
    {
      AddInsideSegment(pixel, previous, next, near, far, hit, hitCount);
    }
    else if (!previousInside && !nextInside)
    {
      // Both outside: where an entry and an exit are recorded, the ray's whole stretch through the
      // mesh lies between the two samples (a silhouette, a thin part), from the nearest entry to the
      // last exit, the scalar linear between the recorded ones.
      if (IsRecord(previous, EntryRecords) && IsRecord(next, ExitRecords))
      {
        vec2 entry = ReadRecord(previous, EntryRecords), exit = ReadRecord(next, ExitRecords);
        Add(ShortSegment(entry.y, exit.y, max(entry.x + exit.x - 1.0, 0.0)));
      }
      for (; hit < hitCount && HitDistance(pixel, hit) < far; ++hit)
        Add(HitColour(pixel, hit));
    }
    else
    {
      // The ray enters or leaves the mesh (or meets opaque geometry) inside this segment: the part
      // inside, at the inside end's scalar; hits are composited before it when the ray enters here,
      // after it when it leaves.
      vec2 inside = ScalarAndDensity(previousInside ? previous : next);
      if (previousInside)
        Add(PartialSegment(inside.x, inside.y * clamp(InsideFraction(next, false), 0.0, 1.0)));
      for (; hit < hitCount && HitDistance(pixel, hit) < far; ++hit)
        Add(HitColour(pixel, hit));
      if (nextInside)
        Add(PartialSegment(inside.x, inside.y * clamp(InsideFraction(previous, true), 0.0, 1.0)));
    }
    previous = next;
  }
  result.a = 1.0 - transmittance;
  if (!(result.a > 0.0))
  {
    discard;
  }
  gl_FragData[0] = result;
}
