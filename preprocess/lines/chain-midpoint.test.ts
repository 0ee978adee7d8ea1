// The port of a shared boundary: halfway along it, the same to the last bit from either side.
import test from 'node:test';
import assert from 'node:assert/strict';
import { chainMidpoint } from './chain-midpoint.js';

const reversed = (c: number[]): number[] => {
  const out: number[] = [];
  for (let i = c.length - 2; i >= 0; i -= 2) out.push(c[i]!, c[i + 1]!);
  return out;
};

test('halfway along a chain by length, worked by hand', () => {
  // Lengths 3, 4 and 5 (total 12): halfway is 3 into the second segment, from (3, 0) up to (3, 4).
  assert.deepEqual(chainMidpoint([0, 0, 3, 0, 3, 4, 0, 0]), { x: 3, y: 3 });
  assert.deepEqual(chainMidpoint([0, 0, 10, 0]), { x: 5, y: 0 });
  // On a vertex: (4, 0) is halfway along two equal segments.
  assert.deepEqual(chainMidpoint([0, 0, 4, 0, 4, 4]), { x: 4, y: 0 });
});

test('a chain walked the other way gives the identical point, where walking each way round differs in the last bit', () => {
  // National grid coordinates; walking this chain from either end by the same arithmetic
  // lands 3e-11 m apart in x (found by search), so only a canonical order makes them meet.
  const c = [181013.28351135054, 457008.37640138733, 181037.27136782242, 457026.1961567338, 181014.68169536194, 457000.1168161631, 181038.83300984223, 457008.21809475694, 181095.65201168676, 457018.2561322666];
  const a = chainMidpoint(c), b = chainMidpoint(reversed(c));
  assert.ok(a.x === b.x && a.y === b.y, `(${a.x}, ${a.y}) and (${b.x}, ${b.y})`);
  // And it is halfway: on a segment (collinear to rounding), with half the length before it.
  let before = 0, total = 0, upTo = NaN;
  for (let i = 0; i + 2 < c.length; i += 2) {
    const ax = c[i]!, ay = c[i + 1]!, bx = c[i + 2]!, by = c[i + 3]!;
    const l = Math.hypot(bx - ax, by - ay);
    const da = Math.hypot(a.x - ax, a.y - ay), db = Math.hypot(bx - a.x, by - a.y);
    if (Number.isNaN(upTo) && Math.abs(da + db - l) < 1e-9) upTo = before + da;
    before += l;
    total += l;
  }
  assert.ok(Math.abs(upTo - total / 2) < 1e-9, `${upTo} vs ${total / 2}`);
});

test('a closed chain gives the same point from any start and either direction', () => {
  const ring = [[0.1, 0.2], [10.3, 0.7], [9.9, 6.1], [0.4, 5.3]];
  const points = new Set<string>();
  for (let s = 0; s < ring.length; s++) {
    const rot = [...ring.slice(s), ...ring.slice(0, s)];
    const closed = [...rot, rot[0]!].flat();
    for (const c of [closed, reversed(closed)]) {
      const p = chainMidpoint(c);
      points.add(`${p.x},${p.y}`);
    }
  }
  assert.equal(points.size, 1, [...points].join(' | '));
});
