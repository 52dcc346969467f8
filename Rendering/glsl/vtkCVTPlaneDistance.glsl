// Jump flooding in the plane (spliced in at //CVT::Distance::Dec): texels hold (site x, site y,
// site id, 0) in grid units, distances are measured from pixel centres in physical units
// (metric: the size of one pixel), every pixel takes part and borders are not identified.
// Site slots hold (x, y) in grid units.
uniform vec2 metric;
const vec4 cvtNoSite = vec4(0.0, 0.0, -1.0, 0.0);

float cvtSiteId(vec4 texel)
{
  return texel.z;
}

vec4 cvtPixel(ivec2 p)
{
  return vec4(vec2(p) + 0.5, 0.0, 1.0);
}

ivec2 cvtWrap(ivec2 q)
{
  return q;
}

ivec2 cvtSeamPartner(ivec2 p)
{
  return ivec2(-1); // the plane has no seams
}

float cvtDistance2(vec4 site, vec4 here)
{
  vec2 d = (site.xy - here.xy) * metric;
  return dot(d, d);
}

ivec2 cvtSeedPixel(vec4 slot)
{
  return clamp(ivec2(floor(slot.xy)), ivec2(0), gridSize - 1);
}

vec4 cvtSeedTexel(vec4 slot, float id)
{
  return vec4(slot.xy, id, 0.0);
}
