//VTK::System::Dec
//VTK::Output::Dec
// One jump flooding pass: every pixel looks at itself and its 8 neighbours stepLength pixels
// away and keeps the nearest site seen, measured from its centre in physical units.
// Texels hold (site x, site y, site id, 0) in grid units; id < 0 means "no site yet".
uniform sampler2D seeds;
uniform int stepLength;
uniform ivec2 gridSize;
uniform vec2 metric; // physical size of one pixel
in vec2 texCoord;    // from vtkOpenGLQuadHelper: pixel centre / grid size

void main()
{
  ivec2 p = ivec2(texCoord * vec2(gridSize));
  vec2 centre = vec2(p) + 0.5;
  vec4 best = vec4(0.0, 0.0, -1.0, 0.0);
  float bestDistance = 3.0e38;
  for (int dy = -1; dy <= 1; ++dy)
  {
    for (int dx = -1; dx <= 1; ++dx)
    {
      ivec2 q = p + ivec2(dx, dy) * stepLength;
      if (q.x < 0 || q.y < 0 || q.x >= gridSize.x || q.y >= gridSize.y)
      {
        continue;
      }
      vec4 candidate = texelFetch(seeds, q, 0);
      if (candidate.z < 0.0)
      {
        continue;
      }
      vec2 d = (candidate.xy - centre) * metric;
      float distance2 = dot(d, d);
      // Ties go to the lower id so the result does not depend on the visiting order.
      if (distance2 < bestDistance || (distance2 == bestDistance && candidate.z < best.z))
      {
        bestDistance = distance2;
        best = candidate;
      }
    }
  }
  gl_FragData[0] = best;
}
