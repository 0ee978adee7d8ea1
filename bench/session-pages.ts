// The two pages of bench:session, each with one full-window map and the same small API for
// the driver (window.bench): `first` resolves at the first complete map, `frame(view)` sets
// the view and resolves when the map is complete again. Times are performance.now() (from the
// navigation's start) and `at` the wall clock, to line up with the server's response log.
// The vario map comes from the public ES build (lib/), MapLibre from its ESM build (maplibre/).
import { writeFile } from 'node:fs/promises';
import path from 'node:path';
import type { Style } from '../preprocess/style.js';
import type { LngLatView, ProjectedView } from './scale-zoom.js';
import { TILE_LAYER, type Tiles } from './tippecanoe-tiles.js';

/** What MapLibre's style takes from the dataset's: the class property, the background and the class colours. */
export type TileStyle = Pick<Style, 'background' | 'classes'> & { classProperty: string };

/** What a page's frame(view) gives back. */
export interface FrameResult {
  /** setView to the first complete image on screen, ms. */
  ms: number;
  at: number;
  /** Triangles drawn in the complete frame, when the map says. */
  triangles: number | null;
}

export interface FirstMap {
  /** ms from the navigation's start. */
  ms: number;
  at: number;
}

/** A page script's expression for its start view: the URL's (startQuery), else `fallback`. */
const startOr = (fallback: ProjectedView | LngLatView): string => `JSON.parse(new URLSearchParams(location.search).get('start') ?? 'null') ?? ${JSON.stringify(fallback)}`;

/** The query that opens a session page at `view` instead of its own start. */
export function startQuery(view: ProjectedView | LngLatView): string {
  return `?start=${encodeURIComponent(JSON.stringify(view))}`;
}

const head = (title: string, css: string): string => `<!doctype html>
<html lang="en">
<head>
  <meta charset="utf-8">
  <title>${title}</title>
  <link rel="icon" href="data:,">
  <link rel="stylesheet" href="${css}">
  <style>html, body { margin: 0; height: 100%; } #map { position: absolute; inset: 0; }</style>
</head>
<body>
<div id="map"></div>
<script type="module">
const epoch = () => performance.timeOrigin + performance.now();
`;

/**
 * The vario map, opening at `start` (or the URL's, startQuery). One supersampling frame: 'idle'
 * then comes with the first complete frame, as MapLibre's does (it does not accumulate). No
 * scale limits, so that both maps go wherever the session goes.
 */
function varioPage(start: ProjectedView): string {
  return `${head('vario map', 'lib/vario-map.css')}import { VarioMap } from './lib/vario-map.js';
const start = ${startOr(start)};
const map = new VarioMap({ container: 'map', source: 'cube/', centerProjected: start.center, scaleDenominator: start.scale, supersampling: 1, minScale: 1e-9, maxScale: Infinity });
let triangles = null;
map.on('render', (e) => { triangles = e.triangles; });
window.bench = {
  // The first map on screen: its first 'complete' ('load' also waits for the CRS, which this page does not use).
  first: Promise.race([map.once('complete'), map.whenIdle()]).then(() => ({ ms: performance.now(), at: epoch() })),
  async frame(v) {
    const t0 = performance.now();
    map.jumpTo({ centerProjected: v.center, scaleDenominator: v.scale });
    // Complete: the image on screen shows the whole view. The session goes on from there, as a
    // user's zoom does; waiting for 'idle' would add a redraw per view (blending is turned off,
    // and the view drawn once more, 300 ms after the slice stops). A view with failed chunks
    // never completes, and 'idle' ends it; so does an unchanged view, idle already.
    await Promise.race([map.once('complete'), map.whenIdle()]);
    return { ms: performance.now() - t0, at: epoch(), triangles };
  },
};
</script>
</body>
</html>
`;
}

/** MapLibre's style: the background and the tile layer's polygons filled by their class, in the cube style's colours. */
function mapLibreStyle(style: TileStyle, tiles: Tiles): unknown {
  const colours = style.classes.flatMap((c) => [c.key, c.color]);
  return {
    version: 8,
    sources: { areas: { type: 'vector', tiles: ['TILES_URL'], minzoom: tiles.minZoom, maxzoom: tiles.maxZoom, bounds: tiles.bounds } },
    layers: [
      { id: 'background', type: 'background', paint: { 'background-color': style.background } },
      // Class values may be numbers in the data (nlcd's code) and are keys in the style.
      { id: 'areas', type: 'fill', source: 'areas', 'source-layer': TILE_LAYER, paint: { 'fill-color': ['match', ['to-string', ['get', style.classProperty]], ...colours, style.background] } },
    ],
  };
}

/**
 * MapLibre, opening at `start` (or the URL's, startQuery), with its triangles counted at the
 * WebGL calls: every drawElements/drawArrays of TRIANGLES between two 'render' events is one
 * frame's.
 */
function mapLibrePage(start: LngLatView, style: unknown): string {
  return `${head('MapLibre', 'maplibre/maplibre-gl.css')}let drawn = 0;
for (const C of [WebGLRenderingContext, WebGL2RenderingContext]) {
  const p = C.prototype, elements = p.drawElements, arrays = p.drawArrays;
  p.drawElements = function (mode, count, type, offset) { if (mode === this.TRIANGLES) drawn += count / 3; return elements.call(this, mode, count, type, offset); };
  p.drawArrays = function (mode, first, count) { if (mode === this.TRIANGLES) drawn += count / 3; return arrays.call(this, mode, first, count); };
}
const { Map } = await import('./maplibre/maplibre-gl.mjs');
// Tile URLs must be absolute; a URL object would escape the braces.
const style = JSON.parse(${JSON.stringify(JSON.stringify(style))}.replace('TILES_URL', location.origin + '/tiles/{z}/{x}/{y}.pbf'));
const start = ${startOr(start)};
const map = new Map({ container: 'map', style, center: start.center, zoom: start.zoom, fadeDuration: 0, minZoom: 0, maxZoom: 24 });
let mark = 0, triangles = null;
map.on('render', () => { triangles = drawn - mark; mark = drawn; });
map.on('error', (e) => console.error('maplibre: ' + (e.error?.message ?? e)));
window.bench = {
  first: new Promise((resolve) => map.once('idle', () => resolve({ ms: performance.now(), at: epoch() }))),
  async frame(v) {
    const t0 = performance.now();
    const idle = new Promise((resolve) => map.once('idle', resolve));
    map.jumpTo({ center: v.center, zoom: v.zoom });
    await idle;
    return { ms: performance.now() - t0, at: epoch(), triangles };
  },
};
</script>
</body>
</html>
`;
}

/** Writes vario.html and maplibre.html into the site's folder. */
export async function writeSessionPages(dir: string, start: ProjectedView, startLngLat: LngLatView, style: TileStyle, tiles: Tiles): Promise<void> {
  await writeFile(path.join(dir, 'vario.html'), varioPage(start));
  await writeFile(path.join(dir, 'maplibre.html'), mapLibrePage(startLngLat, mapLibreStyle(style, tiles)));
}
