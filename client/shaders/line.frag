#version 300 es
// Line pass: how much of this pixel the segment's band covers (a box filter of one pixel: full
// within half a pixel inside the edge, none half a pixel out), where the slicing surface's z at
// the pixel lies in the segment's z range (the rule of the CPU reference, draw-lines.ts, which
// keeps a pixel whose centre lies within half the width). The width is the rule's times the
// smaller of the line's and the rule's ramp shares at that z (format/line-ramp.ts, rampShare),
// so lines grow as they appear and shrink as they go; the segment's ends are where their
// glides have taken them at that z (format/line-glide.ts).
// Written as (rule, coverage) into the line pass's coverage target, not blended: the depth
// test keeps the largest coverage per pixel (then the later rule), so where segments overlap
// (a line's joins, crossings) a pixel is painted once, by line-composite.frag.
precision highp float;

uniform sampler2D uSurface;  // R32F: z of the slicing surface per pixel

flat in vec2 vA;
flat in vec2 vB;
flat in vec2 vZ;
flat in vec4 vLineRamp;
flat in vec4 vRuleRamp;
flat in vec2 vAT;
flat in vec2 vBT;
flat in vec4 vGlide;
flat in float vHalf;
flat in float vRule;
in vec2 vP;

out vec4 oCover;  // (rule, coverage) twice: the pass's colour mask keeps casing (rg) or fill (ba)

// z0, z0Full, z1Full, z1: 0 at the ends, 1 between the full points, linear in z between.
float share(vec4 r, float z) {
  float grow = r.y > r.x ? (z - r.x) / (r.y - r.x) : 1.0;
  float shrink = r.w > r.z ? (r.w - z) / (r.w - r.z) : 1.0;
  return clamp(min(grow, shrink), 0.0, 1.0);
}

// How far along its glide an end is at z, gliding over [from, to]: 0 before it, 1 at its end and after (glideShare).
float glide(float from, float to, float z) {
  if (!(to > from)) return z >= to ? 1.0 : 0.0;
  return clamp((z - from) / (to - from), 0.0, 1.0);
}

void main() {
  float z = texelFetch(uSurface, ivec2(gl_FragCoord.xy), 0).r;
  if (z < vZ.x || z >= vZ.y) discard;
  float s = min(share(vLineRamp, z), share(vRuleRamp, z));
  if (s <= 0.0) discard;
  vec2 a = mix(vA, vAT, glide(vGlide.x, vGlide.y, z));
  vec2 b = mix(vB, vBT, glide(vGlide.z, vGlide.w, z));
  vec2 ab = b - a;
  float l2 = dot(ab, ab);
  float t = l2 > 0.0 ? clamp(dot(vP - a, ab) / l2, 0.0, 1.0) : 0.0;
  float d = length(vP - (a + t * ab));
  // In the target's 8 bits, so that depth and colour agree on which fragment won.
  float cover = floor(clamp(vHalf * s + 0.5 - d, 0.0, 1.0) * 255.0 + 0.5);
  if (cover <= 0.0) discard;
  oCover = vec4(vRule, cover, vRule, cover) / 255.0;
  gl_FragDepth = ((255.0 - cover) * 256.0 + (255.0 - vRule) + 0.5) / 65536.0;
}
