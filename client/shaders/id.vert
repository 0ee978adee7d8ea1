#version 300 es
// ID pass: the SSC's upward-facing triangles, top-down and orthographic. Positions are relative
// to the chunk's origin; uOffset is that origin less a whole-unit point near the view centre
// (an integer, exact), and uMatrix, the same for every chunk, takes that point to the view centre
// (composed in float64 on the CPU, so national grid coordinates keep their millimetres). A corner
// two chunks share is one value on the cube's grid, origin + position, so the correctly rounded
// sum is one float32 in both and the same matrix puts it on the same spot: the two triangles
// beside a shared edge meet exactly, and no pixel centre on that edge falls between them.
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
uniform vec2 uOffset;
uniform float uZRef;

// The same position in every program built from this shader (the FLAT one and the surface
// one): the rasterizer then covers the same pixels, whichever slices.
invariant gl_Position;

flat out uvec2 vIds;
flat out uint vClasses;
out float vZ;
out float vZRel;

void main() {
  gl_Position = uMatrix * vec4(aPosition.xy + uOffset, 0.0, 1.0);
  vIds = uvec2(aUpper, aLower);
  vClasses = (aUpperClass & 0xffffu) | ((aLowerClass & 0xffffu) << 16);
  vZ = aPosition.z;
  vZRel = aPosition.z - uZRef;
}
