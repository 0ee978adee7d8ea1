// ssc style on the four real datasets: the style it writes parses, names every class of the
// data (classes as listed in ../shared/data/README.md), and the small one generalizes and builds.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { dataset } from '../../testing/paths.js';
import { startSscSession, type SscSession } from '../../testing/run-ssc.js';
import { tempDir } from '../../testing/temp-dir.js';
import { loadStyle, parseStyle } from '../style.js';
import { readInput } from '../io/read-input.js';
import { formatStyleJson, scaffoldStyle } from '../style-scaffold/scaffold-style.js';
import { readTgap } from '../../format/tgap.js';

let ssc: SscSession;
before(() => {
  ssc = startSscSession();
});
after(() => ssc.close());

/** Hue in degrees of "#rrggbb" (HSL), for "is it blue, is it green". */
function hue(hex: string): number {
  const [r, g, b] = [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16)) as [number, number, number];
  const max = Math.max(r, g, b), d = max - Math.min(r, g, b);
  const h = max === r ? ((g - b) / d) % 6 : max === g ? (b - r) / d + 2 : (r - g) / d + 4;
  return (h * 60 + 360) % 360;
}

async function scaffold(t: { after: (fn: () => void) => void }, name: string): Promise<{ file: string; stdout: string; dir: string }> {
  const dir = tempDir(t);
  const file = path.join(dir, 'style.json');
  const r = await ssc.run(['style', dataset(name), '--out', file]);
  assert.equal(r.code, 0, r.stderr);
  return { file, stdout: r.stdout, dir };
}

