#version 300 es
// Line pass: how much of this pixel the segment's band covers (a box filter of one pixel: full
// within half a pixel inside the edge, none half a pixel out), where the slicing surface's z at
// the pixel lies in the segment's z range (the rule of the CPU reference, draw-lines.ts, which
// keeps a pixel whose centre lies within half the width). Premultiplied over the map.
precision highp float;

uniform sampler2D uSurface;  // R32F: z of the slicing surface per pixel

flat in vec2 vA;
flat in vec2 vB;
flat in vec2 vZ;
flat in float vHalf;
flat in vec4 vColour;
in vec2 vP;

out vec4 oColour;

void main() {
  float z = texelFetch(uSurface, ivec2(gl_FragCoord.xy), 0).r;
  if (z < vZ.x || z >= vZ.y) discard;
  vec2 ab = vB - vA;
  float l2 = dot(ab, ab);
  float t = l2 > 0.0 ? clamp(dot(vP - vA, ab) / l2, 0.0, 1.0) : 0.0;
  float d = length(vP - (vA + t * ab));
  float cover = clamp(vHalf + 0.5 - d, 0.0, 1.0) * vColour.a;
  if (cover <= 0.0) discard;
  oColour = vec4(vColour.rgb * cover, cover);
}
