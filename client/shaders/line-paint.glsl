// The cube's lines painted over a pixel of the map (#include'd by colour.frag and present.frag,
// shader-include.ts): the line pass's coverage (line.frag: casing rule and coverage in rg, fill
// in ba) in the rules' colours, the fill over the casing, each pixel once. Painting them in
// the pass that puts the map on the canvas saves a full-screen pass of blending.

uniform sampler2D uLineCover;  // RGBA8, line.frag
uniform sampler2D uLineRules;  // line-rules.ts: row 0 fill colours, row 1 casing colours

// A rule's colour at `cover`, premultiplied; the rule is kept with 128 added where it covers half.
vec4 linePaint(float rule, float cover, int row) {
  vec4 c = texelFetch(uLineRules, ivec2(int(rule * 255.0 + 0.5) & 127, row), 0);
  float a = c.a * cover;
  return vec4(c.rgb * a, a);
}

vec3 withLines(vec3 colour, ivec2 p) {
  vec4 c = texelFetch(uLineCover, p, 0);
  if (c.g <= 0.0 && c.a <= 0.0) return colour;
  vec4 fill = linePaint(c.b, c.a, 0);
  vec4 lines = fill + linePaint(c.r, c.g, 1) * (1.0 - fill.a);
  return colour * (1.0 - lines.a) + lines.rgb;
}
