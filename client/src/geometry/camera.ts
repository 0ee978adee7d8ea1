// Where the map looks, as the interaction code sees it: a ground centre and a scale
// denominator; and the two moves everything else is made of: keeping a ground point under a
// screen point while the scale changes, and interpolating between two cameras.
import { resolutionAtScale } from './view.js';

export interface Camera {
  x: number;
  y: number;
  /** Scale denominator. */
  scale: number;
}

/**
 * The camera at `scale` that shows ground point `ground` at `offset` CSS pixels from the view's
 * centre (x right, y down): zooming "about" a point.
 */
export function cameraAround(ground: readonly [number, number], offset: readonly [number, number], scale: number, pixelSizeMm: number): Camera {
  const res = resolutionAtScale(scale, pixelSizeMm);
  return { x: ground[0] - offset[0] * res, y: ground[1] + offset[1] * res, scale };
}

/** The ground point at `offset` CSS pixels from the centre of the camera's view. */
export function groundAt(c: Camera, offset: readonly [number, number], pixelSizeMm: number): [number, number] {
  const res = resolutionAtScale(c.scale, pixelSizeMm);
  return [c.x + offset[0] * res, c.y - offset[1] * res];
}

/** Geometric in scale, linear in position. */
export function lerpCamera(a: Camera, b: Camera, t: number): Camera {
  return { x: a.x + (b.x - a.x) * t, y: a.y + (b.y - a.y) * t, scale: a.scale * Math.pow(b.scale / a.scale, t) };
}

/**
 * From `a` to the scale of `b` while the ground point at `offset` stays where it is: the path of
 * a zoom about the cursor (b must keep that point at that offset too).
 */
export function zoomAboutPath(a: Camera, scale: number, offset: readonly [number, number], pixelSizeMm: number): (t: number) => Camera {
  const ground = groundAt(a, offset, pixelSizeMm);
  return (t) => cameraAround(ground, offset, a.scale * Math.pow(scale / a.scale, t), pixelSizeMm);
}
