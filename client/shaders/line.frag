#version 300 es
// Line pass: how much of this pixel the segment's band covers (a box filter of one pixel: full
// within half a pixel inside the edge, none half a pixel out), its casing's and its fill's at
// once, where the slicing surface's z at the pixel lies in the segment's z range (the rule of
// the CPU reference, draw-lines.ts, which keeps a pixel whose centre lies within half the
// width). The width is the rule's times the smaller of the line's and the rule's ramp shares at
// that z (format/line-ramp.ts, rampShare), so lines grow as they appear and shrink as they go;
// the segment's ends are where their glides have taken them at that z (format/line-glide.ts).
// FLAT (a flat slice): one z for every pixel, so line.vert works these out once per segment.
// Written into the line pass's coverage target with blend MAX, not painted: where segments
// overlap (a line's joins, crossings) a pixel keeps the largest coverage and is painted once,
// later (line-paint.glsl). The rule goes beside each coverage with 128 added where it covers
// at least half the pixel, so MAX keeps the latest rule among those covering half or more, and
// a rule's anti-aliased fringe does not take the pixel from one that covers it whole.
precision highp float;

uniform sampler2D uSurface;  // R32F: z of the slicing surface per pixel (not FLAT)

flat in vec2 vA;
flat in vec2 vB;
flat in vec2 vZ;
flat in vec4 vLineRamp;
flat in vec4 vRuleRamp;
flat in vec2 vAT;
flat in vec2 vBT;
flat in vec4 vGlide;
flat in vec2 vHalf;
flat in float vRule;
in vec2 vP;

out vec4 oCover;  // casing (rule, coverage), fill (rule, coverage), in 255ths

#include "line-z.glsl"

// (rule as kept, coverage) in 255ths, at distance d from the segment, of a band reaching half_ either side (0: none).
vec2 cover(float half_, float d) {
  float c = half_ > 0.0 ? floor(clamp(half_ + 0.5 - d, 0.0, 1.0) * 255.0 + 0.5) : 0.0;
  return c > 0.0 ? vec2(vRule + (c >= 128.0 ? 128.0 : 0.0), c) : vec2(0.0);
}

void main() {
#ifdef FLAT
  // line.vert placed the ends and narrowed the line at the slice's one z.
  vec2 a = vA, b = vB, bands = vHalf;
#else
  float z = texelFetch(uSurface, ivec2(gl_FragCoord.xy), 0).r;
  if (z < vZ.x || z >= vZ.y) discard;
  float s = min(share(vLineRamp, z), share(vRuleRamp, z));
  if (s <= 0.0) discard;
  vec2 a = mix(vA, vAT, glide(vGlide.x, vGlide.y, z));
  vec2 b = mix(vB, vBT, glide(vGlide.z, vGlide.w, z));
  vec2 bands = vHalf * s;
#endif
  vec2 ab = b - a;
  float l2 = dot(ab, ab);
  float t = l2 > 0.0 ? clamp(dot(vP - a, ab) / l2, 0.0, 1.0) : 0.0;
  float d = length(vP - (a + t * ab));
  vec2 casing = cover(bands.x, d), fill = cover(bands.y, d);
  if (casing.y <= 0.0 && fill.y <= 0.0) discard;
  oCover = vec4(casing, fill) / 255.0;
}
