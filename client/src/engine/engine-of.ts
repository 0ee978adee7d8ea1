// The one way in to a map's engine from outside the map (the test page, the e2e tests and the
// render benchmark read chunk statuses, frame stats and the ID buffer). Not exported from the
// library: embedders use VarioMap's methods.
import type { MapEngine } from './map-engine.js';

const engines = new WeakMap<object, MapEngine>();

/** Called by the map that owns `engine`. */
export function bindEngine(map: object, engine: MapEngine): void {
  engines.set(map, engine);
}

export function engineOf(map: object): MapEngine {
  const e = engines.get(map);
  if (!e) throw new Error('engineOf: not a VarioMap');
  return e;
}
