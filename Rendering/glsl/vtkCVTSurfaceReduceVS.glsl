//VTK::System::Dec
//CVT::Slots::Dec
// Regional reduction on a geometry image: one point per pixel, moved to its site's slot; the
// pixel's area weight w gives w * (1, p - site) and w * |p - site|^2, summed by blending.
uniform sampler2D seeds;     // (site x, y, z, id)
uniform sampler2D positions; // (x, y, z, valid)
uniform sampler2D weights;   // area weight per pixel
uniform ivec2 gridSize;
uniform ivec2 slotSize;
out vec4 cellSums;   // w * (1, p - site)
out float cellEnergy; // w * |p - site|^2

void main()
{
  ivec2 p = ivec2(gl_VertexID % gridSize.x, gl_VertexID / gridSize.x);
  vec4 seed = texelFetch(seeds, p, 0);
  vec4 here = texelFetch(positions, p, 0);
  if (seed.w < 0.0 || here.w <= 0.0)
  {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // culled
    cellSums = vec4(0.0);
    cellEnergy = 0.0;
    return;
  }
  float w = texelFetch(weights, p, 0).r;
  vec3 d = here.xyz - seed.xyz;
  cellSums = w * vec4(1.0, d);
  cellEnergy = w * dot(d, d);
  int id = int(seed.w);
  gl_Position = cvtPointInto(cvtSlotTexel(id, slotSize), slotSize, 0.0);
}
