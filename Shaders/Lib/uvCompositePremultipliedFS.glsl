//VTK::System::Dec
//VTK::Output::Dec
// Copies a premultiplied RGBA image; drawn with blending (ONE, ONE_MINUS_SRC_ALPHA) it composites the
// volume over what VTK already drew.
in vec2 texCoord;
uniform sampler2D premultipliedImage;

void main()
{
  gl_FragData[0] = texture(premultipliedImage, texCoord);
}
