// The test page (index.html): a VarioMap over the cube named by the URL (?source=dir/), with
// optional view, surface and tools from URL parameters:
//   center=x,y  scale=n  bbox=x0,y0,x1,y1 (the cube's projected CRS)  z=steps  surface=kind:key=value,...  tool=lens|idw
//   supersampling=n  boundaries=1  blending=off|moving|always  budget=bytes  ratio=dpr
//   retries=n  backoff=ms  concurrency=n (chunk loading)  legend=1 (the LegendControl)
// Any scale may be shown (no limits) and no control covers the canvas. `window.map` (and
// `window.engine`, the map's engine for chunk statuses, frame stats and the ID buffer;
// `window.lens`, `window.idw`) are there for the console and the tests.
import { engineOf } from './engine/engine-of.js';
import { IdwControl } from './ui/idw-control.js';
import { LegendControl } from './ui/legend-control.js';
import { LensControl } from './ui/lens-control.js';
import { VarioMap, type VarioMapOptions } from './vario-map.js';

const params = new URLSearchParams(location.search);
const num = (k: string): number | undefined => {
  const v = params.get(k);
  return v === null || v === '' ? undefined : Number(v);
};
const pair = (k: string): number[] | undefined => params.get(k)?.split(',').map(Number);
const options: VarioMapOptions = { container: 'map', source: params.get('source') ?? 'cube/', minScale: 1e-9, maxScale: Infinity, attributionControl: false };
const center = pair('center');
if (center) options.centerProjected = [center[0] ?? NaN, center[1] ?? NaN];
const bbox = pair('bbox');
if (bbox) options.boundsProjected = [bbox[0] ?? NaN, bbox[1] ?? NaN, bbox[2] ?? NaN, bbox[3] ?? NaN];
const scale = num('scale');
if (scale !== undefined) options.scaleDenominator = scale;
const z = num('z');
if (z !== undefined) options.sliceZ = z;
const surface = params.get('surface');
if (surface) options.surface = surface;
const ss = num('supersampling');
if (ss !== undefined) options.supersampling = ss;
const budget = num('budget');
if (budget !== undefined) options.gpuMemoryBudget = budget;
const ratio = num('ratio');
if (ratio !== undefined) options.pixelRatio = ratio;
if (params.get('boundaries') === '1') options.boundaries = { enabled: true };
if (params.get('lines') === '0') options.lines = false;
// A style to draw from the start (JSON, as setStyle takes it).
const style = params.get('style');
if (style) options.style = JSON.parse(style) as NonNullable<VarioMapOptions['style']>;
const blending = params.get('blending');
if (blending === 'off' || blending === 'moving' || blending === 'always') options.blending = { mode: blending };
const retries = num('retries'), backoff = num('backoff'), concurrency = num('concurrency');
options.sourceOptions = {};
if (retries !== undefined) options.sourceOptions.retries = retries;
if (backoff !== undefined) options.sourceOptions.backoffMs = backoff;
if (concurrency !== undefined) options.sourceOptions.concurrency = concurrency;

const map = new VarioMap(options);
const info = document.getElementById('info');
const say = (text: string): void => {
  if (info) info.textContent = text;
};
map.on('error', (e) => say(`${e.kind} error: ${e.message}`));

const tool = params.get('tool');
const lens = new LensControl();
const idw = new IdwControl();
if (tool === 'lens') map.addControl(lens.enable());
if (tool === 'idw') map.addControl(idw.enable());
if (params.get('legend') === '1') map.addControl(new LegendControl(), 'top-right');
if (tool !== 'idw') {
  map.on('click', (ev) => {
    const f = ev.feature;
    const what = f?.kind === 'face' ? `face ${f.face}, steps ${f.stepLow}-${f.stepHigh}` : 'line';
    say(f ? `${f.classLabel} (${what})\n${JSON.stringify(f.properties, null, 1)}` : '');
  });
}

Object.assign(window, { map, engine: engineOf(map), lens, idw });
