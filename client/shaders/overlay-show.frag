#version 300 es
// Overlay pass: every overlay layer, painted (premultiplied) into the overlays target, shown
// over the map on the canvas (blend ONE, ONE_MINUS_SRC_ALPHA).
precision highp float;
uniform sampler2D uOverlays;
out vec4 oColour;
void main() {
  oColour = texelFetch(uOverlays, ivec2(gl_FragCoord.xy), 0);
}
