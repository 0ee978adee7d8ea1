// The elements controls are made of: a group box and a labelled button (keyboard-operable as
// a native button is), and SVG drawings.

export function controlGroup(className: string): HTMLElement {
  const d = document.createElement('div');
  d.className = `vario-map-ctrl vario-map-ctrl-group ${className}`;
  return d;
}

export function controlButton(className: string, label: string, text: string, onClick: () => void): HTMLButtonElement {
  const b = document.createElement('button');
  b.type = 'button';
  b.className = className;
  b.setAttribute('aria-label', label);
  b.title = label;
  b.textContent = text;
  b.addEventListener('click', onClick);
  return b;
}

/** A labelled form field in a panel. */
export function field(label: string, input: HTMLInputElement | HTMLSelectElement, id: string): HTMLElement {
  const row = document.createElement('div');
  row.className = 'vario-map-field';
  const l = document.createElement('label');
  l.htmlFor = id;
  l.textContent = label;
  input.id = id;
  row.append(l, input);
  return row;
}

export function numberInput(min: number, max: number, step: number, value: number): HTMLInputElement {
  const i = document.createElement('input');
  i.type = 'number';
  i.min = String(min);
  i.max = String(max);
  i.step = String(step);
  i.value = String(value);
  return i;
}

export function select(options: [string, string][], value: string): HTMLSelectElement {
  const s = document.createElement('select');
  for (const [v, text] of options) {
    const o = document.createElement('option');
    o.value = v;
    o.textContent = text;
    s.appendChild(o);
  }
  s.value = value;
  return s;
}

/** An SVG element with these attributes (a drawing of `size` px square when `name` is 'svg'). */
export function svgNode<K extends keyof SVGElementTagNameMap>(name: K, attributes: Record<string, string | number>): SVGElementTagNameMap[K] {
  const el = document.createElementNS('http://www.w3.org/2000/svg', name);
  for (const [k, v] of Object.entries(attributes)) el.setAttribute(k, String(v));
  return el;
}

/** A decorative drawing (hidden from screen readers), `size` CSS px square in its own units. */
export function svgIcon(size: number): SVGSVGElement {
  return svgNode('svg', { viewBox: `0 0 ${size} ${size}`, width: size, height: size, 'aria-hidden': 'true' });
}
