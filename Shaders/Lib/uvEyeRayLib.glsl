// The eye ray through a pixel, in model space from the near plane (uniforms nearPlane[3] and
// rayDirection[3], set by the mapper in double). Shared by the ray-casting passes of the hexahedral
// mapper and the tetrahedra mapper (marker //UV::EyeRay).

/// The pixel at `fragCoord` in normalised device coordinates.
vec2 PixelNdc(vec2 fragCoord, vec2 viewportSize)
{
  return fragCoord / viewportSize * 2.0 - 1.0;
}

/// The ray through `ndc` in model space, from the near plane, unit direction. The near-plane point
/// and the direction (far minus near point) are affine in ndc for every camera projection; the
/// mapper gives their coefficients (at ndc 0, per unit x, per unit y), computed in double: unprojecting
/// through a float clip-to-model matrix loses the direction when the far plane is far beyond the near.
void EyeRay(vec2 ndc, vec3 nearPlane[3], vec3 rayDirection[3], out vec3 origin, out vec3 direction)
{
  origin = nearPlane[0] + ndc.x * nearPlane[1] + ndc.y * nearPlane[2];
  direction = normalize(rayDirection[0] + ndc.x * rayDirection[1] + ndc.y * rayDirection[2]);
}

/// The depth an entry pass writes for ray parameter t, so that the depth test keeps the nearest face
/// by t itself: the window depth resolves distance ever more coarsely past the near plane (with the
/// square of the distance over the near plane's), and faces a cell apart can round to one depth
/// there. Increasing in t, steepest at `centreT` (where the ray passes the mesh's centre) and spread
/// over `radius` (the mesh's), so float keeps its resolution across the whole mesh.
float RayParameterDepth(float t, float centreT, float radius)
{
  float fromCentre = t - centreT;
  return 0.5 + 0.5 * fromCentre / (abs(fromCentre) + radius + 1e-30);
}
