// Where a marker's or popup's element goes: which of its points (the anchor) sits on the place,
// moved by an offset in CSS px, as MapLibre GL JS places them. Pure but for the one style write
// (to any element: no DOM types, so the unit test runs in Node).

export type Anchor = 'center' | 'top' | 'bottom' | 'left' | 'right' | 'top-left' | 'top-right' | 'bottom-left' | 'bottom-right';

/** Moves the element so that its anchor point is at its top left corner. */
const ANCHOR_TRANSLATE: Record<Anchor, string> = {
  center: 'translate(-50%, -50%)',
  top: 'translate(-50%, 0)',
  'top-left': 'translate(0, 0)',
  'top-right': 'translate(-100%, 0)',
  bottom: 'translate(-50%, -100%)',
  'bottom-left': 'translate(0, -100%)',
  'bottom-right': 'translate(-100%, -100%)',
  left: 'translate(0, -50%)',
  right: 'translate(-100%, -50%)',
};

/** An offset: [x, y] CSS px, or a distance away from the place in the anchor's direction (MapLibre's number form). */
export type Offset = number | [number, number];

export function offsetFor(anchor: Anchor, offset: Offset): [number, number] {
  if (Array.isArray(offset)) return offset;
  const d = offset, c = offset / Math.SQRT2;
  const away: Record<Anchor, [number, number]> = {
    center: [0, 0],
    top: [0, d],
    'top-left': [c, c],
    'top-right': [-c, c],
    bottom: [0, -d],
    'bottom-left': [c, -c],
    'bottom-right': [-c, -c],
    left: [d, 0],
    right: [-d, 0],
  };
  return away[anchor];
}

/**
 * MapLibre's automatic popup anchor: below the place when the element would leave the map at
 * the top, above it when at the bottom, and pushed aside near the left and right edges.
 */
export function autoAnchor(point: [number, number], size: [number, number], mapSize: [number, number]): Anchor {
  const parts: string[] = [];
  if (point[1] < size[1]) parts.push('top');
  else if (point[1] > mapSize[1] - size[1]) parts.push('bottom');
  if (point[0] < size[0] / 2) parts.push('left');
  else if (point[0] > mapSize[0] - size[0] / 2) parts.push('right');
  return parts.length === 0 ? 'bottom' : (parts.join('-') as Anchor);
}

/** Puts the element's anchor point at `point` (CSS px in the map), sub-pixel exact. */
export function placeElement(el: { style: { transform: string } }, point: [number, number], anchor: Anchor): void {
  el.style.transform = `translate(${point[0]}px, ${point[1]}px) ${ANCHOR_TRANSLATE[anchor]}`;
}
