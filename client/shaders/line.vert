#version 300 es
// Line pass: a quad around one segment of a cube line (four vertices per segment), its corners
// half the rule's width (its casing's, the whole band, when it has one) plus half a pixel (for
// anti-aliasing) out from the segment and past its ends, so consecutive segments join round. A
// segment whose z range (intersected with its rule's scale range) misses the slicing surface's
// z range over the view is moved out of clip space: at a flat slice that is every segment not on the map, so they cost no fragments. The quad is
// as wide as the line at full width, and long and wide enough to hold its ends wherever their
// glides take them; line.frag places the ends and narrows the line by the line's and the rule's
// ramps at the pixel's z (format/line-glide.ts, format/line-ramp.ts). FLAT (a flat slice): the
// ends and the width at the slice's one z are worked out here, and the quad holds just them.
precision highp float;
precision highp int;

layout(location = 0) in vec4 aEnds;  // a (xy) and b (zw), ground units from the chunk's origin
layout(location = 1) in vec2 aZ;     // drawn for aZ.x <= z < aZ.y
layout(location = 2) in uint aRule;  // column of uRules
layout(location = 3) in vec4 aLineRamp;  // the line's z0, z0Full, z1Full, z1
layout(location = 4) in vec4 aTargets;   // where a (xy) and b (zw) glide to (format/line-glide.ts)
layout(location = 5) in vec4 aGlide;     // a glides from z x to y, b from z to w

uniform sampler2D uRules;  // RGBA32F, one column per rule: fill; casing; (fill width, casing width mm); its ramp
uniform float uPxPerMm;    // device pixels per millimetre on screen
uniform vec2 uOffset;      // chunk origin - view centre, ground units
uniform float uRes;        // ground units per device pixel
uniform vec2 uHalfSize;    // half the target, device pixels
uniform vec2 uSliceRange;  // the slicing surface's z range over the view
uniform float uSliceZ;     // FLAT: the slice's one z

flat out vec2 vA;          // the segment's ends, device pixels from the view centre
flat out vec2 vB;
flat out vec2 vZ;          // the z range drawn
flat out vec4 vLineRamp;
flat out vec4 vRuleRamp;
flat out vec2 vAT;         // the glides' targets, device pixels from the view centre
flat out vec2 vBT;
flat out vec4 vGlide;
flat out vec2 vHalf;       // half the casing's and the fill's width, device pixels (0: not drawn)
flat out float vRule;
out vec2 vP;               // this point, device pixels from the view centre

#include "line-z.glsl"

void main() {
  int rule = int(aRule);
  vec4 sizes = texelFetch(uRules, ivec2(rule, 2), 0);
  float fillAlpha = texelFetch(uRules, ivec2(rule, 0), 0).a, casingAlpha = texelFetch(uRules, ivec2(rule, 1), 0).a;
  vRule = float(rule);
  vHalf = 0.5 * uPxPerMm * vec2(casingAlpha > 0.0 ? sizes.y : 0.0, fillAlpha > 0.0 ? sizes.x : 0.0);
  float band = max(vHalf.x, vHalf.y);
  vRuleRamp = texelFetch(uRules, ivec2(rule, 3), 0);
  vLineRamp = aLineRamp;
  vZ = vec2(max(aZ.x, vRuleRamp.x), min(aZ.y, vRuleRamp.w));
  if (band <= 0.0 || vZ.x >= vZ.y || vZ.y <= uSliceRange.x || vZ.x > uSliceRange.y) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  vA = (aEnds.xy + uOffset) / uRes;
  vB = (aEnds.zw + uOffset) / uRes;
  vAT = (aTargets.xy + uOffset) / uRes;
  vBT = (aTargets.zw + uOffset) / uRes;
  vGlide = aGlide;
#ifdef FLAT
  // One z everywhere: the segment's ends and width there, for every pixel (line.frag).
  float s = min(share(vLineRamp, uSliceZ), share(vRuleRamp, uSliceZ));
  if (uSliceZ < vZ.x || uSliceZ >= vZ.y || s <= 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  vA = mix(vA, vAT, glide(aGlide.x, aGlide.y, uSliceZ));
  vB = mix(vB, vBT, glide(aGlide.z, aGlide.w, uSliceZ));
  vAT = vA;
  vBT = vB;
  vHalf *= s;
  band = max(vHalf.x, vHalf.y);
#endif
  vec2 ab = vB - vA;
  float len = length(ab);
  vec2 t = len > 0.0 ? ab / len : vec2(1.0, 0.0);
  vec2 n = vec2(-t.y, t.x);
  // Along t from a and across n: the box of both ends and both targets.
  vec2 at = vec2(dot(vAT - vA, t), dot(vAT - vA, n)), bt = vec2(dot(vBT - vA, t), dot(vBT - vA, n));
  // line.frag's box filter covers nothing from half a pixel beyond the edge: the quad stops there.
  float reach = band + 0.5;
  float lo = min(0.0, min(at.x, bt.x)) - reach, hi = max(len, max(at.x, bt.x)) + reach;
  float left = max(0.0, max(at.y, bt.y)) + reach, right = min(0.0, min(at.y, bt.y)) - reach;
  // Corners in this order: a-left, a-right, b-left, b-right (gpu-line-chunk.ts).
  int v = gl_VertexID % 4;
  vP = vA + t * (v < 2 ? lo : hi) + n * (v % 2 == 0 ? left : right);
  gl_Position = vec4(vP / uHalfSize, 0.0, 1.0);
}
