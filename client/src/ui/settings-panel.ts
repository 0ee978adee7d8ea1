// The seed paper's interaction parameters in a panel, changeable while the map runs: the zoom
// step factor, the zoom and pan animation durations (0: none), blending and its distance, the
// slicing surface (flat, tilted, sine waves, or the lens and control point tools, driven through
// their controls), the comparison mode (discrete scales), and the interaction log's export.
// Native, labelled form controls, so the panel works from the keyboard and with screen readers.
import { InteractionLog } from '../research/interaction-log.js';
import type { SurfaceSpec } from '../../../format/slicing-surface.js';
import { resolutionAtScale } from '../geometry/view.js';
import type { BlendMode, Control, VarioMap } from '../vario-map.js';
import { controlButton, controlGroup, field, numberInput, select } from './control-dom.js';
import { IdwControl } from './idw-control.js';
import { LensControl } from './lens-control.js';

export type SurfaceMode = 'flat' | 'lens' | 'idw' | 'tilted' | 'sine';

let panels = 0;

export class SettingsPanel implements Control {
  /** The interaction log the panel records and exports (made on onAdd unless given). */
  log: InteractionLog | null = null;
  private map: VarioMap | null = null;
  /** The tools the surface modes 'lens' and 'idw' turn on. */
  readonly lens = new LensControl();
  readonly idw = new IdwControl();
  private mode: SurfaceMode = 'flat';

  constructor(private readonly options: { log?: InteractionLog | boolean } = {}) {}

  onAdd(map: VarioMap): HTMLElement {
    this.map = map;
    this.lens.attach(map);
    this.idw.attach(map);
    const log = this.options.log ?? true;
    this.log = log instanceof InteractionLog ? log : log ? new InteractionLog(map) : null;
    const n = ++panels;
    const id = (k: string): string => `vario-map-settings-${n}-${k}`;
    const group = controlGroup('vario-map-settings');
    const panel = document.createElement('form');
    panel.className = 'vario-map-settings-panel';
    panel.id = id('panel');
    panel.hidden = true;
    panel.setAttribute('aria-label', 'Map settings');
    panel.addEventListener('submit', (e) => e.preventDefault());
    const toggle = controlButton('vario-map-settings-toggle', 'Settings', '\u2699', () => {
      panel.hidden = !panel.hidden;
      toggle.setAttribute('aria-expanded', String(!panel.hidden));
      if (!panel.hidden) panel.querySelector<HTMLElement>('input, select')?.focus();
    });
    toggle.setAttribute('aria-expanded', 'false');
    toggle.setAttribute('aria-controls', panel.id);
    panel.addEventListener('keydown', (e) => {
      if (e.key !== 'Escape') return;
      panel.hidden = true;
      toggle.setAttribute('aria-expanded', 'false');
      toggle.focus();
    });

    const s = map.getSettings();
    const b = map.getBlending();
    const zoomStep = numberInput(1.1, 8, 0.1, s.zoomStep);
    const zoomMs = numberInput(0, 5000, 50, s.zoomDurationMs);
    const panMs = numberInput(0, 5000, 50, s.panDurationMs);
    const blend = select([['off', 'Off'], ['moving', 'While moving'], ['always', 'Always']], b.mode);
    const blendDist = numberInput(0.1, 50, 0.1, b.distance);
    const surface = select([['flat', 'Flat (one scale)'], ['lens', 'Lens at the pointer'], ['idw', 'Control points (click to place)'], ['tilted', 'Tilted (detail at the bottom)'], ['sine', 'Sine waves']], this.mode);
    const comparison = document.createElement('input');
    comparison.type = 'checkbox';
    comparison.checked = s.comparisonMode;
    const num = (i: HTMLInputElement, min: number): number | null => {
      const v = Number(i.value);
      return i.value !== '' && Number.isFinite(v) && v >= min ? v : null;
    };
    const on = (el: HTMLElement, fn: () => void): void => el.addEventListener('change', fn);
    on(zoomStep, () => {
      const v = num(zoomStep, 1.01);
      if (v !== null) map.setSettings({ zoomStep: v });
    });
    on(zoomMs, () => {
      const v = num(zoomMs, 0);
      if (v !== null) map.setSettings({ zoomDurationMs: v });
    });
    on(panMs, () => {
      const v = num(panMs, 0);
      if (v !== null) map.setSettings({ panDurationMs: v });
    });
    on(blend, () => map.setBlending({ mode: blend.value as BlendMode }));
    on(blendDist, () => {
      const v = num(blendDist, 0.01);
      if (v !== null) map.setBlending({ distance: v });
    });
    on(surface, () => {
      this.mode = surface.value as SurfaceMode;
      this.applySurface();
    });
    on(comparison, () => map.setSettings({ comparisonMode: comparison.checked }));

    panel.append(
      field('Zoom step factor', zoomStep, id('zoom-step')),
      field('Zoom animation (ms)', zoomMs, id('zoom-ms')),
      field('Pan animation (ms)', panMs, id('pan-ms')),
      field('Blending', blend, id('blending')),
      field('Blending distance (steps)', blendDist, id('blend-distance')),
      field('Slicing surface', surface, id('surface')),
      field('Discrete scales (classic multi-scale map)', comparison, id('comparison')),
    );
    if (this.log) panel.append(this.logFields(this.log, id));
    group.append(toggle, panel);

    map.on('move', this.onMove);
    map.on('meta', this.onMeta);
    return group;
  }

