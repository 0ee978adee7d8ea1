// A button that puts the map's container on the whole screen and takes it back (Esc leaves
// too), as MapLibre's: its label says what a press does. The map follows the new size by
// itself (its canvas watches its container).
import type { Control, VarioMap } from '../vario-map.js';
import { controlButton, controlGroup, svgIcon, svgNode } from './control-dom.js';

export interface FullscreenOptions {
  /** What goes fullscreen: by default the map's container, controls and all. */
  container?: HTMLElement;
}

export class FullscreenControl implements Control {
  private target: HTMLElement | null = null;
  private button: HTMLButtonElement | null = null;

  constructor(private readonly options: FullscreenOptions = {}) {}

  onAdd(map: VarioMap): HTMLElement {
    this.target = this.options.container ?? map.getContainer();
    const group = controlGroup('vario-map-fullscreen');
    this.button = controlButton('vario-map-fullscreen-toggle', 'Enter fullscreen', '', () => this.toggle());
    this.button.append(cornersIcon());
    group.append(this.button);
    // A page (or an iframe without allowfullscreen) that cannot go fullscreen shows no button.
    group.hidden = !document.fullscreenEnabled;
    document.addEventListener('fullscreenchange', this.changed);
    return group;
  }

  onRemove(): void {
    document.removeEventListener('fullscreenchange', this.changed);
    if (this.isFullscreen()) void document.exitFullscreen();
    this.target = null;
    this.button = null;
  }

  private isFullscreen(): boolean {
    return this.target !== null && document.fullscreenElement === this.target;
  }

  private toggle(): void {
    const done = this.isFullscreen() ? document.exitFullscreen() : this.target?.requestFullscreen();
    // Refused (e.g. by the page's permissions policy): the map stays as it was.
    done?.catch((e: unknown) => console.warn('VarioMap: fullscreen refused', e));
  }

  private readonly changed = (): void => {
    if (!this.button) return;
    const label = this.isFullscreen() ? 'Exit fullscreen' : 'Enter fullscreen';
    this.button.setAttribute('aria-label', label);
    this.button.title = label;
  };
}

/** Four corners, drawn: the fullscreen glyph (U+26F6) is missing from many fonts. */
function cornersIcon(): SVGSVGElement {
  const svg = svgIcon(18);
  svg.style.verticalAlign = 'middle';
  svg.append(svgNode('path', { d: 'M2 7V2h5M11 2h5v5M16 11v5h-5M7 16H2v-5', fill: 'none', stroke: 'currentColor', 'stroke-width': 2 }));
  return svg;
}
