// flyTo along van Wijk and Nuij's path, on a cube of bgt_otterlo_400m cut into many small chunks:
// the flight arrives exactly where it was sent, and because its path is known at the start,
// the chunks the destination shows are requested before the view (with its prefetch margin)
// comes near them.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { boxMeets } from '../format/index-query.js';
import { growBbox } from '../client/src/geometry/view.js';
import { useTestBed } from './helpers/test-bed.js';
import { openMap } from './helpers/browser.js';
import { camera, idle, record, recorded, settle, type VarioWindow } from './helpers/vario-page.js';

describe('flyTo (bgt_otterlo_400m in small chunks)', () => {
  const bed = useTestBed(['--no-precompress', '--chunk-bytes', '16384']);

  test('a flight arrives at its target, having requested the chunks there ahead of the view', async () => {
    assert.ok(bed.contents.leaves.length >= 40, `${bed.contents.leaves.length} chunks`);
    const e = bed.contents.meta.extent;
    const at = (fx: number, fy: number): [number, number] => [e[0] + fx * (e[2] - e[0]), e[1] + fy * (e[3] - e[1])];
    const scale = bed.contents.meta.baseScale;
    // Opened at the start: only its chunks are loaded. (The test page, whose engine tells which chunks a view shows.)
    const start = at(0.15, 0.15);
    bed.page = await openMap(bed.browser, bed.server.url, { source: 'cube/', supersampling: 1, center: start.join(','), scale });
    const page = bed.page.page;
    await idle(page);
    await record(page);
    const target = at(0.85, 0.85);
    const flight = await page.evaluate(async (c) => {
      const t0 = performance.now();
      const done = await (globalThis as unknown as VarioWindow).map.flyTo({ centerProjected: c, scaleDenominator: 1000, duration: 4000 });
      return { t0, done };
    }, target);
    const arrived = flight.done;
    assert.equal(arrived, true, 'the flight completed');
    await settle(page, 'true');
    const end = await camera(page);
    assert.ok(Math.abs(end.x - target[0]) < 1e-6 && Math.abs(end.y - target[1]) < 1e-6 && Math.abs(end.scale - scale) < 1e-6, `arrived at ${end.x}, ${end.y}, 1:${end.scale}`);

    const rec = await recorded(page);
    const moves = rec.filter((r) => r.type === 'move');
    const requested = new Map<string, number>();
    const before = new Set<string>();
    for (const r of rec) {
      if (r.type !== 'dataloading') continue;
      if (r.t < flight.t0) before.add(r.file!);
      else if (!requested.has(r.file!)) requested.set(r.file!, r.t);
    }
    // The chunks the destination shows: at the base scale the floor's, or the cube's when those
    // came in along the path's lower part (they hold the floor's triangles too).
    const last = moves[moves.length - 1]!;
    const first = moves[0]!;
    const leaves = [...bed.contents.leaves, ...bed.contents.floorLeaves];
    const { visible } = await page.evaluate(() => engine.neededChunks());
    const shown = visible.filter((f) => !f.startsWith('l-')); // (line chunks, if any: not surfaces)
    const meets = (file: string, m: { bounds: [number, number, number, number]; z: number }, margin: number): boolean => {
      const leaf = leaves.find((l) => l.file === file)!;
      return boxMeets(leaf.bbox, { ground: growBbox(m.bounds, margin), zMin: m.z, zMax: m.z });
    };
    assert.ok(shown.every((f) => leaves.some((l) => l.file === f) && meets(f, last, 0)), `shown: ${shown.join(' ')}`);
    // (Chunks the start already had, or had asked for, are not fetched again.)
    const destination = shown.filter((f) => !meets(f, first, 0.25) && !before.has(f));
    assert.ok(destination.length >= 3, `${destination.length} chunks shown at the destination and not at the start`);
    for (const f of destination) {
      const t = requested.get(f);
      assert.ok(t !== undefined, `${f} was requested during the flight`);
      // The first frame whose view, with the prefetch margin, came near the chunk.
      const near = moves.find((m) => meets(f, m, 0.25))!;
      assert.ok(t < near.t, `${f} requested ${(near.t - t).toFixed(0)} ms before the view came near it`);
    }
    // And the flight went out and back in (van Wijk and Nuij), not straight across.
    const widest = Math.max(...moves.map((m) => m.scale));
    assert.ok(widest > 2 * scale, `the path zoomed out to 1:${widest.toFixed(0)}`);
  });
});
