//VTK::System::Dec
//VTK::Output::Dec
// Lloyd update on the GPU: every site with mass moves to its cell's centroid.
uniform sampler2D sites; // (x, y) in grid units
uniform sampler2D sums;  // (mass, moment x, moment y, energy), physical units, moments about the site
uniform ivec2 slotSize;
uniform int numberOfSites;
uniform vec2 metric;
uniform ivec2 gridSize;
in vec2 texCoord; // from vtkOpenGLQuadHelper: slot centre / slot texture size

void main()
{
  ivec2 p = ivec2(texCoord * vec2(slotSize));
  int i = p.y * slotSize.x + p.x;
  vec4 site = texelFetch(sites, p, 0);
  vec4 cell = texelFetch(sums, p, 0);
  if (i < numberOfSites && cell.x > 0.0)
  {
    site.xy = clamp(site.xy + cell.yz / cell.x / metric, vec2(0.0), vec2(gridSize));
  }
  gl_FragData[0] = site;
}
