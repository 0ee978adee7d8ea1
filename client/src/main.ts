// The demo page: a SliceMap over the cube named by the URL (?source=dir/), with optional view,
// surface and tools from URL parameters:
//   center=x,y  scale=n  bbox=x0,y0,x1,y1  z=steps  surface=kind:key=value,...  tool=lens|idw
//   supersampling=n  boundaries=1  blending=off|moving|always  budget=bytes  ratio=dpr
//   retries=n  backoff=ms  concurrency=n (chunk loading)
// `window.map` (and `window.lens`, `window.idw`) are there for the console and the tests.
import { SliceMap, type SliceMapOptions } from './slice-map.js';
import { IdwControl } from './ui/idw-control.js';
import { LensControl } from './ui/lens-control.js';

const params = new URLSearchParams(location.search);
const num = (k: string): number | undefined => {
  const v = params.get(k);
  return v === null || v === '' ? undefined : Number(v);
};
const options: SliceMapOptions = { container: 'map', source: params.get('source') ?? 'cube/' };
const center = params.get('center');
if (center) options.center = center.split(',').map(Number) as [number, number];
const bbox = params.get('bbox');
if (bbox) options.bounds = bbox.split(',').map(Number) as [number, number, number, number];
const scale = num('scale');
if (scale !== undefined) options.scaleDenominator = scale;
const z = num('z');
if (z !== undefined) options.z = z;
const surface = params.get('surface');
if (surface) options.surface = surface;
const ss = num('supersampling');
if (ss !== undefined) options.supersampling = ss;
const budget = num('budget');
if (budget !== undefined) options.gpuMemoryBudget = budget;
const ratio = num('ratio');
if (ratio !== undefined) options.pixelRatio = ratio;
if (params.get('boundaries') === '1') options.boundaries = { enabled: true };
const blending = params.get('blending');
if (blending === 'off' || blending === 'moving' || blending === 'always') options.blending = { mode: blending };
const retries = num('retries'), backoff = num('backoff'), concurrency = num('concurrency');
options.sourceOptions = {};
if (retries !== undefined) options.sourceOptions.retries = retries;
if (backoff !== undefined) options.sourceOptions.backoffMs = backoff;
if (concurrency !== undefined) options.sourceOptions.concurrency = concurrency;

const map = new SliceMap(options);
const info = document.getElementById('info')!;
map.on('error', (e) => {
  info.textContent = `${e.kind} error: ${e.message}`;
});

const tool = params.get('tool');
const lens = new LensControl(map);
const idw = new IdwControl(map);
if (tool === 'lens') lens.enable();
if (tool === 'idw') idw.enable();
if (tool !== 'idw') {
  map.canvas.addEventListener('click', (ev) => {
    const rect = map.container.getBoundingClientRect();
    map.queryFeatures([ev.clientX - rect.left, ev.clientY - rect.top]).then(
      (fs) => {
        const f = fs[0];
        info.textContent = f ? `${f.classLabel} (face ${f.face}, steps ${f.stepLow}-${f.stepHigh})\n${JSON.stringify(f.properties, null, 1)}` : '';
      },
      (err: unknown) => {
        info.textContent = `picking failed: ${(err as Error).message}`;
      },
    );
  });
}

Object.assign(window, { map, lens, idw });
