//VTK::System::Dec
//VTK::Output::Dec
// Target 0 is summed by additive blending, target 1 kept at its maximum (GL_MAX blending).
in vec4 cellSums;
in float cellRadius;

void main()
{
  gl_FragData[0] = cellSums;
  gl_FragData[1] = vec4(cellRadius, 0.0, 0.0, 0.0);
}
