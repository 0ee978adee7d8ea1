#version 300 es
// Colour pass: from the ID buffer to colours. Per pixel the upper face's class colour (and its
// pattern within the pattern's z range); near-intersection blending toward the face below when
// the surface is less than uBlendDistance under the slice (d = slice z - surface z at this
// pixel: on a tilted surface of the smooth cube, the z of its plane here as the ID pass
// interpolated it from the vertices, so the blend fades in across the surface toward where the
// slice meets it; the face below is the triangle's lower face, the one the surface replaces,
// e.g. a merge's loser); face boundaries where the face id
// changes between neighbouring pixels; last the paint of faces whose feature state has hover or
// highlight, on their own pixels only (a fill, and an outline just inside the face's edge).
// Blending, boundaries and states are compiled in only when a frame draws them (BLENDING,
// BOUNDARIES, STATES; colour-pass.ts): a software GPU runs an untaken branch's texture reads
// for every pixel, and these cost more than half of the frame. So are the patterns (PATTERNS:
// some class's pattern shows in the slice's z range). The ID target is read only for
// boundaries and states: face 0 (nothing, or an area that left the map) has class 0xffff,
// which is drawn as the background. FLAT: the slice's z is uSliceZ.
// LINES: the cube's lines painted over the map (a frame drawn straight onto the canvas).
// Tried: the ID pass looking each class's fill up once a vertex and writing it beside the
// classes (an RGBA32UI target), so that this pass reads no style texel. On bgt_otterlo_1800m at
// 1280x720 (bench:passes, two runs of 3 turns against the code before, interleaved) this pass
// took 2 to 5 ms less at every scale, but the ID pass, writing 8 more bytes a fragment over its
// overdraw, 3 to 6 ms more at 1:4,304 and 1:8,929: no gain. Not kept.
precision highp float;
precision highp int;
precision highp usampler2D;

uniform usampler2D uIds;      // RG32UI: upper, lower face
uniform usampler2D uAux;      // RG32UI: classes, z of the surface (float bits)
uniform sampler2D uSurface;   // R32F: z of the slicing surface
uniform float uSliceZ;        // its one z (FLAT)
uniform sampler2D uStyle;     // RGBA32F, one column per class: fill + pattern kind; pattern colour; pattern z range
uniform int uClassCount;
uniform vec4 uBackground;
uniform float uBlendDistance; // c in steps (BLENDING)
uniform int uBoundaryBefore;  // boundary band: neighbours from -before to +after (device pixels)
uniform int uBoundaryAfter;   // (BOUNDARIES)
uniform vec4 uBoundaryColour; // rgb, alpha = opacity
uniform float uPatternInvCell; // 1 / the pattern's period in device pixels
uniform float uPatternLine;   // pattern line width / dot radius, device pixels
uniform vec2 uPatternShift;   // anchors patterns to the ground, device pixels
uniform usampler2D uFaceState; // R8UI, one texel per face id (rows of 2^uFaceStateShift): bit i, state i
uniform uint uFaceStateShift;
uniform uint uFaceCount;       // faces in uFaceState
// Per drawn state (0 hover, 1 highlight, painted in that order):
uniform vec4 uStateFill[2];    // rgb, alpha = opacity
uniform vec4 uStateOutline[2]; // rgb, alpha = opacity
uniform int uStateWidth[2];    // outline inside the face, device pixels; 0: none

out vec4 oColour;

#ifdef LINES
#include "line-paint.glsl"
#endif

// Shifts, not division (face-state-texture.ts has a power of two texels a row): on a software
// GPU integer division costs as much as a texture read.
uint stateBits(uint face) {
  if (face == 0u || face >= uFaceCount) return 0u;
  return texelFetch(uFaceState, ivec2(int(face & ((1u << uFaceStateShift) - 1u)), int(face >> uFaceStateShift)), 0).r;
}

// Whether a pixel within `width` of p (on screen) shows another face than `face`.
bool nearOtherFace(ivec2 p, ivec2 size, uint face, int width) {
  for (int dy = -width; dy <= width; dy++) {
    for (int dx = -width; dx <= width; dx++) {
      ivec2 q = p + ivec2(dx, dy);
      if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
      if (texelFetch(uIds, q, 0).x != face) return true;
    }
  }
  return false;
}

