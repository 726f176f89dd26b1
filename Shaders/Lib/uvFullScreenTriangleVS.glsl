//VTK::System::Dec
// One triangle covering the viewport, generated from gl_VertexID: no vertex buffer to bind.
// Used by the final pass that blends a mapper's premultiplied float image into VTK's scene, and by
// full-screen passes. UV_AT_FAR_PLANE puts it at window depth 1, so that a depth test (GREATER)
// against a depth image keeps only the pixels where something was drawn into that image.
out vec2 texCoord;

void main()
{
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  texCoord = corner;
#ifdef UV_AT_FAR_PLANE
  gl_Position = vec4(corner * 2.0 - 1.0, 1.0, 1.0);
#else
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
#endif
}
