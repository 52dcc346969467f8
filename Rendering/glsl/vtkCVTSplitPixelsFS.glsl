//VTK::System::Dec
//CVT::Slots::Dec
//VTK::Output::Dec
// Regional reduction, step 1 of 3: split every pixel between the sites that may own part of it.
//
// A pixel is not given whole to the site nearest its centre: the distinct sites labelled in
// its 3x3 neighbourhood are its candidates, and the pixel square is cut between them by their
// bisectors (a square clipped by half-planes). Each piece's integrals are exact for a density
// constant over the pixel, so cell masses, moments and energies are those of the continuous
// Voronoi cells, not of whole-pixel staircases.
//
// Outputs, for candidates k = 0..3 (0 is the pixel's own label):
//   gl_FragData[0][k]   = id * 9 + collector, or -1: the collector is the neighbour (index
//                         (dy + 1) * 3 + dx + 1) labelled with that site that will add the
//                         piece to its own sums in step 2 (4, the pixel itself, for k = 0);
//   gl_FragData[1 + k]  = rho * (area, integral of (x - site), integral of |x - site|^2).
uniform sampler2D seeds;   // final jump flooding result: (x, y, id, 0), grid units
uniform sampler2D density; // one value per pixel
uniform ivec2 gridSize;
uniform vec2 metric;        // physical size of one pixel
uniform int candidateLimit; // 1: whole pixels to the nearest site; 4: split pixels
in vec2 texCoord;

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

// Boundary term of the polygon integrals for the edge a -> b (coordinates about the site):
// sums of these over a counter-clockwise boundary give 2 * area, 6 * first moments and
// 12 * second moment.
vec4 edgeTerm(vec2 a, vec2 b)
{
  float cross = a.x * b.y - b.x * a.y;
  return vec4(cross, (a + b) * cross, (dot(a, a) + dot(a, b) + dot(b, b)) * cross);
}

// Adds the part of edge a -> b where dot(x, normal) <= offset, and remembers where the
// boundary leaves and re-enters the half-plane.
void clipEdge(vec2 a, vec2 b, vec2 normal, float offset, inout vec4 sum, inout vec2 leave,
  inout vec2 enter, inout bool crossed)
{
  float da = dot(a, normal) - offset;
  float db = dot(b, normal) - offset;
  float denominator = da - db;
  vec2 crossing = mix(a, b, clamp(da / (denominator == 0.0 ? 1.0 : denominator), 0.0, 1.0));
  if (da <= 0.0 && db <= 0.0)
  {
    sum += edgeTerm(a, b);
  }
  else if (da <= 0.0)
  {
    sum += edgeTerm(a, crossing);
    leave = crossing;
    crossed = true;
  }
  else if (db <= 0.0)
  {
    sum += edgeTerm(crossing, b);
    enter = crossing;
  }
}

// Integrals of the square [lo, hi] cut by one half-plane: the common boundary pixel between
// two cells, in straight-line code (no arrays).
vec4 halfSquareIntegrals(vec2 lo, vec2 hi, vec2 normal, float offset)
{
  vec4 sum = vec4(0.0);
  vec2 leave = vec2(0.0);
  vec2 enter = vec2(0.0);
  bool crossed = false;
  clipEdge(lo, vec2(hi.x, lo.y), normal, offset, sum, leave, enter, crossed);
  clipEdge(vec2(hi.x, lo.y), hi, normal, offset, sum, leave, enter, crossed);
  clipEdge(hi, vec2(lo.x, hi.y), normal, offset, sum, leave, enter, crossed);
  clipEdge(vec2(lo.x, hi.y), lo, normal, offset, sum, leave, enter, crossed);
  if (crossed)
  {
    sum += edgeTerm(leave, enter);
  }
  return sum * vec4(0.5, 1.0 / 6.0, 1.0 / 6.0, 1.0 / 12.0);
}

// Appends x to the polygon held in v0..v4 (count m): registers, not an array.
void pushVertex(inout vec2 v0, inout vec2 v1, inout vec2 v2, inout vec2 v3, inout vec2 v4,
  inout int m, vec2 x)
{
  if (m == 0)
    v0 = x;
  else if (m == 1)
    v1 = x;
  else if (m == 2)
    v2 = x;
  else if (m == 3)
    v3 = x;
  else
    v4 = x;
  m = min(m + 1, 5);
}

// Keeps the part of the square edge a -> b where dot(x, normal) <= offset.
void cutSquareEdge(vec2 a, vec2 b, vec2 normal, float offset, inout vec2 v0, inout vec2 v1,
  inout vec2 v2, inout vec2 v3, inout vec2 v4, inout int m)
{
  float da = dot(a, normal) - offset;
  float db = dot(b, normal) - offset;
  if (da <= 0.0)
  {
    pushVertex(v0, v1, v2, v3, v4, m, a);
  }
  if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))
  {
    pushVertex(v0, v1, v2, v3, v4, m, mix(a, b, da / (da - db)));
  }
}