// Every pattern's mask at this pixel, worked out once for both classes a pixel may show
// (hatch, dots, cross): a software GPU runs a branch's work whether taken or not, so a class
// without a pattern costs this anyway. In cells (fract, not mod, whose division is dear there).
vec3 patternMasks() {
  vec2 q = (gl_FragCoord.xy + uPatternShift) * uPatternInvCell;
  float w = uPatternLine * uPatternInvCell;
  float hatch = fract(q.x + q.y) < w ? 1.0 : 0.0;
  float other = fract(q.x - q.y) < w ? 1.0 : 0.0;
  vec2 m = fract(q) - 0.5;
  return vec3(hatch, dot(m, m) < w * w ? 1.0 : 0.0, max(hatch, other));
}

vec3 classColour(uint cls, float zSlice, vec3 masks) {
  int i = int(cls);
  if (i >= uClassCount) return uBackground.rgb;
  // The pattern's kind beside the fill: a class without a pattern costs one read.
  vec4 fill = texelFetch(uStyle, ivec2(i, 0), 0);
#ifdef PATTERNS
  int kind = int(fill.a + 0.5);
  if (kind != 0) {
    vec3 pat = texelFetch(uStyle, ivec2(i, 1), 0).rgb;
    vec2 range = texelFetch(uStyle, ivec2(i, 2), 0).xy;
    if (zSlice >= range.x && zSlice <= range.y) return mix(fill.rgb, pat, masks[kind - 1]);
  }
#endif
  return fill.rgb;
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(uAux, 0);
  uvec2 aux = texelFetch(uAux, p, 0).xy;
  uint upperClass = aux.x & 0xffffu;
  uint lowerClass = aux.x >> 16;
  vec3 colour;
  if (upperClass == 0xffffu) {
    colour = uBackground.rgb;
  } else {
#ifdef FLAT
    float zSlice = uSliceZ;
#else
    float zSlice = texelFetch(uSurface, p, 0).r;
#endif
#ifdef PATTERNS
    vec3 masks = patternMasks();
#else
    vec3 masks = vec3(0.0);
#endif
    colour = classColour(upperClass, zSlice, masks);
#ifdef BLENDING
    if (lowerClass != 0xffffu) {
      float d = zSlice - uintBitsToFloat(aux.y);
      if (d < uBlendDistance) colour = mix(classColour(lowerClass, zSlice, masks), colour, d / uBlendDistance);
    }
#endif
  }
#if defined(BOUNDARIES) || defined(STATES)
  uint face = texelFetch(uIds, p, 0).x;
#endif
#ifdef BOUNDARIES
  {
    bool edge = false;
    for (int k = -uBoundaryBefore; k <= uBoundaryAfter; k++) {
      if (k == 0) continue;
      ivec2 a = clamp(p + ivec2(k, 0), ivec2(0), size - 1);
      ivec2 b = clamp(p + ivec2(0, k), ivec2(0), size - 1);
      if (texelFetch(uIds, a, 0).x != face || texelFetch(uIds, b, 0).x != face) edge = true;
    }
    if (edge) colour = mix(colour, uBoundaryColour.rgb, uBoundaryColour.a);
  }
#endif
#ifdef STATES
  uint bits = stateBits(face);
  // Guarded: SwiftShader runs this loop for every pixel otherwise, which doubled the pass.
  if (bits != 0u) for (int s = 0; s < 2; s++) {
    if ((bits & (1u << uint(s))) == 0u) continue;
    colour = mix(colour, uStateFill[s].rgb, uStateFill[s].a);
    // The outline: pixels of the face within its width of another face (or of nothing).
    if (uStateWidth[s] > 0 && nearOtherFace(p, size, face, uStateWidth[s])) colour = mix(colour, uStateOutline[s].rgb, uStateOutline[s].a);
  }
#endif
#ifdef LINES
  colour = withLines(colour, p);
#endif
  oColour = vec4(colour, 1.0);
}
