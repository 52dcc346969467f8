// Jump flooding on a geometry image (spliced in at //CVT::Distance::Dec): texels hold (site x,
// y, z, id), distances are 3D Euclidean distances from the pixel's surface point, borders
// identified by the wrap flags are neighbours, masked pixels (w = 0) take no part, and an
// atlas's chart-border pixels also look at their seam partner, the pixel where the surface goes
// on in another chart. Site slots hold (x, y, z, index of the pixel that holds the site).
uniform sampler2D positions; // (x, y, z, valid)
uniform ivec2 wrap;          // (wrap u, wrap v)
uniform sampler2D seams;     // per pixel: (i, j) of its seam partner, (-1, -1) for none
uniform int hasSeams;
const vec4 cvtNoSite = vec4(0.0, 0.0, 0.0, -1.0);

float cvtSiteId(vec4 texel)
{
  return texel.w;
}

vec4 cvtPixel(ivec2 p)
{
  return texelFetch(positions, p, 0);
}

ivec2 cvtWrap(ivec2 q)
{
  if (wrap.x != 0)
    q.x = (q.x % gridSize.x + gridSize.x) % gridSize.x;
  if (wrap.y != 0)
    q.y = (q.y % gridSize.y + gridSize.y) % gridSize.y;
  return q;
}

// The pixel where the surface goes on across a chart border, or (-1, -1).
ivec2 cvtSeamPartner(ivec2 p)
{
  return hasSeams != 0 ? ivec2(texelFetch(seams, p, 0).xy) : ivec2(-1);
}

float cvtDistance2(vec4 site, vec4 here)
{
  vec3 d = site.xyz - here.xyz;
  return dot(d, d);
}

ivec2 cvtSeedPixel(vec4 slot)
{
  int pixel = int(slot.w);
  return ivec2(pixel % gridSize.x, pixel / gridSize.x);
}

vec4 cvtSeedTexel(vec4 slot, float id)
{
  return vec4(slot.xyz, id);
}
