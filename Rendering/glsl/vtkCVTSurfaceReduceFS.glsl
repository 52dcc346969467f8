//VTK::System::Dec
//VTK::Output::Dec
// Targets 0 and 1 are summed by additive blending, target 2 kept at its maximum (GL_MAX).
in vec4 cellSums;
in float cellEnergy;
in float cellRadius;

void main()
{
  gl_FragData[0] = cellSums;
  gl_FragData[1] = vec4(cellEnergy, 0.0, 0.0, 0.0);
  gl_FragData[2] = vec4(cellRadius, 0.0, 0.0, 0.0);
}
