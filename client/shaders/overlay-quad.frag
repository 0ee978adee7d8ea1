#version 300 es
// Overlay pass: how much of this pixel a segment's band covers, per channel of the layer's
// coverage target (r: polygon edge, g: line, b: circle, a: circle with its stroke). uRadii is
// each channel's half width in device pixels (negative: not this geometry's channel). Box
// filter of one pixel: full coverage within half a pixel inside the edge, none half a pixel
// out. The target keeps the largest coverage of each pixel (blend MAX), so overlapping
// segments (at every join) do not add up.
precision highp float;

uniform vec4 uRadii;

flat in vec2 vA;
flat in vec2 vB;
in vec2 vP;

out vec4 oCoverage;

void main() {
  vec2 ab = vB - vA;
  float l2 = dot(ab, ab);
  float t = l2 > 0.0 ? clamp(dot(vP - vA, ab) / l2, 0.0, 1.0) : 0.0;
  float d = length(vP - (vA + t * ab));
  oCoverage = clamp(uRadii + 0.5 - d, 0.0, 1.0);
}
