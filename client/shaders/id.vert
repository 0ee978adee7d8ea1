#version 300 es
// ID pass: the SSC's upward-facing triangles, top-down and orthographic. Positions are relative
// to the chunk's origin; uMatrix carries the chunk's offset from the view centre, composed in
// float64 on the CPU, so national grid coordinates keep their millimetres.
// z is per vertex (the smooth cube's tilted surfaces) and reaches the fragment twice: as it is,
// and less uZRef (the slicing surface's base z), because a GPU's interpolation errs in proportion
// to the size of the values interpolated (see id.frag).
precision highp float;
precision highp int;

layout(location = 0) in vec3 aPosition;
layout(location = 1) in uint aUpper;
layout(location = 2) in uint aLower;
layout(location = 3) in uint aUpperClass;
layout(location = 4) in uint aLowerClass;

uniform mat4 uMatrix;
uniform float uZRef;

flat out uvec2 vIds;
flat out uint vClasses;
out float vZ;
out float vZRel;

void main() {
  gl_Position = uMatrix * vec4(aPosition.xy, 0.0, 1.0);
  vIds = uvec2(aUpper, aLower);
  vClasses = (aUpperClass & 0xffffu) | ((aLowerClass & 0xffffu) << 16);
  vZ = aPosition.z;
  vZRel = aPosition.z - uZRef;
}
