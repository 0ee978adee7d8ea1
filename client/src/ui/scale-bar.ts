// The scale: "1:25 000" and a bar of a round ground length.
import { formatDistance, formatScale, scaleBarLength } from '../geometry/scale-bar-length.js';
import { resolutionAtScale } from '../geometry/view.js';
import type { Control, VarioMap } from '../vario-map.js';

export class ScaleBar implements Control {
  private map: VarioMap | null = null;
  private el: HTMLElement | null = null;
  private bar: HTMLElement | null = null;
  private text: HTMLElement | null = null;

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
    el.append(this.text, this.bar);
    this.el = el;
    map.on('move', this.update);
    map.on('meta', this.update);
    this.update();
    return el;
  }

  onRemove(map: VarioMap): void {
    map.off('move', this.update);
    map.off('meta', this.update);
    this.map = null;
  }

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
