#version 300 es
// ID pass: keep, per pixel, the nearest surface at or below the slicing surface. Fragments
// above it are discarded; the depth is the distance below it (written here, since the surface
// varies per pixel), so a float depth buffer is most precise right under the slice.
precision highp float;
precision highp int;
precision highp usampler2D;

uniform sampler2D uSurface;  // R32F: z of the slicing surface per pixel
uniform float uDepthScale;   // 1 / (the largest distance below the slice that matters)

flat in uvec2 vIds;
flat in uint vClasses;
in float vZ;

layout(location = 0) out uvec2 oIds;  // upper face, lower face
layout(location = 1) out uvec2 oAux;  // classes (upper | lower << 16), z of the surface (float bits)

void main() {
  float zSlice = texelFetch(uSurface, ivec2(gl_FragCoord.xy), 0).r;
  float d = zSlice - vZ;
  if (d < 0.0) discard;
  gl_FragDepth = clamp(d * uDepthScale, 0.0, 1.0);
  oIds = vIds;
  oAux = uvec2(vClasses, floatBitsToUint(vZ));
}
