//VTK::System::Dec
//CVT::Slots::Dec
// Regional reduction on a geometry image: one point per pixel, moved to its site's slot; the
// pixel's area weight w gives w * (1, p - site) and w * |p - site|^2, summed by blending, and
// the pixel's distance in pixels from its site's pixel, kept at the largest (the adaptive step).
uniform sampler2D seeds;     // (site x, y, z, id)
uniform sampler2D positions; // (x, y, z, valid)
uniform sampler2D weights;   // area weight per pixel
uniform sampler2D sites;     // slot i: (x, y, z, pixel index)
uniform ivec2 gridSize;
uniform ivec2 slotSize;
uniform ivec2 wrap; // (wrap u, wrap v): identified borders are one pixel apart
out vec4 cellSums;    // w * (1, p - site)
out float cellEnergy; // w * |p - site|^2
out float cellRadius; // pixels from the site's pixel

void main()
{
  ivec2 p = cvtVertexPixel(gl_VertexID, gridSize);
  vec4 seed = texelFetch(seeds, p, 0);
  vec4 here = texelFetch(positions, p, 0);
  if (seed.w < 0.0 && here.w > 0.0)
  {
    // No site reached this surface pixel: report an unbounded radius (in slot 0) so that the
    // engine's safeguard redoes the labelling with the full step.
    cellSums = vec4(0.0);
    cellEnergy = 0.0;
    cellRadius = 3.0e38;
    gl_Position = cvtPointInto(ivec2(0), slotSize, 0.0);
    return;
  }
  if (seed.w < 0.0 || here.w <= 0.0)
  {
    gl_Position = cvtCulled;
    cellSums = vec4(0.0);
    cellEnergy = 0.0;
    cellRadius = 0.0;
    return;
  }
  int id = int(seed.w);
  float w = texelFetch(weights, p, 0).r;
  vec3 d = here.xyz - seed.xyz;
  cellSums = w * vec4(1.0, d);
  cellEnergy = w * dot(d, d);
  int pixel = int(texelFetch(sites, cvtSlotTexel(id, slotSize), 0).w);
  vec2 offset = abs(vec2(p - ivec2(pixel % gridSize.x, pixel / gridSize.x)));
  if (wrap.x != 0)
    offset.x = min(offset.x, float(gridSize.x) - offset.x);
  if (wrap.y != 0)
    offset.y = min(offset.y, float(gridSize.y) - offset.y);
  cellRadius = length(offset);
  gl_Position = cvtPointInto(cvtSlotTexel(id, slotSize), slotSize, 0.0);
}
