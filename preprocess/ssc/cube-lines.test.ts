// Lines in the cube, on the 400 m cut of Otterlo: built by buildCube, read back by CubeReader
// as the map would (the index's line chunks of a view, checked and decoded), they are the lines
// of collapseLines + pruneLines of the lines the style draws: as many per class, the same
// coordinates to the nearest step of the chunk's grid, z ranges at phase 0 of the step born and the step pruned, and exactly
// the lines whose range holds a z are alive there. Each line's rule is the one styles/bgt.json
// gives its input feature's `klasse` (read from the GeoJSON itself). A style without linear
// classes gives a cube without a lines entry.
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import test from 'node:test';
import { EVERYWHERE } from '../../format/index-query.js';
import { lineOfChunk } from '../../format/line-chunk.js';
import { lineAliveAt, linePathsAtZ, type LineRecord } from '../../format/line-record.js';
import type { LineRule } from '../../format/line-style.js';
import type { Tgap } from '../../format/tgap-model.js';
import { dataset, styleFile } from '../../testing/paths.js';
import { tempDir } from '../../testing/temp-dir.js';
import { collapseLines } from '../lines/collapse-lines.js';
import { keepLines } from '../lines/keep-lines.js';
import { pruneLines, type PrunedLine } from '../lines/prune-lines.js';
import { linePathsAt, simplifyLines } from '../lines/simplify-lines.js';
import { generalizeFile } from '../pipeline.js';
import { loadStyle } from '../style.js';
import { buildCube, LINE_CHUNK_FACTOR } from './build-cube.js';
import { inspectCube } from './inspect-cube.js';
import { CubeReader } from './read-cube.js';

/** Every line of the cube as read back, with the origin and the position step of its chunk. */
async function readAll(reader: CubeReader): Promise<{ line: LineRecord; originX: number; originY: number; step: number }[]> {
  const out: { line: LineRecord; originX: number; originY: number; step: number }[] = [];
  for (const leaf of reader.lineChunks(EVERYWHERE)) {
    const c = await reader.lineChunk(leaf);
    assert.equal(c.lineCount, leaf.lines, `${leaf.file}: lines as the index says`);
    const step = 2 ** c.gridExponent;
    for (let i = 0; i < c.lineCount; i++) out.push({ line: lineOfChunk(c, i), originX: c.originX, originY: c.originY, step });
  }
  return out;
}

// Not by position: on the cube's grid (7.8 mm here) a first point may round to another whole unit.
const key = (classIndex: number, feature: number): string => `${classIndex}|${feature}`;

