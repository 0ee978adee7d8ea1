// The default marker: a pin whose tip is the middle of its bottom edge (placed with anchor
// 'bottom'), drawn as SVG in the marker's colour with a white dot.

export const PIN_WIDTH_PX = 27;
export const PIN_HEIGHT_PX = 41;

const SVG_NS = 'http://www.w3.org/2000/svg';

export function createPin(color: string): HTMLElement {
  const el = document.createElement('div');
  el.className = 'vario-map-marker-pin';
  const svg = document.createElementNS(SVG_NS, 'svg');
  svg.setAttribute('width', String(PIN_WIDTH_PX));
  svg.setAttribute('height', String(PIN_HEIGHT_PX));
  svg.setAttribute('viewBox', `0 0 ${PIN_WIDTH_PX} ${PIN_HEIGHT_PX}`);
  svg.setAttribute('aria-hidden', 'true');
  const body = document.createElementNS(SVG_NS, 'path');
  // A circle of radius 12.5 around (13.5, 13.5) narrowing to the tip at (13.5, 41).
  body.setAttribute('d', 'M13.5 41 C11 33 1 25 1 13.5 A12.5 12.5 0 0 1 26 13.5 C26 25 16 33 13.5 41 Z');
  body.setAttribute('fill', color);
  body.setAttribute('stroke', 'rgba(0, 0, 0, 0.25)');
  const dot = document.createElementNS(SVG_NS, 'circle');
  dot.setAttribute('cx', '13.5');
  dot.setAttribute('cy', '13.5');
  dot.setAttribute('r', '5');
  dot.setAttribute('fill', '#fff');
  svg.append(body, dot);
  el.appendChild(svg);
  return el;
}
