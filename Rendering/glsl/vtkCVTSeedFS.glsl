//VTK::System::Dec
//VTK::Output::Dec
in vec4 seedValue;

void main()
{
  gl_FragData[0] = seedValue;
}
