#version 300 es
// Overlay pass: a polygon's interior covers its pixels fully (the fill channel, red); its
// anti-aliased edge comes from the rings' quads (overlay-quad.frag).
precision highp float;
out vec4 oCoverage;
void main() {
  oCoverage = vec4(1.0, 0.0, 0.0, 0.0);
}