test('bgt_otterlo_400m: the cube\'s lines read back are the collapsed and pruned lines, alive exactly in their z range', async (t) => {
  const styleName = styleFile('bgt.json');
  const { tgap } = await generalizeFile(dataset('bgt_otterlo_400m.geojson'), { style: styleName });
  const style = await loadStyle(styleName);
  // The input's own attributes, by feature index (the GeoJSON's order).
  const input = JSON.parse(await readFile(dataset('bgt_otterlo_400m.geojson'), 'utf8')) as { features: { properties: { layer: string; klasse: string } }[] };
  const klasseOf = (feature: number): string => input.features[feature]!.properties.klasse;

  const steps = tgap.meta.steps;
  // The lines the style draws: of a class with `line`, whose rule is wider than 0, weighed by it.
  const collapsed = collapseLines(tgap, style).lines;
  const ruleOf = collapsed.map((l) => expectedRule(style.lineRules, l.classIndex, klasseOf(l.feature)));
  const drawn = ruleOf.map((r) => r >= 0 && style.lineRules[r]!.width > 0);
  const kept = keepLines(collapsed, drawn);
  const keptRules = ruleOf.filter((_, i) => drawn[i]);
  const pruned = pruneLines(kept, tgap, style, { weights: keptRules.map((r) => style.lineRules[r]!.weight), groups: keptRules }).lines;
  // Lines pruned the step they are born are never on the map and not written.
  const shown = pruned.filter((l) => l.step < l.prunedStep);
  assert.ok(shown.length > 50 && shown.length < pruned.length, `${shown.length} of ${pruned.length} lines shown`);
  const simplified = new Map(simplifyLines(shown, tgap).lines.map((l, i) => [shown[i]!, l]));

  const dir = path.join(tempDir(t), 'cube');
  // Chunks small enough that the surfaces take many (and the lines several, at a quarter of it).
  const report = await buildCube(tgap, dir, { precompress: false, chunkBytes: 12 * 1024 });
  assert.equal(report.lines, shown.length);
  const reader = await CubeReader.open(dir);
  const read = await readAll(reader);
  // Planned at a quarter of the chunk size (a line lives over much of the z range, so a view
  // takes nearly every line chunk over its ground): at most as many chunks as that target gives
  // for the lines' records as the reader expands them (docs/FORMAT.md; fewer when a line is
  // larger than a chunk), and at least twice as many as the surface chunks' size would give.
  const recordBytes = read.reduce((n, { line }) => n + 20 + 4 * line.paths.length + 12 * line.paths.reduce((m, p) => m + p.length / 2, 0), 0);
  const lineChunks = report.lineChunkBytes.length;
  assert.ok(lineChunks <= Math.round(recordBytes / (LINE_CHUNK_FACTOR * 12 * 1024)), `${lineChunks} line chunks for ${recordBytes} bytes of lines`);
  assert.ok(lineChunks >= 2 * Math.round(recordBytes / (12 * 1024)), `${lineChunks} line chunks: smaller than the surface chunks`);

  // As many lines per class.
  const perClass = (classes: number[]): number[] => style.classes.map((_, ci) => classes.filter((c) => c === ci).length);
  assert.deepEqual(perClass(read.map((r) => r.line.classIndex)), perClass(shown.map((l) => l.classIndex)));

  // Each line read back is one line of pruneLines' (by class and feature), with its coordinates to the
  // nearest step of its chunk's grid (docs/FORMAT.md) and its z range, less the vertices that
  // simplification takes by the step the line is born (never drawn).
  const expected = new Map<string, PrunedLine[]>();
  for (const l of shown) {
    const k = key(l.classIndex, l.feature);
    expected.set(k, [...(expected.get(k) ?? []), l]);
  }
  const phase0 = (s: number): number => Math.fround(s - 1 + 1 / 9);
  const readOf = new Map<PrunedLine, LineRecord>();
  const onGrid = (v: number, origin: number, step: number): number => origin + Math.round((v - origin) / step) * step;
  for (const { line, originX, originY, step } of read) {
    const candidates = expected.get(key(line.classIndex, line.feature)) ?? [];
    const drawn = (l: PrunedLine, k: number): number[] => {
      const ends = simplified.get(l)!.vertexEnd[k]!;
      return [...l.paths[k]!].filter((_, i) => ends[i >> 1]! > l.step);
    };
    const same = (l: PrunedLine): boolean =>
      l.paths.length === line.paths.length &&
      l.paths.every((_, k) => drawn(l, k).length === line.paths[k]!.length && drawn(l, k).every((v, i) => line.paths[k]![i] === onGrid(v, i % 2 === 0 ? originX : originY, step)));
    const match = candidates.find((l) => same(l) && !readOf.has(l));
    assert.ok(match, `a line of class ${line.classIndex}, feature #${line.feature} read back matches no line of pruneLines on its grid`);
    readOf.set(match, line);
    assert.equal(line.zStart, phase0(match.step), 'zStart: phase 0 of the step the line is born');
    assert.equal(line.zEnd, match.prunedStep > steps ? steps + 1 : phase0(match.prunedStep), 'zEnd: phase 0 of the step pruned, or the top');
  }
  assert.equal(readOf.size, shown.length);
  const stored = read.reduce((n, r) => n + r.line.leaveZ.reduce((m, e) => m + e.length, 0), 0);
  const all = shown.reduce((n, l) => n + l.paths.reduce((m, p) => m + p.length / 2, 0), 0);
  t.diagnostic(`${stored} of ${all} line vertices stored`);
  assert.ok(stored < all, 'vertices gone by a line\'s birth are left out');
  for (const { line } of read) assert.ok(line.leaveZ.every((e) => e.every((z) => z > line.zStart)), 'every vertex stored is drawn at the line\'s birth');

  // Each line read back carries the rule of its feature's klasse: cycle paths the cycle-path rule,
  // main roads the main-road rule, and so on; classes and values without a drawn line have none.
  const byKlasse = new Map<string, Set<number>>();
  for (const { line } of read) {
    const p = input.features[line.feature]!.properties;
    assert.equal(style.classes[line.classIndex]!.key, p.layer, `feature #${line.feature}: the line's class is its layer`);
    const k = `${p.layer}/${p.klasse}`;
    byKlasse.set(k, (byKlasse.get(k) ?? new Set()).add(line.rule));
  }
  const rule = (values: string[] | null, layer = 'wegdeel'): number =>
    style.lineRules.findIndex((r) => style.classes[r.classIndex]!.key === layer && JSON.stringify(r.values) === JSON.stringify(values));
  const want: Record<string, number> = {
    'wegdeel/fietspad': rule(['fietspad']),
    'wegdeel/rijbaan regionale weg': rule(['rijbaan regionale weg']),
    'wegdeel/rijbaan lokale weg': rule(['rijbaan lokale weg']),
    'wegdeel/voetpad': rule(['voetpad', 'voetpad op trap', 'voetgangersgebied']),
    'wegdeel/voetpad op trap': rule(['voetpad', 'voetpad op trap', 'voetgangersgebied']),
    'wegdeel/voetgangersgebied': rule(['voetpad', 'voetpad op trap', 'voetgangersgebied']),
    'wegdeel/inrit': rule(['inrit', 'parkeervlak']),
    'wegdeel/parkeervlak': rule(['inrit', 'parkeervlak']),
    'waterdeel/waterloop': rule(['waterloop'], 'waterdeel'),
    'waterdeel/greppel, droge sloot': rule(['greppel, droge sloot'], 'waterdeel'),
    'scheiding/muur': rule(null, 'scheiding'),
  };
  assert.deepEqual(style.lineRules[want['wegdeel/fietspad']!]!.color, '#d06a5a', 'the cycle-path rule');
  for (const [k, r] of Object.entries(want)) {
    if (byKlasse.has(k)) assert.deepEqual([...byKlasse.get(k)!], [r], `${k}: every line has rule ${r}`);
  }
  for (const k of ['wegdeel/fietspad', 'wegdeel/rijbaan regionale weg', 'wegdeel/rijbaan lokale weg', 'wegdeel/voetpad', 'waterdeel/waterloop']) assert.ok(byKlasse.has(k), `lines of ${k} are stored`);
  assert.deepEqual([...byKlasse.keys()].filter((k) => !(k in want)), [], 'no lines of verges, banks or classes without a drawn line');

  // At states and between them, in the whole extent and in a corner: the lines of the chunks the
  // index gives for the view that are alive there are exactly those whose state range holds it,
  // each with its simplified vertices of that state.
  const [x0, y0, x1, y1] = tgap.meta.extent;
  const views: [number, number, number, number][] = [[x0, y0, x1, y1], [x0, y0, (x0 + x1) / 2, (y0 + y1) / 2]];
  const changes = [...new Set(shown.flatMap((l) => [l.step, l.prunedStep]))].filter((s) => s <= steps).sort((a, b) => a - b);
  const states = [0, ...Array.from({ length: 6 }, (_, k) => changes[Math.floor((k * (changes.length - 1)) / 5)]!), steps];
  for (const ground of views) {
    for (const s of states) {
      for (const z of s < steps ? [s, s + 0.5] : [s]) {
        const got: string[] = [];
        for (const leaf of reader.lineChunks({ ground, zMin: z, zMax: z })) {
          const c = await reader.lineChunk(leaf);
          for (let i = 0; i < c.lineCount; i++) {
            const l = lineOfChunk(c, i);
            if (lineAliveAt(l, z) && meets(l, ground)) got.push(key(l.classIndex, l.feature));
          }
        }
        // Between states s and s + 1 the lines of state s + 1 are shown: phase 0 of step s + 1 is at s + 1/9.
        const state = z === s ? s : s + 1;
        const want = shown.filter((l) => l.step <= state && state < l.prunedStep && meets(readOf.get(l)!, ground));
        assert.deepEqual(got.sort(), want.map((l) => key(l.classIndex, l.feature)).sort(), `lines alive at z ${z} in ${ground.join(',')}`);
        if (z === s) {
          for (const l of want) {
            const atZ = linePathsAtZ(readOf.get(l)!, z).map((p) => p.length / 2);
            assert.deepEqual(atZ, linePathsAt(simplified.get(l)!, s).map((p) => p.length / 2), `vertices of a line at state ${s}`);
          }
        }
      }
    }
  }
});

