// What the test page (index.html) puts on window, for page.evaluate callbacks in the tests.
import type { EngineApi, MapApi } from './map-page.js';

declare global {
  var map: MapApi;
  var engine: EngineApi;
  var lens: { enable(): unknown; disable(): unknown };
  var idw: { points: { x: number; y: number; z: number }[]; enable(): unknown };
}
