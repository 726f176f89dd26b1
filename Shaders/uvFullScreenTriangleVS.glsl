//VTK::System::Dec
// One triangle covering the viewport, generated from gl_VertexID: no vertex buffer to bind.
// Used by the final pass that blends a mapper's premultiplied float image into VTK's scene.
out vec2 texCoord;

void main()
{
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  texCoord = corner;
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