/** The rule styles/bgt.json gives a line of class `classIndex` with this klasse: the rule listing it, else the class's default. */
function expectedRule(rules: readonly LineRule[], classIndex: number, klasse: string): number {
  const listed = rules.findIndex((r) => r.classIndex === classIndex && r.values?.includes(klasse));
  return listed >= 0 ? listed : rules.findIndex((r) => r.classIndex === classIndex && r.values === null);
}

/** Whether a line's ground box meets a view's. */
function meets(l: LineRecord, g: [number, number, number, number]): boolean {
  const xs = l.paths.flatMap((p) => [...p].filter((_, i) => i % 2 === 0)), ys = l.paths.flatMap((p) => [...p].filter((_, i) => i % 2 === 1));
  return Math.min(...xs) <= g[2] && Math.max(...xs) >= g[0] && Math.min(...ys) <= g[3] && Math.max(...ys) >= g[1];
}

test('a style without linear classes gives a cube without lines; the classic build writes them too', async (t) => {
  const styleName = styleFile('bgt.json');
  const { tgap } = await generalizeFile(dataset('bgt_otterlo_400m.geojson'), { style: styleName });
  const style = tgap.meta.style as { classes: Record<string, unknown>[] };
  const noLines: Tgap = { ...tgap, meta: { ...tgap.meta, style: { ...style, classes: style.classes.map(({ line: _, network: _n, ...c }) => ({ ...c, linear: false })) } } };
  const dir = tempDir(t);
  await buildCube(noLines, path.join(dir, 'areas'), { precompress: false, smooth: false });
  const areas = await CubeReader.open(path.join(dir, 'areas'));
  assert.equal(areas.index.lines, undefined, 'no lines entry');
  assert.equal((await inspectCube(path.join(dir, 'areas'))).lines, null);
  assert.deepEqual(areas.lineChunks({ ground: tgap.meta.extent, zMin: 0, zMax: 0 }), []);

  const report = await buildCube(tgap, path.join(dir, 'classic'), { precompress: false, smooth: false });
  const classic = await CubeReader.open(path.join(dir, 'classic'));
  assert.ok(report.lines > 50);
  assert.equal((await readAll(classic)).length, report.lines, 'the classic cube holds the lines');
  const inspected = await inspectCube(path.join(dir, 'classic'));
  assert.deepEqual(inspected.lines, { chunks: report.lineChunkBytes.length, lines: report.lines, bytes: report.lineChunkBytes.reduce((a, b) => a + b, 0) });
  assert.equal(inspected.views[0]!.lines, 0, 'no lines at the base scale: every linear face is still an area');
  assert.ok(inspected.views.slice(1).every((v) => v.lines > 0), 'lines in a view at every scale above the base');
});
