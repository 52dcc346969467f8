//VTK::System::Dec
//CVT::Slots::Dec
// Constrained centroids, step 2 of 2: one point per pixel, moved to its site's slot with the
// distance as depth; the depth test keeps each cell's nearest point.
uniform sampler2D seeds;    // (site x, y, z, id)
uniform sampler2D nearest;  // (point, distance) from step 1
uniform sampler2D corners;  // pixel index holding that point
uniform ivec2 gridSize;
uniform ivec2 slotSize;
uniform float maximumDistance;
out vec4 result; // (point, pixel index)

void main()
{
  ivec2 p = cvtVertexPixel(gl_VertexID, gridSize);
  vec4 candidate = texelFetch(nearest, p, 0);
  float id = texelFetch(seeds, p, 0).w;
  result = vec4(candidate.xyz, texelFetch(corners, p, 0).r);
  if (candidate.w < 0.0 || id < 0.0)
  {
    gl_Position = cvtCulled;
    return;
  }
  int i = int(id);
  float depth = clamp(candidate.w / maximumDistance, 0.0, 1.0) * 2.0 - 1.0;
  gl_Position = cvtPointInto(cvtSlotTexel(i, slotSize), slotSize, depth);
}
