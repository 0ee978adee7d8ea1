import { test } from 'node:test';
import assert from 'node:assert/strict';
import { chooseClassColours, PALETTE, shade } from './class-colours.js';

/** Hue in degrees and saturation (HSL) of "#rrggbb": computed here, independent of the module. */
function hueSat(hex: string): { hue: number; sat: number } {
  const [r, g, b] = [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16) / 255) as [number, number, number];
  const max = Math.max(r, g, b), min = Math.min(r, g, b), d = max - min;
  if (d === 0) return { hue: 0, sat: 0 };
  const l = (max + min) / 2;
  const sat = d / (1 - Math.abs(2 * l - 1));
  const h = max === r ? ((g - b) / d) % 6 : max === g ? (b - r) / d + 2 : (r - g) / d + 4;
  return { hue: (h * 60 + 360) % 360, sat };
}
const isBlue = (hex: string): boolean => { const { hue, sat } = hueSat(hex); return sat > 0.15 && hue >= 180 && hue <= 260; };
const isGreen = (hex: string): boolean => { const { hue, sat } = hueSat(hex); return sat > 0.15 && hue >= 60 && hue <= 170; };
const isRed = (hex: string): boolean => { const { hue, sat } = hueSat(hex); return sat > 0.15 && (hue <= 20 || hue >= 340); };
const byKey = (keys: string[]) => new Map(chooseClassColours(keys).map((c) => [c.key, c]));

test('NLCD codes get the NLCD legend: open water blue, the forests green, developed red', () => {
  const c = byKey(['11', '21', '22', '23', '24', '31', '41', '42', '43', '52', '71', '81', '82', '90', '95']);
  assert.ok(isBlue(c.get('11')!.color), c.get('11')!.color);
  for (const k of ['41', '42', '43']) assert.ok(isGreen(c.get(k)!.color), `${k}: ${c.get(k)!.color}`);
  assert.ok(isRed(c.get('23')!.color));
  assert.equal(c.get('11')!.label, 'Open water');
  assert.equal(c.get('42')!.source, 'NLCD');
});

test('CORINE codes get the CORINE legend; one value outside a nomenclature drops it for all', () => {
  const c = byKey(['112', '211', '311', '312', '512']);
  assert.equal(c.get('311')!.label, 'Broad-leaved forest');
  assert.ok(isGreen(c.get('312')!.color) && isGreen(c.get('311')!.color));
  const water = hueSat(c.get('512')!.color); // CORINE draws water bodies cyan
  assert.ok(water.hue >= 160 && water.hue <= 260 && water.sat > 0.15, c.get('512')!.color);
  // 11 is NLCD water, but 1..17 is not NLCD: nothing here may be read as a nomenclature.
  const plain = chooseClassColours(Array.from({ length: 17 }, (_, i) => String(i + 1)));
  assert.ok(plain.every((p) => p.source === 'palette'));
});

test('BGT/TOP10NL layer names: waterdeel blue, pand a building colour, begroeidterreindeel green', () => {
  const c = byKey(['begroeidterreindeel', 'pand', 'waterdeel', 'wegdeel', 'Gebouw']);
  assert.ok(isBlue(c.get('waterdeel')!.color));
  assert.ok(isGreen(c.get('begroeidterreindeel')!.color));
  assert.equal(c.get('pand')!.label, 'building');
  assert.equal(c.get('Gebouw')!.source, 'BGT/TOP10NL');
  // Two names for one legend colour stay apart.
  assert.notEqual(c.get('Gebouw')!.color, c.get('pand')!.color);
});

test('names suggest colours: water blue, vegetation green, never the other way round', () => {
  const c = byKey(['Lake', 'river', 'Mixed forest', 'Shrubland', 'grassland', 'Woody wetlands', 'onbegroeid', 'zz-unknown']);
  assert.ok(isBlue(c.get('Lake')!.color) && isBlue(c.get('river')!.color));
  for (const k of ['Mixed forest', 'Shrubland', 'grassland']) {
    assert.ok(isGreen(c.get(k)!.color), `${k}: ${c.get(k)!.color}`);
    assert.ok(!isBlue(c.get(k)!.color));
  }
  assert.equal(c.get('Woody wetlands')!.source, 'name: wetland');
  assert.equal(c.get('onbegroeid')!.source, 'name: bare');
  assert.equal(c.get('zz-unknown')!.source, 'palette');
});

test('the fixed palette holds no blue, and its colours and their shades are distinct', () => {
  for (const p of PALETTE) assert.ok(!isBlue(p), p);
  const many = chooseClassColours(Array.from({ length: 40 }, (_, i) => `k${i}`)).map((c) => c.color);
  assert.equal(new Set(many).size, 40);
  for (const c of many) assert.ok(!isBlue(c), c);
  assert.equal(shade('#808080', 0), '#808080');
  assert.equal(shade('#808080', 1), '#717171'); // 12% darker: 128 * 0.88 = 112.6
  assert.equal(shade('#808080', 2), '#8f8f8f'); // 12% towards white: 128 + 127 * 0.12 = 143.2
});

test('the same keys give the same colours', () => {
  const keys = ['b', 'a', 'water', 'c'];
  assert.deepEqual(chooseClassColours(keys), chooseClassColours([...keys]));
});
