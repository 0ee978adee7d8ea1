// The dataset's attribution, from its metadata (index.json), plus any the page adds.
import type { Control, VarioMap } from '../vario-map.js';

export class AttributionControl implements Control {
  private el: HTMLElement | null = null;
  private map: VarioMap | null = null;

  constructor(private readonly extra: string[] = []) {}

  onAdd(map: VarioMap): HTMLElement {
    this.map = map;
    this.el = document.createElement('div');
    this.el.className = 'vario-map-ctrl vario-map-attrib';
    map.on('meta', this.update);
    this.update();
    return this.el;
  }

  onRemove(map: VarioMap): void {
    map.off('meta', this.update);
    this.map = null;
  }

  private readonly update = (): void => {
    if (!this.el || !this.map) return;
    const own = this.map.getMetadata()?.attribution ?? '';
    // Text only: an attribution is data, not markup to run.
    this.el.textContent = [own, ...this.extra].filter((s) => s.trim() !== '').join(' | ');
    this.el.hidden = this.el.textContent === '';
  };
}
