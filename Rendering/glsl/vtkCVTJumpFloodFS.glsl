//VTK::System::Dec
//CVT::Slots::Dec
//VTK::Output::Dec
// One jump flooding pass: every pixel that takes part looks at itself, its 8 neighbours
// stepLength pixels away and its seam partner (on an atlas) and keeps the nearest site seen.
// The texel layout, the distance, the identified borders and the seams come from the distance
// snippet (plane or geometry image).
uniform sampler2D seeds;
uniform int stepLength;
uniform ivec2 gridSize;
in vec2 texCoord; // from vtkOpenGLQuadHelper: pixel centre / grid size

//CVT::Distance::Dec

void main()
{
  ivec2 p = ivec2(texCoord * vec2(gridSize));
  vec4 here = cvtPixel(p);
  vec4 best = cvtNoSite;
  if (here.w > 0.0)
  {
    float bestDistance = 3.0e38;
    for (int n = 0; n < 10; ++n)
    {
      ivec2 q = n < 9 ? cvtWrap(p + ivec2(n % 3 - 1, n / 3 - 1) * stepLength) : cvtSeamPartner(p);
      if (!cvtInGrid(q, gridSize))
        continue;
      vec4 candidate = texelFetch(seeds, q, 0);
      if (cvtSiteId(candidate) < 0.0)
        continue;
      float distance2 = cvtDistance2(candidate, here);
      // Ties go to the lower id so the result does not depend on the visiting order.
      if (distance2 < bestDistance ||
        (distance2 == bestDistance && cvtSiteId(candidate) < cvtSiteId(best)))
      {
        bestDistance = distance2;
        best = candidate;
      }
    }
  }
  gl_FragData[0] = best;
}
