//VTK::System::Dec
//CVT::Slots::Dec
// Regional reduction, step 3 of 3 (Rong et al. 3.2): one point per pixel, moved to the slot of
// the pixel's site and summed there by additive float blending. The sums come from step 2.
uniform sampler2D seeds;     // final jump flooding result: (x, y, id, 0), grid units
uniform sampler2D collected; // per pixel: rho * (area, moments, second moment) of its site
uniform ivec2 gridSize;
uniform ivec2 slotSize;
uniform vec2 metric;       // physical size of one pixel
uniform float radiusScale; // 1 / smallest spacing: physical distance -> pixels

out vec4 cellSums;
out float cellRadius; // distance from the site to this pixel's centre, in pixels

void main()
{
  ivec2 p = cvtVertexPixel(gl_VertexID, gridSize);
  vec4 seed = texelFetch(seeds, p, 0);
  int id = int(seed.z);
  if (id < 0)
  {
    // No site reached this pixel: report an unbounded radius (in slot 0) so that the
    // engine's safeguard redoes the labelling with the full step.
    id = 0;
    cellSums = vec4(0.0);
    cellRadius = 3.0e38;
  }
  else
  {
    cellSums = texelFetch(collected, p, 0);
    cellRadius = length((vec2(p) + 0.5 - seed.xy) * metric) * radiusScale;
  }
  gl_Position = cvtPointInto(cvtSlotTexel(id, slotSize), slotSize, 0.0);
}