// Integrals of the square [lo, hi] cut by two half-planes: a pixel shared by three cells.
vec4 twiceCutSquareIntegrals(vec2 lo, vec2 hi, vec2 normal1, float offset1, vec2 normal2,
  float offset2)
{
  vec2 v0 = vec2(0.0), v1 = vec2(0.0), v2 = vec2(0.0), v3 = vec2(0.0), v4 = vec2(0.0);
  int m = 0;
  cutSquareEdge(lo, vec2(hi.x, lo.y), normal1, offset1, v0, v1, v2, v3, v4, m);
  cutSquareEdge(vec2(hi.x, lo.y), hi, normal1, offset1, v0, v1, v2, v3, v4, m);
  cutSquareEdge(hi, vec2(lo.x, hi.y), normal1, offset1, v0, v1, v2, v3, v4, m);
  cutSquareEdge(vec2(lo.x, hi.y), lo, normal1, offset1, v0, v1, v2, v3, v4, m);
  vec4 sum = vec4(0.0);
  vec2 leave = vec2(0.0);
  vec2 enter = vec2(0.0);
  bool crossed = false;
  if (m > 0)
    clipEdge(v0, m > 1 ? v1 : v0, normal2, offset2, sum, leave, enter, crossed);
  if (m > 1)
    clipEdge(v1, m > 2 ? v2 : v0, normal2, offset2, sum, leave, enter, crossed);
  if (m > 2)
    clipEdge(v2, m > 3 ? v3 : v0, normal2, offset2, sum, leave, enter, crossed);
  if (m > 3)
    clipEdge(v3, m > 4 ? v4 : v0, normal2, offset2, sum, leave, enter, crossed);
  if (m > 4)
    clipEdge(v4, v0, normal2, offset2, sum, leave, enter, crossed);
  if (crossed)
  {
    sum += edgeTerm(leave, enter);
  }
  return sum * vec4(0.5, 1.0 / 6.0, 1.0 / 6.0, 1.0 / 12.0);
}

void main()
{
  ivec2 p = ivec2(texCoord * vec2(gridSize));
  // Candidates as vectors, not arrays: software rasterisers keep arrays in memory.
  vec4 ids = vec4(-1.0);   // id * 9 + collector
  vec4 siteIds = vec4(-1.0);
  vec4 siteX = vec4(0.0);
  vec4 siteY = vec4(0.0);
  int count = 0;
  vec4 own = texelFetch(seeds, p, 0);
  if (own.z >= 0.0)
  {
    ids.x = own.z * 9.0 + 4.0;
    siteIds.x = own.z;
    siteX.x = own.x;
    siteY.x = own.y;
    count = 1;
  }
  int limit = min(MaxCandidates, candidateLimit);
  for (int n = 0; n < 9; ++n)
  {
    ivec2 q = p + ivec2(n % 3 - 1, n / 3 - 1);
    if (n == 4 || count == 0 || !cvtInGrid(q, gridSize))
    {
      continue;
    }
    vec4 s = texelFetch(seeds, q, 0);
    if (s.z >= 0.0 && !any(equal(siteIds, vec4(s.z))) && count < limit)
    {
      ids[count] = s.z * 9.0 + float(n);
      siteIds[count] = s.z;
      siteX[count] = s.x;
      siteY[count] = s.y;
      ++count;
    }
  }

  float rho = texelFetch(density, p, 0).r;
  vec4 pieces[MaxCandidates];
  for (int k = 0; k < MaxCandidates; ++k)
  {
    pieces[k] = vec4(0.0);
  }
  if (count == 1)
  {
    // Interior pixel: the whole square, about the site.
    vec2 centre = (vec2(p) + 0.5 - vec2(siteX.x, siteY.x)) * metric;
    float area = metric.x * metric.y;
    pieces[0] = rho * area * vec4(1.0, centre, dot(centre, centre) + dot(metric, metric) / 12.0);
  }
  if (count == 2)
  {
    // Two cells share the pixel: one cut each way.
    vec2 s0 = vec2(siteX.x, siteY.x);
    vec2 s1 = vec2(siteX.y, siteY.y);
    vec2 d = (s1 - s0) * metric;
    float offset = 0.5 * dot(d, d);
    vec2 lo0 = (vec2(p) - s0) * metric;
    vec2 lo1 = (vec2(p) - s1) * metric;
    pieces[0] = rho * halfSquareIntegrals(lo0, lo0 + metric, d, offset);
    pieces[1] = rho * halfSquareIntegrals(lo1, lo1 + metric, -d, offset);
  }
  if (count == 3)
  {
    // Three cells share the pixel (near a Voronoi vertex): two cuts per piece.
    for (int k = 0; k < 3; ++k)
    {
      vec2 site = vec2(siteX[k], siteY[k]);
      vec2 a = (vec2(siteX[(k + 1) % 3], siteY[(k + 1) % 3]) - site) * metric;
      vec2 b = (vec2(siteX[(k + 2) % 3], siteY[(k + 2) % 3]) - site) * metric;
      vec2 lo = (vec2(p) - site) * metric;
      pieces[k] =
        rho * twiceCutSquareIntegrals(lo, lo + metric, a, 0.5 * dot(a, a), b, 0.5 * dot(b, b));
    }
  }
  // Four cells: clip the square by every bisector. The loop runs zero times when no pixel of
  // a shading group needs it (software rasterisers execute both sides of an if in lockstep,
  // but leave a loop once no pixel needs it).
  int generalCount = count > 3 ? count : 0;
  for (int k = 0; k < generalCount; ++k)
  {
    vec2 site = vec2(siteX[k], siteY[k]);
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
        vec2 d = (vec2(siteX[c], siteY[c]) - site) * metric;
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
    pieces[k] = rho * vec4(0.5 * area, moment / 6.0, second / 12.0);
  }
  gl_FragData[0] = ids;
  gl_FragData[1] = pieces[0];
  gl_FragData[2] = pieces[1];
  gl_FragData[3] = pieces[2];
  gl_FragData[4] = pieces[3];
}
