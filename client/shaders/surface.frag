#version 300 es
// Surface pass: the slicing surface's z (steps) at the ground point under each pixel, with the
// definitions of client/src/shared/surfaces.ts. Positions are offsets from the view centre (small numbers);
// everything that involves absolute coordinates was worked out on the CPU in float64
// (client/src/shared/surface-params.ts), so float32 keeps the precision.
precision highp float;
precision highp int;

#define MAX_POINTS 64

uniform int uKind;        // 0 flat, 1 tilted, 2 sine, 3 lens, 4 idw
uniform float uBase;
uniform float uZMax;
uniform vec2 uHalfSize;   // half the target size, device pixels
uniform float uRes;       // ground units per device pixel
uniform vec4 uP;          // per kind, see surface-params.ts
uniform int uCount;
uniform float uPower;
uniform vec3 uPoints[MAX_POINTS]; // idw: x, y relative to the view centre; z

out float oZ;

float rawZ(vec2 d) {
  if (uKind == 1) return uP.x + uP.y * d.x + uP.z * d.y;
  if (uKind == 2) return uBase + uP.w * sin(uP.x + uP.y * d.x + uP.z * d.y);
  if (uKind == 3) {
    vec2 q = d + uP.xy;
    float d2 = dot(q, q);
    float r2 = uP.z * uP.z;
    if (d2 >= r2) return uBase;
    float t = 1.0 - d2 / r2;
    return uBase - uP.w * t * t;
  }
  if (uKind == 4) {
    if (uCount == 0) return uBase;
    float sw = 0.0, sz = 0.0;
    for (int i = 0; i < MAX_POINTS; i++) {
      if (i >= uCount) break;
      vec2 q = d - uPoints[i].xy;
      float d2 = dot(q, q);
      if (d2 == 0.0) return uPoints[i].z;
      float w = 1.0 / pow(d2, uPower * 0.5);
      sw += w;
      sz += w * uPoints[i].z;
    }
    return sz / sw;
  }
  return uBase;
}

void main() {
  vec2 d = (gl_FragCoord.xy - uHalfSize) * uRes;
  oZ = clamp(rawZ(d), 0.0, uZMax);
}
