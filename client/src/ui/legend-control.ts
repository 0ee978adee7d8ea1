// The legend: one entry per class of the style drawn, a swatch (fill and pattern) and the
// class's label, in the style's order. A list with a heading for screen readers; a button
// folds it away. Follows setStyle and setClassStyle.
import type { CubeStyle, StyleClass } from '../../../format/style.js';
import type { Control, VarioMap } from '../vario-map.js';
import { svgIcon, svgNode } from './control-dom.js';

export interface LegendOptions {
  /** The heading (default "Legend"). */
  title?: string;
  /** A button folds the list away and back (default true). */
  collapsible?: boolean;
  /** Starts folded (default false). */
  collapsed?: boolean;
}

let legendCount = 0;

export class LegendControl implements Control {
  private el: HTMLElement | null = null;
  private list: HTMLUListElement | null = null;
  private toggle: HTMLButtonElement | null = null;

  constructor(private readonly options: LegendOptions = {}) {}

  onAdd(map: VarioMap): HTMLElement {
    const id = `vario-map-legend-${++legendCount}`;
    const el = document.createElement('section');
    el.className = 'vario-map-ctrl vario-map-legend';
    el.setAttribute('aria-labelledby', `${id}-title`);
    const heading = document.createElement('h2');
    heading.className = 'vario-map-legend-title';
    heading.id = `${id}-title`;
    const title = this.options.title ?? 'Legend';
    const list = document.createElement('ul');
    list.className = 'vario-map-legend-list';
    list.id = `${id}-list`;
    if (this.options.collapsible ?? true) {
      const b = document.createElement('button');
      b.type = 'button';
      b.className = 'vario-map-legend-toggle';
      b.setAttribute('aria-controls', list.id);
      b.textContent = title;
      b.addEventListener('click', () => this.setCollapsed(!list.hidden));
      heading.append(b);
      this.toggle = b;
    } else heading.textContent = title;
    el.append(heading, list);
    this.el = el;
    this.list = list;
    this.setCollapsed(this.options.collapsed ?? false);
    map.on('style', this.update);
    this.update(map.getStyle());
    return el;
  }

  onRemove(map: VarioMap): void {
    map.off('style', this.update);
    this.el = this.list = this.toggle = null;
  }

  /** Folds the list away (true) or shows it. */
  setCollapsed(collapsed: boolean): void {
    if (!this.list) return;
    this.list.hidden = collapsed;
    this.toggle?.setAttribute('aria-expanded', String(!collapsed));
  }

  private readonly update = (style: CubeStyle | null): void => {
    if (!this.list || !this.el) return;
    this.el.hidden = !style;
    this.list.replaceChildren(...(style?.classes ?? []).map((c) => entry(c)));
  };
}

function entry(c: StyleClass): HTMLLIElement {
  const li = document.createElement('li');
  li.className = 'vario-map-legend-item';
  li.dataset.class = c.key;
  const label = document.createElement('span');
  label.textContent = c.label;
  li.append(swatch(c), label);
  return li;
}

/** The class's fill with its pattern over it, as the map draws them (8 px cell, 1.25 px lines). */
function swatch(c: StyleClass): SVGSVGElement {
  const svg = svgIcon(16);
  svg.classList.add('vario-map-legend-swatch');
  svg.append(svgNode('rect', { width: 16, height: 16, fill: c.color }));
  const p = c.pattern;
  if (p) {
    const lines = (dir: 1 | -1): string => [0, 8, 16, 24].map((k) => (dir === 1 ? `M${k - 16} 16L${k} 0` : `M${k - 16} 0L${k} 16`)).join('');
    const dots = [4, 12].flatMap((x) => [4, 12].map((y) => `M${x - 1.25} ${y}a1.25 1.25 0 1 0 2.5 0a1.25 1.25 0 1 0 -2.5 0`)).join('');
    const paint: Record<string, string | number> = p.kind === 'dots'
      ? { d: dots, fill: p.color }
      // Hatches run as the map's (top left to bottom right on screen); crosses add the other way.
      : { d: p.kind === 'cross' ? lines(1) + lines(-1) : lines(-1), stroke: p.color, 'stroke-width': 1.25, fill: 'none' };
    svg.append(svgNode('path', { class: 'vario-map-legend-pattern', 'data-kind': p.kind, ...paint }));
  }
  svg.append(svgNode('rect', { width: 16, height: 16, fill: 'none', stroke: 'rgba(0,0,0,.25)' }));
  return svg;
}
