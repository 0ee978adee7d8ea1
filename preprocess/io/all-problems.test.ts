// A refused input names all its problems in one run, grouped by kind, and --problems writes
// their places as GeoJSON points; nothing else is written.
import test, { after, before } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { startSscSession, type SscSession } from '../../testing/run-ssc.js';
import { at, collection, feature, OX, OY, polygon, rect, writeCase, type Json } from '../../testing/topology-cases.js';

let ssc: SscSession;
before(() => {
  ssc = startSscSession();
});
after(() => ssc.close());

// A row of five squares 10 wide; three of them have a problem each:
//  #1 "nul": class property null           named at its first point (10, 0)
//  #2 "bow": a bow-tie (20,0) (30,10) (30,0) (20,10)... made lopsided, crossing at (25 + 5/3, 5)
//  #4 "far": a coordinate of 1e300         named at the point before it (40, 0)
const BOW: [number, number][] = [[20, 0], [30, 12], [30, -2], [20, 10]];
function threeProblems(): Json {
  const doc = collection([
    feature('ok0', polygon(rect(0, 0, 10, 10))),
    feature('nul', polygon(rect(10, 0, 20, 10))),
    feature('bow', polygon(BOW)),
    feature('ok3', polygon(rect(30, 0, 40, 10))),
    feature('far', { type: 'Polygon', coordinates: [[at(40, 0), [1e300, OY], at(50, 10), at(40, 10), at(40, 0)]] }),
  ]);
  ((doc as { features: { properties: Record<string, Json> }[] }).features[1]!.properties).cls = null;
  return doc;
}

// (20,0)-(30,12) and (30,-2)-(20,10) cross where 1.2 (x - 20) = 10 - 1.2 (x - 20): x = 20 + 25/6, y = 5.
const BOW_CROSSING: [number, number] = [OX + 20 + 25 / 6, OY + 5];

test('three problems in three features are named in one run, and their places written', async (t) => {
  const c = writeCase(t, 'three.geojson', threeProblems());
  const problems = path.join(c.dir, 'problems.geojson');
  const r = await ssc.run(['generalize', c.input, '--style', c.style, '--out', path.join(c.dir, 'out.tgap'), '--quiet', '--problems', problems]);
  assert.equal(r.code, 1);
  assert.equal(r.stdout, '');
  const lines = r.stderr.trimEnd().split('\n');
  assert.equal(lines[0], 'ssc generalize: three.geojson: 3 problems; the input is refused:');
  // Grouped by kind, each with its feature (index and id) and place.
  assert.deepEqual(lines.slice(1, 7), [
    '  coordinate out of range (1):',
    '    feature #4 (id "far"), at (1040, 2000): has a coordinate out of range: [1e+300, 2000] (no CRS reaches beyond ±1000000000 units)',
    '  class (1):',
    '    feature #1 (id "nul"), at (1010, 2000): has the class property "cls" set to null',
    '  self-intersection (1):',
    `    feature #2 (id "bow"), at (${Math.round(BOW_CROSSING[0] * 1000) / 1000}, 2005): is self-intersecting: its outer ring crosses itself`,
  ]);
  assert.equal(lines[7], `(the places of the problems are in ${problems})`);
  assert.equal(lines.length, 8);
  // Only the problems file is new in the folder.
  assert.deepEqual(readdirSync(c.dir).sort(), [...c.files, 'problems.geojson'].sort());
  const gj = JSON.parse(readFileSync(problems, 'utf8')) as {
    crs: { properties: { name: string } };
    features: { properties: { kind: string; feature: number; id: string }; geometry: { type: string; coordinates: [number, number] } }[];
  };
  assert.equal(gj.crs.properties.name, 'urn:ogc:def:crs:EPSG::28992');
  const byId = Object.fromEntries(gj.features.map((f) => [f.properties.id, f]));
  assert.deepEqual(Object.keys(byId).sort(), ['bow', 'far', 'nul']);
  for (const f of gj.features) assert.equal(f.geometry.type, 'Point');
  assert.deepEqual(byId.nul!.geometry.coordinates, at(10, 0));
  assert.deepEqual(byId.far!.geometry.coordinates, at(40, 0));
  const [bx, by] = byId.bow!.geometry.coordinates;
  assert.ok(Math.abs(bx - BOW_CROSSING[0]) < 1e-9 && Math.abs(by - BOW_CROSSING[1]) < 1e-9, `bow-tie named at ${bx}, ${by}`);
  assert.deepEqual(gj.features.map((f) => [f.properties.feature, f.properties.kind]).sort(), [[1, 'class'], [2, 'self-intersection'], [4, 'coordinate out of range']]);
});

test('--max-problems stops at that many, and says so', async (t) => {
  const c = writeCase(t, 'three.geojson', threeProblems());
  const r = await ssc.run(['generalize', c.input, '--style', c.style, '--out', path.join(c.dir, 'out.tgap'), '--quiet', '--max-problems', '2']);
  assert.equal(r.code, 1);
  const lines = r.stderr.trimEnd().split('\n');
  assert.equal(lines[0], 'ssc generalize: three.geojson: the first 2 problems; the input is refused (--max-problems raises the limit of 2):');
  assert.equal(lines.filter((l) => l.startsWith('    feature #')).length, 2);
  assert.match(r.stderr, /--problems <file\.geojson> writes their places/);
  assert.deepEqual(readdirSync(c.dir).sort(), c.files, 'nothing written');
});

test('problems of the partition are gathered too: two gaps in one run', async (t) => {
  // Two frames side by side, each around a hole no feature fills.
  const frame = (x: number): Json => polygon(rect(x, 0, x + 30, 30), [...rect(x + 10, 10, x + 20, 20)].reverse());
  const c = writeCase(t, 'gaps.geojson', collection([feature('frame1', frame(0)), feature('frame2', frame(30))]));
  const r = await ssc.run(['generalize', c.input, '--style', c.style, '--out', path.join(c.dir, 'out.tgap'), '--quiet']);
  assert.equal(r.code, 1);
  const lines = r.stderr.trimEnd().split('\n');
  assert.equal(lines[0], 'ssc generalize: gaps.geojson: 2 problems; the input is refused:');
  assert.equal(lines[1], '  gap (2):');
  assert.match(lines[2]!, /^ {4}feature #0 \(id "frame1"\), at \(10[12]\d, 20[12]\d\): borders a gap inside the domain \(an area no feature covers, 100\.0 square units, bounding box 1010, 2010, 1020, 2020\)/);
  assert.match(lines[3]!, /^ {4}feature #1 \(id "frame2"\), at \(10[45]\d, 20[12]\d\): borders a gap inside the domain \(an area no feature covers, 100\.0 square units, bounding box 1040, 2010, 1050, 2020\)/);
  assert.deepEqual(readdirSync(c.dir).sort(), c.files, 'nothing written');
});
