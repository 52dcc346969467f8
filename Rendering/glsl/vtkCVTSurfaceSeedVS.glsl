//VTK::System::Dec
//CVT::Slots::Dec
// Surface seeding: one point per site, drawn into the geometry-image pixel that holds it.
uniform sampler2D sites; // slot i: (x, y, z, pixel index)
uniform ivec2 slotSize;
uniform ivec2 gridSize;
uniform int numberOfSites;
out vec4 result;

void main()
{
  int i = gl_VertexID;
  vec4 site = texelFetch(sites, cvtSlotTexel(i, slotSize), 0);
  int pixel = int(site.w);
  // lower id wins a pixel
  gl_Position = cvtPointInto(ivec2(pixel % gridSize.x, pixel / gridSize.x), gridSize,
    cvtIdDepth(i, numberOfSites));
  result = vec4(site.xyz, float(i));
}