  onRemove(map: VarioMap): void {
    map.off('move', this.onMove);
    map.off('meta', this.onMeta);
    this.lens.detach();
    this.idw.detach();
    this.log?.stop();
    this.map = null;
  }

  private logFields(log: InteractionLog, id: (k: string) => string): HTMLElement {
    const box = document.createElement('fieldset');
    const legend = document.createElement('legend');
    legend.textContent = 'Interaction log';
    const rec = document.createElement('input');
    rec.type = 'checkbox';
    rec.checked = log.active;
    rec.addEventListener('change', () => (rec.checked ? log.start() : log.stop()));
    const save = (name: string, type: string, text: () => string): HTMLButtonElement =>
      controlButton('vario-map-log-export', `Export the log as ${name}`, name, () => {
        const url = URL.createObjectURL(new Blob([text()], { type }));
        const a = document.createElement('a');
        a.href = url;
        a.download = `interaction-log.${name.toLowerCase()}`;
        a.click();
        setTimeout(() => URL.revokeObjectURL(url), 1000);
      });
    const clear = controlButton('vario-map-log-clear', 'Clear the log', 'Clear', () => log.clear());
    const buttons = document.createElement('div');
    buttons.className = 'vario-map-log-buttons';
    buttons.append(save('JSON', 'application/json', () => JSON.stringify(log.toJSON(), null, 1)), save('CSV', 'text/csv', () => log.toCSV()), clear);
    box.append(legend, field('Record', rec, id('log-record')), buttons);
    return box;
  }

  private readonly onMove = (): void => {
    if (this.mode === 'tilted') this.applySurface();
  };

  /** A mode chosen before the cube was known (proj4 may still load after the first map) takes effect now. */
  private readonly onMeta = (): void => {
    if (this.mode !== 'flat') this.applySurface();
  };

  /** The surface for the mode, sized to the view (its ground size and the cube's z range); none before 'meta' (onMeta). */
  private applySurface(): void {
    const map = this.map;
    const meta = map?.getMetadata();
    if (!map || !meta) return;
    // The tools own the surface in their modes.
    if (this.mode !== 'lens') this.lens.disable();
    if (this.mode !== 'idw') this.idw.disable();
    if (this.mode === 'lens' || this.mode === 'idw') {
      this[this.mode].enable();
      return;
    }
    const res = resolutionAtScale(map.getScaleDenominator(), meta.pixelSizeMm);
    const [cx, cy] = map.getCenterProjected();
    const rect = map.getCanvasContainer().getBoundingClientRect();
    let spec: SurfaceSpec;
    switch (this.mode) {
      case 'flat':
        spec = { kind: 'flat' };
        break;
      case 'tilted':
        // More detail toward the bottom of the screen, as a landscape seen at an angle.
        spec = { kind: 'tilted', cx, cy, dzdx: 0, dzdy: (meta.zMax * 0.15) / Math.max(1, (rect.height / 2) * res) };
        break;
      case 'sine':
        spec = { kind: 'sine', amplitude: meta.zMax * 0.05, wavelength: Math.max(1, (rect.width / 2) * res), angle: 30 };
        break;
    }
    map.setSlicingSurface(spec);
  }
}
