#version 300 es
// Overlay pass: a GeoJSON layer's polygon triangles. Positions are relative to the layer's
// origin; uOffset is the origin's offset from the view centre, worked out in float64 on the CPU,
// so the view (pan, zoom) is applied here and the triangles are uploaded once.
precision highp float;

layout(location = 0) in vec2 aPosition;

uniform vec2 uOffset;    // layer origin - view centre, ground units
uniform float uRes;      // ground units per device pixel
uniform vec2 uHalfSize;  // half the target, device pixels

void main() {
  gl_Position = vec4((aPosition + uOffset) / uRes / uHalfSize, 0.0, 1.0);
}
