// Shared by the CVT shaders (spliced in at //CVT::Slots::Dec): site i lives in the texel
// (i % slotSize.x, i / slotSize.x) of the slot textures, and points are drawn into one texel
// of a target by placing them at its centre in clip space; and the pixel-grid helpers every
// pass uses.
ivec2 cvtSlotTexel(int id, ivec2 slotSize)
{
  return ivec2(id % slotSize.x, id / slotSize.x);
}

vec4 cvtPointInto(ivec2 texel, ivec2 targetSize, float depth)
{
  return vec4((vec2(texel) + 0.5) / vec2(targetSize) * 2.0 - 1.0, depth, 1.0);
}

// The depth of site i when n sites compete for a pixel: the lowest id wins a less-than test.
float cvtIdDepth(int id, int n)
{
  return (float(id) + 0.5) / float(n) * 2.0 - 1.0;
}

// Whether pixel q lies in a grid of gridSize pixels.
bool cvtInGrid(ivec2 q, ivec2 gridSize)
{
  return q.x >= 0 && q.y >= 0 && q.x < gridSize.x && q.y < gridSize.y;
}

// The pixel of vertex `vertexId` in a draw of one point per pixel of a grid, row by row.
ivec2 cvtVertexPixel(int vertexId, ivec2 gridSize)
{
  return ivec2(vertexId % gridSize.x, vertexId / gridSize.x);
}

// A clip-space position outside the view volume: the point is dropped.
const vec4 cvtCulled = vec4(2.0, 2.0, 2.0, 1.0);
