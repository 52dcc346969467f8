//VTK::System::Dec
//CVT::Slots::Dec
//VTK::Output::Dec
// Regional reduction, step 2 of 3: every pixel adds to its own piece the pieces of its
// neighbours that belong to its site and name it as their collector (see
// vtkCVTSplitPixelsFS.glsl), so that step 3 scatters a single point per pixel.
uniform sampler2D candidates; // id * 9 + collector for candidates 0..3, -1 for none
uniform sampler2D piece0;     // own piece
uniform sampler2D piece1;
uniform sampler2D piece2;
uniform sampler2D piece3;
uniform ivec2 gridSize;
in vec2 texCoord;

void main()
{
  ivec2 q = ivec2(texCoord * vec2(gridSize));
  float own = texelFetch(candidates, q, 0).x;
  vec4 total = texelFetch(piece0, q, 0);
  if (own >= 0.0)
  {
    float label = floor(own / 9.0);
    for (int dy = -1; dy <= 1; ++dy)
    {
      for (int dx = -1; dx <= 1; ++dx)
      {
        ivec2 p = q + ivec2(dx, dy);
        if ((dx == 0 && dy == 0) || !cvtInGrid(p, gridSize))
        {
          continue;
        }
        // Seen from p, this pixel is at offset (-dx, -dy).
        float wanted = label * 9.0 + float((1 - dy) * 3 + 1 - dx);
        vec4 codes = texelFetch(candidates, p, 0);
        if (codes.y == wanted)
        {
          total += texelFetch(piece1, p, 0);
        }
        else if (codes.z == wanted)
        {
          total += texelFetch(piece2, p, 0);
        }
        else if (codes.w == wanted)
        {
          total += texelFetch(piece3, p, 0);
        }
      }
    }
  }
  gl_FragData[0] = total;
}
