//VTK::System::Dec
// Surface seeding: one point per site, drawn into the geometry-image pixel that holds it.
uniform sampler2D sites; // slot i: (x, y, z, pixel index)
uniform ivec2 slotSize;
uniform ivec2 gridSize;
uniform int numberOfSites;
out vec4 result;

void main()
{
  int i = gl_VertexID;
  vec4 site = texelFetch(sites, ivec2(i % slotSize.x, i / slotSize.x), 0);
  int pixel = int(site.w);
  vec2 p = vec2(pixel % gridSize.x, pixel / gridSize.x) + 0.5;
  float depth = (float(i) + 0.5) / float(numberOfSites) * 2.0 - 1.0; // lower id wins a pixel
  gl_Position = vec4(p / vec2(gridSize) * 2.0 - 1.0, depth, 1.0);
  result = vec4(site.xyz, float(i));
}
