// The elements controls are made of: a group box and a labelled button (keyboard-operable as
// a native button is).

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
