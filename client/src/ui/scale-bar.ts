// The scale: "1:25 000" and a bar of a round ground length, and the scale announced to screen
// readers when a movement ends.
import { formatDistance, formatScale, scaleBarLength } from '../geometry/scale-bar-length.js';
import { resolutionAtScale } from '../geometry/view.js';
import type { Control, VarioMap } from '../vario-map.js';
import { ScaleAnnouncer } from './scale-announcer.js';

export class ScaleBar implements Control {
  private map: VarioMap | null = null;
  private el: HTMLElement | null = null;
  private bar: HTMLElement | null = null;
  private text: HTMLElement | null = null;
  private readonly announcer = new ScaleAnnouncer();

  constructor(private readonly maxWidthPx = 100) {}

  onAdd(map: VarioMap): HTMLElement {
    this.map = map;
    const el = document.createElement('div');
    el.className = 'vario-map-ctrl vario-map-scale';
    el.setAttribute('role', 'status');
    el.setAttribute('aria-live', 'off');
    this.text = document.createElement('div');
    this.text.className = 'vario-map-scale-denominator';
    this.bar = document.createElement('div');
    this.bar.className = 'vario-map-scale-bar';
    el.append(this.text, this.bar, this.announcer.element);
    this.el = el;
    map.on('move', this.update);
    map.on('meta', this.update);
    map.on('moveend', this.announce);
    this.update();
    return el;
  }

  onRemove(map: VarioMap): void {
    map.off('move', this.update);
    map.off('meta', this.update);
    map.off('moveend', this.announce);
    this.map = null;
  }

  private readonly announce = (): void => {
    if (this.map?.getMetadata()) this.announcer.announce(this.map.getScaleDenominator());
  };

  private readonly update = (): void => {
    const map = this.map;
    if (!map || !this.text || !this.bar || !this.el) return;
    const meta = map.getMetadata();
    if (!meta) return;
    const scale = map.getScaleDenominator();
    const { length, px } = scaleBarLength(resolutionAtScale(scale, meta.pixelSizeMm), this.maxWidthPx);
    this.text.textContent = formatScale(scale);
    this.bar.style.width = `${Math.round(px)}px`;
    this.bar.textContent = formatDistance(length);
    this.el.setAttribute('aria-label', `Scale ${formatScale(scale)}, bar ${formatDistance(length)}`);
  };
}
