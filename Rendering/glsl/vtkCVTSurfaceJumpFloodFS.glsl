//VTK::System::Dec
//VTK::Output::Dec
// One jump flooding pass on a geometry image: distances are 3D Euclidean distances between the
// surface point of this pixel and the candidate sites; borders identified by the wrap flags
// are neighbours; masked pixels take no part. Texels: (site x, y, z, id), id < 0: none.
uniform sampler2D seeds;
uniform sampler2D positions; // (x, y, z, valid)
uniform int stepLength;
uniform ivec2 gridSize;
uniform ivec2 wrap; // (wrap u, wrap v)
in vec2 texCoord;

void main()
{
  ivec2 p = ivec2(texCoord * vec2(gridSize));
  vec4 here = texelFetch(positions, p, 0);
  vec4 best = vec4(0.0, 0.0, 0.0, -1.0);
  if (here.w > 0.0)
  {
    float bestDistance = 3.0e38;
    for (int n = 0; n < 9; ++n)
    {
      ivec2 q = p + ivec2(n % 3 - 1, n / 3 - 1) * stepLength;
      if (wrap.x != 0)
        q.x = (q.x % gridSize.x + gridSize.x) % gridSize.x;
      if (wrap.y != 0)
        q.y = (q.y % gridSize.y + gridSize.y) % gridSize.y;
      if (q.x < 0 || q.y < 0 || q.x >= gridSize.x || q.y >= gridSize.y)
        continue;
      vec4 candidate = texelFetch(seeds, q, 0);
      if (candidate.w < 0.0)
        continue;
      vec3 d = candidate.xyz - here.xyz;
      float distance2 = dot(d, d);
      if (distance2 < bestDistance || (distance2 == bestDistance && candidate.w < best.w))
      {
        bestDistance = distance2;
        best = candidate;
      }
    }
  }
  gl_FragData[0] = best;
}
