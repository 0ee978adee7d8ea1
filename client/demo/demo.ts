// The full-page demo `npm start` serves, built only on the library's public API: every control,
// the URL hash, flights to a few places, and the face under a click.
// ?source=<index.json or directory> picks another cube (default: chunks/ beside the page);
// ?reduceMotion=1|0, ?supersampling=n and ?lines=0|1 override those options; ?sw=0 leaves the
// service worker (offline use) out.
import { FullscreenControl, ScaleBar, SettingsPanel, VarioMap, ZoomControl, type Control, type VarioMapOptions } from '../src/lib/bundle.js';
import { enableOffline } from './offline.js';

const params = new URLSearchParams(location.search);
const options: VarioMapOptions = { container: 'map', source: params.get('source') ?? 'chunks/', hash: true };
const reduce = params.get('reduceMotion');
if (reduce !== null) options.reduceMotion = reduce !== '0';
const ss = params.get('supersampling');
if (ss !== null) options.supersampling = Number(ss);
const lines = params.get('lines');
if (lines !== null) options.lines = lines !== '0';
const map = new VarioMap(options);
const settings = new SettingsPanel();
map.addControl(new ZoomControl(), 'top-right');
map.addControl(new FullscreenControl(), 'top-right');
map.addControl(settings, 'top-right');
map.addControl(new ScaleBar(), 'bottom-left');

/** A box with the title, flights to a few places and the face last clicked. */
class InfoBox implements Control {
  private feature: HTMLElement | null = null;

  onAdd(m: VarioMap): HTMLElement {
    const el = document.createElement('div');
    el.className = 'vario-map-ctrl demo-info';
    const h = document.createElement('h1');
    h.textContent = 'Vario-scale map';
    const hint = document.createElement('p');
    hint.textContent = 'Wheel, drag, pinch, double-click, shift-drag a box, or focus the map and use + - and the arrows.';
    const places = document.createElement('p');
    const fly = (label: string, target: () => Parameters<VarioMap['flyTo']>[0]): void => {
      const b = document.createElement('button');
      b.type = 'button';
      b.textContent = label;
      b.addEventListener('click', () => void m.flyTo(target()));
      places.appendChild(b);
    };
    const meta = (): NonNullable<ReturnType<VarioMap['getMetadata']>> => {
      const md = m.getMetadata();
      if (!md) throw new Error('the map has not loaded yet');
      return md;
    };
    const at = (fx: number, fy: number): [number, number] => {
      const e = meta().extent;
      return [e[0] + fx * (e[2] - e[0]), e[1] + fy * (e[3] - e[1])];
    };
    fly('Overview', () => ({ centerProjected: at(0.5, 0.5), scaleDenominator: m.getComparisonScales().at(-1) ?? meta().baseScale * 16 }));
    fly('North-west', () => ({ centerProjected: at(0.2, 0.8), scaleDenominator: meta().baseScale }));
    fly('South-east', () => ({ centerProjected: at(0.8, 0.2), scaleDenominator: meta().baseScale }));
    this.feature = document.createElement('p');
    this.feature.className = 'demo-feature';
    this.feature.setAttribute('aria-live', 'polite');
    el.append(h, hint, places, this.feature);
    m.on('click', this.onClick);
    return el;
  }

  onRemove(m: VarioMap): void {
    m.off('click', this.onClick);
  }

  private readonly onClick = (ev: { feature: ({ kind: 'face'; face: number } | { kind: 'line' }) & { classLabel: string; scaleRange: [number, number] } | null }): void => {
    if (!this.feature) return;
    const f = ev.feature;
    const what = f?.kind === 'face' ? `face ${f.face}` : 'line';
    this.feature.textContent = f ? `${f.classLabel} (${what}), shown from 1:${Math.round(f.scaleRange[0])} to 1:${Math.round(f.scaleRange[1])}` : '';
  };
}
map.addControl(new InfoBox(), 'top-left');
map.on('error', (e) => console.warn(`map: ${e.kind} error: ${e.message}`));

/** Offered when the service worker has fetched a new build of the cube: reloading shows it. */
function showNewBuild(): void {
  if (document.querySelector('.demo-update')) return;
  const box = document.createElement('div');
  box.className = 'demo-update';
  box.setAttribute('role', 'status');
  const text = document.createElement('span');
  text.textContent = 'The map data has been updated. ';
  const reload = document.createElement('button');
  reload.type = 'button';
  reload.textContent = 'Reload';
  reload.addEventListener('click', () => location.reload());
  box.append(text, reload);
  document.body.appendChild(box);
}

if (params.get('sw') !== '0') enableOffline(map, showNewBuild);

Object.assign(window, { map, settings });
