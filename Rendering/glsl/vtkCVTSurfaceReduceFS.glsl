//VTK::System::Dec
//VTK::Output::Dec
// Both targets are summed by additive blending.
in vec4 cellSums;
in float cellEnergy;

void main()
{
  gl_FragData[0] = cellSums;
  gl_FragData[1] = vec4(cellEnergy, 0.0, 0.0, 0.0);
}
