#version 300 es
// ID pass: keep, per pixel, the nearest surface at or below the slicing surface. Fragments
// above it are discarded; the depth is the distance below it (written here, since the surface
// varies per pixel), so a float depth buffer is most precise right under the slice.
//
// The surface's z at the pixel is the plane through the triangle's three vertex z's (a tilted
// surface of the smooth cube; all three equal on a horizontal one), interpolated by the GPU at
// the pixel centre: the same plane the CPU slicer evaluates there. A GPU interpolates with
// barycentric weights that sum to 1 only up to float32 rounding, amplified by the triangle's
// elongation, so the result errs by about |value| * 1e-7 * (length / width): on a needle
// triangle at z 470 that was 0.01 step, enough to move where a nearly level surface crosses
// the slice by pixels. Interpolating z - uZRef instead (uZRef: the slicing surface's base z)
// makes the error vanish where it matters, at a surface level with a flat slice; vZ itself is
// kept for surfaces nearer 0 than uZRef (the floor, z = 0, stays exact when the slice is
// clamped to 0). Each pixel takes the form with the smaller magnitude.
// FLAT (a flat slice): the slice's z is uZRef itself, not read per fragment from the surface target.
// Tried for FLAT: the depth from id.vert, 2 (uZRef - z) uDepthScale - 1, so the near plane clips
// what lies above the slice and the GPU tests depth before shading (no discard, no
// gl_FragDepth). The ID pass took 15% less time on bgt_otterlo_1800m at middle scales, but
// near -1 that depth resolves only some 3e-5 step at z 474, and more pixels of
// bgt_otterlo_400m differed from the CPU slicer (z 300: 240 -> 270 of 307,200). Not kept.
precision highp float;
precision highp int;
precision highp usampler2D;

uniform sampler2D uSurface;  // R32F: z of the slicing surface per pixel
uniform float uDepthScale;   // 1 / (the largest distance below the slice that matters)
uniform float uZRef;         // the slicing surface's base z (id.vert)

flat in uvec2 vIds;
flat in uint vClasses;
in float vZ;
in float vZRel;

layout(location = 0) out uvec2 oIds;  // upper face, lower face
layout(location = 1) out uvec2 oAux;  // classes (upper | lower << 16), z of the surface (float bits)

void main() {
#ifdef FLAT
  float zSlice = uZRef;
#else
  float zSlice = texelFetch(uSurface, ivec2(gl_FragCoord.xy), 0).r;
#endif
  bool rel = abs(vZRel) < abs(vZ);
  // zSlice - uZRef is exact for a flat slice (0) and wherever the two are within a factor 2.
  float d = rel ? (zSlice - uZRef) - vZRel : zSlice - vZ;
  if (d < 0.0) discard;
  gl_FragDepth = clamp(d * uDepthScale, 0.0, 1.0);
  oIds = vIds;
  // The z read back and blended with: the slice less d, so that the colour pass's
  // zSlice - z is this d up to one rounding.
  oAux = uvec2(vClasses, floatBitsToUint(rel ? vZRel + uZRef : vZ));
}
