#version 300 es
// Present pass: the accumulated (supersampled) colour on the canvas; LINES: with the cube's lines
// painted over it, sharp (they are not accumulated).
precision highp float;
uniform sampler2D uColour;
out vec4 oColour;
#ifdef LINES
#include "line-paint.glsl"
#endif
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 colour = texelFetch(uColour, p, 0).rgb;
#ifdef LINES
  colour = withLines(colour, p);
#endif
  oColour = vec4(colour, 1.0);
}
