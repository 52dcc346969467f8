//VTK::System::Dec
//CVT::Slots::Dec
//VTK::Output::Dec
// Constrained centroids, step 1 of 2 (Rong et al. 4.3): every pixel labelled i finds the point
// nearest to the target of site i (its cell's 3D centroid) on the two triangles of its quad
// (pixels p, p + u, p + u + v, p + v of the regular triangulation); step 2 keeps the nearest
// per cell by the depth test.
//   gl_FragData[0] = (nearest point, distance), distance < 0: no candidate here
//   gl_FragData[1] = (index of the quad corner nearest to that point, 0, 0, 0)
uniform sampler2D seeds;   // (site x, y, z, id)
uniform sampler2D targets; // slot i: target of site i
uniform ivec2 gridSize;
uniform ivec2 slotSize;
in vec2 texCoord;

//CVT::Distance::Dec

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
vec3 closestOnTriangle(vec3 p, vec3 a, vec3 b, vec3 c)
{
  vec3 ab = b - a, ac = c - a, ap = p - a;
  float d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0)
    return a;
  vec3 bp = p - b;
  float d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3)
    return b;
  float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
    return a + ab * (d1 / (d1 - d3));
  vec3 cp = p - c;
  float d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6)
    return c;
  float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
    return a + ac * (d2 / (d2 - d6));
  float va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  float denominator = 1.0 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

void main()
{
  ivec2 p = ivec2(texCoord * vec2(gridSize));
  gl_FragData[0] = vec4(0.0, 0.0, 0.0, -1.0);
  gl_FragData[1] = vec4(0.0);
  float id = texelFetch(seeds, p, 0).w;
  ivec2 corner[4];
  corner[0] = p;
  corner[1] = cvtWrap(p + ivec2(1, 0));
  corner[2] = cvtWrap(p + ivec2(1, 1));
  corner[3] = cvtWrap(p + ivec2(0, 1));
  vec4 x[4];
  bool valid = id >= 0.0;
  for (int k = 0; k < 4; ++k)
  {
    valid = valid && cvtInGrid(corner[k], gridSize);
    x[k] = valid ? texelFetch(positions, corner[k], 0) : vec4(0.0);
    valid = valid && x[k].w > 0.0;
  }
  if (!valid)
  {
    return;
  }
  int i = int(id);
  vec3 target = texelFetch(targets, cvtSlotTexel(i, slotSize), 0).xyz;
  vec3 q0 = closestOnTriangle(target, x[0].xyz, x[1].xyz, x[2].xyz);
  vec3 q1 = closestOnTriangle(target, x[0].xyz, x[2].xyz, x[3].xyz);
  vec3 q = distance(q0, target) <= distance(q1, target) ? q0 : q1;
  int nearest = 0;
  for (int k = 1; k < 4; ++k)
  {
    if (distance(x[k].xyz, q) < distance(x[nearest].xyz, q))
    {
      nearest = k;
    }
  }
  gl_FragData[0] = vec4(q, distance(q, target));
  gl_FragData[1] = vec4(float(corner[nearest].y * gridSize.x + corner[nearest].x), 0.0, 0.0, 0.0);
}
