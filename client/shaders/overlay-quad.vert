#version 300 es
// Overlay pass: a quad around one segment (a point: a segment of length 0) of a GeoJSON
// layer, its corners uReach device pixels out from the segment's ends (overlay-mesh.ts lays
// the quads out). The segment's ends go to the fragment shader, which keeps what lies within
// the half width: a capsule. Positions are relative to the layer's origin, uOffset its offset
// from the view centre (float64 on the CPU), so a pan or zoom changes uniforms only.
precision highp float;

layout(location = 0) in vec4 aSegment;  // ends a (xy) and b (zw), ground units from the origin
layout(location = 1) in vec3 aCorner;   // direction of the corner (xy, unit along + unit across), 0 at a / 1 at b

uniform vec2 uOffset;    // layer origin - view centre, ground units
uniform float uRes;      // ground units per device pixel
uniform vec2 uHalfSize;  // half the target, device pixels
uniform float uReach;    // device pixels from the segment to the quad's edge

flat out vec2 vA;        // the segment's ends, device pixels from the view centre
flat out vec2 vB;
out vec2 vP;             // this point, the same

void main() {
  vA = (aSegment.xy + uOffset) / uRes;
  vB = (aSegment.zw + uOffset) / uRes;
  vP = mix(vA, vB, aCorner.z) + aCorner.xy * uReach;
  gl_Position = vec4(vP / uHalfSize, 0.0, 1.0);
}
