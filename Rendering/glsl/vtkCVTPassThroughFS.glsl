//VTK::System::Dec
//VTK::Output::Dec
// Writes what the vertex shader hands over.
in vec4 result;

void main()
{
  gl_FragData[0] = result;
}
