#version 300 es
// Overlay pass: a GeoJSON layer's coverage (overlay-quad.frag's channels) painted over the
// map, premultiplied (blend ONE, ONE_MINUS_SRC_ALPHA): the fill under the lines under the
// circles, each with its colour and opacity; a circle's stroke is the ring between its radius
// and its radius plus the stroke width.
precision highp float;

uniform sampler2D uCoverage;
uniform vec4 uFill;          // rgb, alpha = opacity
uniform vec4 uLine;
uniform vec4 uCircle;
uniform vec4 uCircleStroke;

out vec4 oColour;

vec4 over(vec4 top, vec4 under) {
  return top + under * (1.0 - top.a);
}

void main() {
  vec4 c = texelFetch(uCoverage, ivec2(gl_FragCoord.xy), 0);
  float fill = c.r * uFill.a;
  float line = c.g * uLine.a;
  float disc = c.b * uCircle.a;
  float ring = max(c.a - c.b, 0.0) * uCircleStroke.a;
  vec4 colour = vec4(uFill.rgb * fill, fill);
  colour = over(vec4(uLine.rgb * line, line), colour);
  colour = over(vec4(uCircle.rgb * disc + uCircleStroke.rgb * ring, disc + ring), colour);
  oColour = colour;
}
