#version 300 es
// Shows the accumulated (supersampled) colour on the canvas.
precision highp float;
uniform sampler2D uColour;
out vec4 oColour;
void main() {
  oColour = vec4(texelFetch(uColour, ivec2(gl_FragCoord.xy), 0).rgb, 1.0);
}