test('bgt_otterlo_400m: layer guessed, waterdeel blue, wegdeel linear; the style generalizes and builds', async (t) => {
  const { file, stdout, dir } = await scaffold(t, 'bgt_otterlo_400m.geojson');
  assert.match(stdout, /class property: layer \(guessed/);
  const style = await loadStyle(file);
  assert.equal(style.classProperty, 'layer');
  assert.equal(style.idProperty, 'lokaalid');
  const cls = new Map(style.classes.map((c) => [c.key, c]));
  assert.deepEqual([...cls.keys()].sort(), ['begroeidterreindeel', 'onbegroeidterreindeel', 'ondersteunendwaterdeel', 'ondersteunendwegdeel', 'overigbouwwerk', 'pand', 'scheiding', 'waterdeel', 'wegdeel']);
  const water = hue(cls.get('waterdeel')!.color);
  assert.ok(water > 180 && water < 260, cls.get('waterdeel')!.color);
  assert.equal(cls.get('wegdeel')!.linear, true);
  assert.equal(cls.get('pand')!.linear, false);
  assert.equal(cls.get('begroeidterreindeel')!.linear, false);
  const tgapFile = path.join(dir, 'x.tgap');
  const g = await ssc.run(['generalize', dataset('bgt_otterlo_400m.geojson'), '--style', file, '--out', tgapFile, '--quiet']);
  assert.equal(g.code, 0, g.stderr);
  const tgap = await readTgap(tgapFile);
  assert.equal(tgap.meta.baseScale, style.baseScale);
  assert.equal(tgap.meta.baseFaces, 475);
  const b = await ssc.run(['build', tgapFile, '--out', path.join(dir, 'cube'), '--quiet', '--no-precompress']);
  assert.equal(b.code, 0, b.stderr);
  // Again: the same bytes.
  const again = path.join(dir, 'again.json');
  assert.equal((await ssc.run(['style', dataset('bgt_otterlo_400m.geojson'), '--out', again])).code, 0);
  assert.equal(readFileSync(again, 'utf8'), readFileSync(file, 'utf8'));
});

test('bgt_otterlo_1800m with --class-property klasse: the 38 classes, the style parses', async (t) => {
  const dir = tempDir(t);
  const file = path.join(dir, 'style.json');
  const r = await ssc.run(['style', dataset('bgt_otterlo_1800m.geojson'), '--class-property', 'klasse', '--out', file]);
  assert.equal(r.code, 0, r.stderr);
  assert.match(r.stdout, /class property: klasse \(given\)/);
  const style = await loadStyle(file);
  assert.equal(style.classes.length, 38);
  const c = new Map(style.classes.map((k) => [k.key, k]));
  for (const k of ['loofbos', 'naaldbos', 'gemengd bos']) assert.ok(hue(c.get(k)!.color) > 60 && hue(c.get(k)!.color) < 170, `${k} ${c.get(k)!.color}`);
  for (const k of ['waterloop', 'watervlakte']) assert.ok(hue(c.get(k)!.color) > 180 && hue(c.get(k)!.color) < 260, `${k} ${c.get(k)!.color}`);
});

test('as18_17: code guessed, the 17 classes, the style parses', async (t) => {
  const { file, stdout } = await scaffold(t, 'as18_17.geojson.gz');
  assert.match(stdout, /class property: code \(guessed/);
  const style = await loadStyle(file);
  assert.deepEqual(style.classes.map((c) => c.key), Array.from({ length: 17 }, (_, i) => String(i + 1)));
  assert.ok(style.baseScale > 1000, `base scale ${style.baseScale}`);
});

test('nlcd_zion: code guessed, the 8 classes, the style parses; recoded to NLCD codes, open water (11) blue and forest (42) green', async () => {
  // Read once, in this process: the file is large. The CLI path is the same scaffoldStyle (as18 above).
  const raw = await readInput(dataset('nlcd_zion.geojson.gz'));
  const plain = scaffoldStyle(raw);
  assert.equal(plain.style.classProperty, 'code');
  assert.deepEqual(parseStyle(JSON.parse(formatStyleJson(plain.style))).classes.map((c) => c.key), ['1', '2', '3', '4', '5', '6', '7', '8']);
  // nlcd_zion.geojson.gz holds NLCD's level-1 groups as 1..8 (data README); the real codes are these.
  const NLCD = ['', '11', '22', '31', '42', '52', '71', '82', '90'];
  for (const f of raw.features) f.properties.code = Number(NLCD[f.properties.code as number]);
  const s = scaffoldStyle(raw);
  const c = new Map(s.rows.map((r) => [r.key, r]));
  assert.deepEqual([...c.keys()], NLCD.slice(1));
  assert.ok(hue(c.get('11')!.color) > 180 && hue(c.get('11')!.color) < 260);
  assert.ok(hue(c.get('42')!.color) > 60 && hue(c.get('42')!.color) < 170);
  assert.ok([...c.values()].every((r) => r.source === 'NLCD'));
});

test('ssc generalize without a style says what it chose and how to write a style', async (t) => {
  const dir = tempDir(t);
  const out = path.join(dir, 'x.tgap');
  const one = await ssc.run(['generalize', dataset('bgt_otterlo_400m.geojson'), '--out', out, '--quiet']);
  assert.equal(one.code, 0, one.stderr);
  assert.match(one.stdout, /no style: one class, one colour \(the property "layer" looks like a class: --class-property layer\)/);
  assert.match(one.stdout, /no style: base scale 1:2000 \(chosen from the data/);
  assert.match(one.stdout, /ssc style bgt_otterlo_400m.geojson --out style.json and see docs\/STYLE.md/);
  const r = await ssc.run(['generalize', dataset('bgt_otterlo_400m.geojson'), '--class-property', 'layer', '--out', out, '--quiet']);
  assert.equal(r.code, 0, r.stderr);
  assert.match(r.stdout, /no style: class property "layer", 9 classes coloured by the BGT\/TOP10NL legend \(9\)/);
  const classes = (await readTgap(out)).meta.style.classes as { key: string; color: string }[];
  const water = hue(classes.find((c) => c.key === 'waterdeel')!.color);
  assert.ok(water > 180 && water < 260);
});
