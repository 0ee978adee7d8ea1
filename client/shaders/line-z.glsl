// A line's width and ends at a z (#include'd by line.vert and line.frag, shader-include.ts):
// its ramps (format/line-ramp.ts, rampShare) and its vertices' glides (format/line-glide.ts).

// z0, z0Full, z1Full, z1: 0 at the ends, 1 between the full points, linear in z between.
float share(vec4 r, float z) {
  float grow = r.y > r.x ? (z - r.x) / (r.y - r.x) : 1.0;
  float shrink = r.w > r.z ? (r.w - z) / (r.w - r.z) : 1.0;
  return clamp(min(grow, shrink), 0.0, 1.0);
}

// How far along its glide an end is at z, gliding over [from, to]: 0 before it, 1 at its end and after (glideShare).
float glide(float from, float to, float z) {
  if (!(to > from)) return z >= to ? 1.0 : 0.0;
  return clamp((z - from) / (to - from), 0.0, 1.0);
}
