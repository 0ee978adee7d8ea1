// What the demo page puts on window, for page.evaluate callbacks in the tests.
import type { MapApi } from './map-page.js';

declare global {
  var map: MapApi;
  var lens: { enable(): unknown; disable(): unknown };
  var idw: { points: { x: number; y: number; z: number }[]; enable(): unknown };
}
