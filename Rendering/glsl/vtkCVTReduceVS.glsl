//VTK::System::Dec
// Regional reduction, one point per (pixel, candidate site): the vertex shader moves the point
// to the slot of its site and hands the fragment shader that site's share of the pixel.
//
// A pixel is not given whole to the site nearest its centre: the distinct sites labelled in
// its 3x3 neighbourhood are the candidates, and the pixel square is split between them by
// their bisectors (clipping a square by half-planes). The integrals of each piece are exact
// for a density that is constant over the pixel, so cell masses, moments and energies are
// those of the continuous Voronoi cells, not of whole-pixel staircases.
//
// Instance k handles the k-th candidate; instances beyond the candidate count are culled.
uniform sampler2D seeds;   // final jump flooding result: (x, y, id, 0), grid units
uniform sampler2D density; // one value per pixel
uniform ivec2 gridSize;
uniform ivec2 slotSize;
uniform vec2 metric;        // physical size of one pixel
uniform float radiusScale;  // 1 / smallest spacing: physical distance -> pixels
uniform int candidateLimit; // 1: whole pixels to the nearest site; MaxCandidates: split pixels

out vec4 cellSums;   // rho * (area, integral of (x - site), integral of |x - site|^2)
out float cellRadius; // distance from the labelled site to this pixel's centre, in pixels

const int MaxCandidates = 4;
const int MaxVertices = 8;

vec2 polygon[MaxVertices];
int vertexCount;

// Keeps the part of the polygon where dot(x, normal) <= offset.
void clipPolygon(vec2 normal, float offset)
{
  vec2 clipped[MaxVertices];
  int count = 0;
  for (int i = 0; i < vertexCount; ++i)
  {
    vec2 a = polygon[i];
    vec2 b = polygon[(i + 1) % vertexCount];
    float da = dot(a, normal) - offset;
    float db = dot(b, normal) - offset;
    if (da <= 0.0 && count < MaxVertices)
    {
      clipped[count++] = a;
    }
    if (((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) && count < MaxVertices)
    {
      clipped[count++] = mix(a, b, da / (da - db));
    }
  }
  for (int i = 0; i < count; ++i)
  {
    polygon[i] = clipped[i];
  }
  vertexCount = count;
}

void main()
{
  ivec2 p = ivec2(gl_VertexID % gridSize.x, gl_VertexID / gridSize.x);

  vec3 candidates[MaxCandidates];
  int count = 0;
  vec4 own = texelFetch(seeds, p, 0);
  if (own.z >= 0.0)
  {
    candidates[count++] = own.xyz;
  }
  for (int dy = -1; dy <= 1; ++dy)
  {
    for (int dx = -1; dx <= 1; ++dx)
    {
      ivec2 q = p + ivec2(dx, dy);
      if ((dx == 0 && dy == 0) || q.x < 0 || q.y < 0 || q.x >= gridSize.x || q.y >= gridSize.y)
      {
        continue;
      }
      vec4 s = texelFetch(seeds, q, 0);
      bool known = s.z < 0.0;
      for (int c = 0; c < count; ++c)
      {
        known = known || candidates[c].z == s.z;
      }
      if (!known && count < min(MaxCandidates, candidateLimit))
      {
        candidates[count++] = s.xyz;
      }
    }
  }

  int k = gl_InstanceID;
  if (count == 0 && k == 0)
  {
    // No site reached this pixel: report an unbounded radius (in slot 0) so that the
    // engine's safeguard redoes the labelling with the full step.
    gl_Position = vec4(vec2(0.5) / vec2(slotSize) * 2.0 - 1.0, 0.0, 1.0);
    cellSums = vec4(0.0);
    cellRadius = 3.0e38;
    return;
  }
  if (k >= count)
  {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // outside the clip volume: culled
    cellSums = vec4(0.0);
    cellRadius = 0.0;
    return;
  }

  vec2 site = candidates[k].xy;
  vec2 lo = (vec2(p) - site) * metric;
  vec2 hi = lo + metric;
  polygon[0] = lo;
  polygon[1] = vec2(hi.x, lo.y);
  polygon[2] = hi;
  polygon[3] = vec2(lo.x, hi.y);
  vertexCount = 4;
  for (int c = 0; c < count; ++c)
  {
    if (c != k)
    {
      vec2 d = (candidates[c].xy - site) * metric;
      clipPolygon(d, 0.5 * dot(d, d));
    }
  }

  float area = 0.0;
  vec2 moment = vec2(0.0);
  float second = 0.0;
  for (int i = 0; i < vertexCount; ++i)
  {
    vec2 a = polygon[i];
    vec2 b = polygon[(i + 1) % vertexCount];
    float cross = a.x * b.y - b.x * a.y;
    area += cross;
    moment += (a + b) * cross;
    second += (dot(a, a) + dot(a, b) + dot(b, b)) * cross;
  }
  float rho = texelFetch(density, p, 0).r;
  cellSums = rho * vec4(0.5 * area, moment / 6.0, second / 12.0);
  cellRadius = (k == 0) ? length((vec2(p) + 0.5 - site) * metric) * radiusScale : 0.0;

  int id = int(candidates[k].z);
  vec2 slot = vec2(id % slotSize.x, id / slotSize.x) + 0.5;
  gl_Position = vec4(slot / vec2(slotSize) * 2.0 - 1.0, 0.0, 1.0);
}
