#version 300 es
// Line pass: the lines' coverage (line.frag: casing rule and coverage in rg, fill in ba) painted
// over the map in the rules' colours, premultiplied (blend ONE, ONE_MINUS_SRC_ALPHA): the
// fill over the casing, each pixel once.
precision highp float;

uniform sampler2D uCover;
uniform sampler2D uRules;  // line-rules.ts: row 0 fill colours, row 1 casing colours

out vec4 oColour;

vec4 paint(float rule, float cover, int row) {
  vec4 c = texelFetch(uRules, ivec2(int(rule * 255.0 + 0.5), row), 0);
  float a = c.a * cover;
  return vec4(c.rgb * a, a);
}

void main() {
  vec4 c = texelFetch(uCover, ivec2(gl_FragCoord.xy), 0);
  if (c.g <= 0.0 && c.a <= 0.0) discard;
  vec4 casing = paint(c.r, c.g, 1);
  vec4 fill = paint(c.b, c.a, 0);
  oColour = fill + casing * (1.0 - fill.a);
}
