//VTK::System::Dec
//VTK::Output::Dec
// vtkBarycentricShellMapper, blending stage (one full-screen pass per shell): the shell's slices of
// this pixel (uvBarycentricShellSliceFS.glsl: scalar + 1 inside the mesh, 0 outside) composited front
// to back. Between two inside samples the scalar is taken as linear and the segment integrated with
// the transfer function exactly (pre-integrated, uvSegmentIntegrationLib.glsl); a segment with one
// inside end is counted as half a segment at that end's scalar (where the ray enters or leaves the
// mesh between samples). The nearest isosurface hit of the pixel (uvBarycentricShellIsosurfaceFS.glsl)
// is composited inside the segment that holds it. The result is blended under what earlier shells
// left (front to back: ONE_MINUS_DST_ALPHA, ONE).
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
uniform sampler2D isosurfaceColor;    // premultiplied, lit
uniform sampler2D isosurfaceDistance; // r: distance of the hit, or a negative value for none
uniform int drawIsosurfaces;
uniform float shellStart;
uniform float sampleDistance;

//UV::TransferFunction

//UV::Phong

//UV::SegmentIntegration

vec4 result = vec4(0.0);
float transmittance = 1.0;

void Add(vec4 piece)
{
  result.rgb += transmittance * piece.rgb;
  transmittance *= 1.0 - piece.a;
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
  float hit = -1.0;
  vec4 surface = vec4(0.0);
  if (drawIsosurfaces == 1)
  {
    hit = texelFetch(isosurfaceDistance, pixel, 0).r;
    surface = texelFetch(isosurfaceColor, pixel, 0);
  }
  const vec3 zero = vec3(0.0), toEye = vec3(0.0, 0.0, 1.0); // the volume is not lit here
  float previous = slice[0].x;
  for (int k = 0; k + 1 < UV_SLICES; ++k)
  {
    float next = slice[(k + 1) >> 2][(k + 1) & 3];
    float near = shellStart + float(k) * sampleDistance;
    bool previousInside = previous > 0.5, nextInside = next > 0.5;
    bool holdsHit = hit >= near && hit < near + sampleDistance;
    if (previousInside && nextInside)
    {
      float a = previous - 1.0, b = next - 1.0;
      if (holdsHit)
      {
        float f = (hit - near) / sampleDistance, middle = mix(a, b, f);
        Add(IntegrateSegment(a, middle, zero, zero, f * sampleDistance, toEye));
        Add(surface);
        Add(IntegrateSegment(middle, b, zero, zero, (1.0 - f) * sampleDistance, toEye));
      }
      else
      {
        Add(IntegrateSegment(a, b, zero, zero, sampleDistance, toEye));
      }
    }
    else
    {
      float inside = previousInside ? previous - 1.0 : next - 1.0;
      bool partial = previousInside || nextInside;
      if (holdsHit && !previousInside)
        Add(surface);
      if (partial)
        Add(IntegrateSegment(inside, inside, zero, zero, 0.5 * sampleDistance, toEye));
      if (holdsHit && previousInside)
        Add(surface);
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
