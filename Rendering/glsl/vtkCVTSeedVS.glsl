//VTK::System::Dec
//CVT::Slots::Dec
// Seeds the jump flooding: one point per site, drawn into the pixel that holds the site.
// Sites keep their float positions; the pixel only says where the flooding starts from.
//
// Two sites can fall in one pixel. The first pass keeps the lowest id there (depth test);
// the second pass gives every site that lost its pixel a free neighbouring pixel, so that
// it is not dropped from the diagram.
uniform sampler2D sites;  // site i's slot: (x, y) in grid units
uniform sampler2D placed; // second pass: the first pass's seeds
uniform ivec2 slotSize;
uniform ivec2 gridSize;
uniform int numberOfSites;
uniform int secondChance; // 0: first pass; 1: re-place the sites that lost their pixel
out vec4 result;

void main()
{
  int i = gl_VertexID;
  vec2 site = texelFetch(sites, cvtSlotTexel(i, slotSize), 0).xy;
  ivec2 pixel = clamp(ivec2(floor(site)), ivec2(0), gridSize - 1);
  result = vec4(site, float(i), 0.0);
  float depth = cvtIdDepth(i, numberOfSites); // lower id wins
  if (secondChance == 1)
  {
    bool lost = texelFetch(placed, pixel, 0).z != float(i);
    ivec2 free = ivec2(-1);
    for (int k = 0; k < 9 && lost && free.x < 0; ++k)
    {
      ivec2 q = pixel + ivec2(k % 3 - 1, k / 3 - 1);
      if (q.x >= 0 && q.y >= 0 && q.x < gridSize.x && q.y < gridSize.y &&
        texelFetch(placed, q, 0).z < 0.0)
      {
        free = q;
      }
    }
    if (free.x < 0)
    {
      gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // placed already (or no room): culled
      return;
    }
    pixel = free;
  }
  gl_Position = cvtPointInto(pixel, gridSize, depth);
}
