// A MapView in Node for the camera's unit tests: a small cube's metadata (0.25 mm pixels, base
// scale 1:1000) and a view of 400 x 200 CSS px recording its movement events and changes.
import type { CubeMeta } from '../format/cube-index.js';
import { MapView, type MoveEventType } from '../client/src/camera/map-view.js';

export const testMeta = {
  name: 'test', crs: '', extent: [0, 0, 1000, 500], zMax: 100, steps: 100, phases: 8,
  baseScale: 1000, baseFaces: 10000, pixelSizeMm: 0.25, scaleTable: [[0, 10000], [100, 1]],
  style: { name: 'test', background: '#ffffff', classes: [] }, attribution: '',
  faces: { count: 0, pages: [] }, attributes: { count: 0, pages: [] },
} as unknown as CubeMeta;

export function makeView(): { view: MapView; events: MoveEventType[]; changes: boolean[] } {
  const events: MoveEventType[] = [];
  const changes: boolean[] = [];
  // 400 x 200 CSS px: at 1:4000 (0.25 mm pixels) the view is 400 x 200 ground units.
  const view = new MapView({ requestFrame: () => undefined, reduceMotion: () => true, size: () => [400, 200], emit: (type) => events.push(type) });
  view.onChange((sliceMoved) => changes.push(sliceMoved));
  return { view, events, changes };
}
