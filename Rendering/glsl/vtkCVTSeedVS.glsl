//VTK::System::Dec
//CVT::Slots::Dec
// Seeds the jump flooding: one point per site, drawn into the pixel that holds the site. The
// texel layout, the site's pixel and which pixels take part come from the distance snippet
// (plane or geometry image). Sites keep their float positions; the pixel only says where the
// flooding starts from.
//
// Two sites can fall in one pixel. The first pass keeps the lowest id there (depth test);
// the second pass gives every site that lost its pixel the nearest free neighbouring pixel
// that takes part, so that it is not dropped from the diagram.
uniform sampler2D sites;  // site i's slot, read by cvtSeedPixel and cvtSeedTexel
uniform sampler2D placed; // second pass: the first pass's seeds
uniform ivec2 slotSize;
uniform ivec2 gridSize;
uniform int numberOfSites;
uniform int secondChance; // 0: first pass; 1: re-place the sites that lost their pixel
out vec4 result;

//CVT::Distance::Dec

void main()
{
  int i = gl_VertexID;
  vec4 slot = texelFetch(sites, cvtSlotTexel(i, slotSize), 0);
  ivec2 pixel = cvtSeedPixel(slot);
  result = cvtSeedTexel(slot, float(i));
  float depth = cvtIdDepth(i, numberOfSites); // lower id wins
  if (secondChance == 1)
  {
    // The free neighbour nearest to the site: the one the site's own cell most likely holds.
    bool lost = cvtSiteId(texelFetch(placed, pixel, 0)) != float(i);
    ivec2 free = ivec2(-1);
    float nearest = 3.0e38;
    for (int k = 0; k < 9 && lost; ++k)
    {
      ivec2 q = cvtWrap(pixel + ivec2(k % 3 - 1, k / 3 - 1));
      if (cvtInGrid(q, gridSize))
      {
        vec4 here = cvtPixel(q);
        float distance2 = cvtDistance2(result, here);
        if (here.w > 0.0 && cvtSiteId(texelFetch(placed, q, 0)) < 0.0 && distance2 < nearest)
        {
          free = q;
          nearest = distance2;
        }
      }
    }
    if (free.x < 0)
    {
      gl_Position = cvtCulled; // placed already, or no room
      return;
    }
    pixel = free;
  }
  gl_Position = cvtPointInto(pixel, gridSize, depth);
}
