// index.json and sub-index files: what the writer accepts the reader reads back, in the
// documented shape; a bad index is refused with every problem named by its place.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { encodeIndex, encodeSubIndex, expectedDigest, hashedName, IndexFormatError, isExternal, isLeaf, parseIndex, parseSubIndex, type CubeIndexJson, type InnerNode } from './cube-index.js';

const sha = (c: string): string => c.repeat(64);

function index(): CubeIndexJson {
  return {
    format: 'ssc-index',
    version: 2,
    meta: {
      name: 'Two', crs: 'EPSG:28992', extent: [0, 0, 2, 1], zMax: 2, steps: 2, phases: 8, baseScale: 1000, baseFaces: 2,
      pixelSizeMm: 0.28, scaleTable: [[0, 2], [2, 1]],
      style: { name: 'Two', background: '#F4F1E8', classes: [{ key: 'b', label: 'B', color: '#AABBCC', weight: 2, linear: true, line: { width: 0.5 } }, { key: 'a', color: '#112233', pattern: { kind: 'hatch', color: '#000000', maxScale: 2500 } }] },
      attribution: '© us', source: 'two.geojson',
      faces: { count: 4, pageSize: 4096, pages: [{ first: 0, file: 'f-0123456789abcdef.bin' }] },
      attributes: { count: 2, pageSize: 4096, pages: [{ first: 0, file: 'a-0123456789abcdef.json' }] },
    },
    root: {
      bbox: [0, 0, 0, 2, 1, 3],
      children: [
        { bbox: [0, 0, 0, 1, 1, 1], file: 'c-aaaaaaaaaaaaaaaa.bin', bytes: 172, triangles: 2 },
        { bbox: [1, 0, 0, 2, 1, 3], ref: 'i-bbbbbbbbbbbbbbbb.json', chunks: 1 },
      ],
    },
  };
}

describe('index.json', () => {
  test('reads back what was written, with the style ready to draw', () => {
    const written = index();
    const bytes = encodeIndex(written);
    const text = new TextDecoder().decode(bytes);
    assert.equal(text, JSON.stringify(written), 'written as given: key order kept, nothing added');
    const back = parseIndex(JSON.parse(text));
    assert.equal(back.meta.name, 'Two');
    assert.deepEqual(back.meta.scaleTable, [[0, 2], [2, 1]]);
    assert.deepEqual(back.meta.faces.pages, [{ first: 0, file: 'f-0123456789abcdef.bin' }]);
    assert.deepEqual(back.meta.style, {
      name: 'Two', background: '#f4f1e8',
      classes: [
        { key: 'b', label: 'B', color: '#aabbcc', weight: 2, linear: true, line: { width: 0.5 } },
        { key: 'a', label: 'a', color: '#112233', weight: 1, linear: false, pattern: { kind: 'hatch', color: '#000000', maxScale: 2500 } },
      ],
      lines: [{ classIndex: 0, by: null, values: null, width: 0.5, color: '#aabbcc', casing: null, weight: 2 }],
    });
    const [leaf, ext] = back.root.children;
    assert.ok(leaf && isLeaf(leaf) && leaf.sha256 === undefined && leaf.triangles === 2);
    assert.equal(expectedDigest(leaf), 'aaaaaaaaaaaaaaaa', "version 2: the file's SHA-256 starts with the 16 hex digits of its name");
    assert.ok(ext && isExternal(ext) && ext.ref === 'i-bbbbbbbbbbbbbbbb.json');
  });

  test('fields left out take their documented defaults', () => {
    const j = JSON.parse(JSON.stringify(index())) as { meta: Record<string, unknown> };
    delete j.meta.pixelSizeMm;
    delete j.meta.phases;
    delete j.meta.attribution;
    const back = parseIndex(j);
    assert.equal(back.meta.pixelSizeMm, 0.28);
    assert.equal(back.meta.phases, 8);
    assert.equal(back.meta.attribution, '');
  });

  test('a bad index is refused with every problem named by its place', () => {
    const j = JSON.parse(JSON.stringify(index())) as { meta: { baseScale: unknown; style: { classes: { color: string }[] } }; root: { children: Record<string, unknown>[] } };
    j.meta.baseScale = 'big';
    j.meta.style.classes[1]!.color = 'red';
    j.root.children[0]!.sha256 = 'xyz';
    j.root.children[0]!.file = '../../etc/passwd';
    assert.throws(() => parseIndex(j), (e: unknown) => {
      assert.ok(e instanceof IndexFormatError);
      for (const where of ['meta.baseScale', 'meta.style.classes.1.color', 'root.children.0.sha256', 'root.children.0.file']) {
        assert.ok(e.message.includes(where), `${where} named in: ${e.message}`);
      }
      assert.ok(e.message.startsWith('index.json: 4 problems'));
      return true;
    });
    assert.throws(() => parseIndex({ ...index(), version: 3 }), /version: must be 1 or 2 \(the versions this reader reads\)/);
    assert.throws(() => parseIndex({ ...index(), format: 'geojson' }), /format: must be "ssc-index"/);
  });

  test('a leaf is named by its SHA-256, or carries it whole as version 1 did; with neither it is refused', () => {
    const j = index();
    const leaf = j.root.children[0] as { file: string; sha256?: string };
    leaf.file = 'c-a.bin';
    assert.throws(() => parseIndex(j), /root\.children\.0: must be named <kind>-<16 hex digits of its SHA-256>\.<ext> \(or carry sha256, as version 1 did\)/);
    const lines = [{ bbox: [0, 0, 0.1, 2, 1, 3] as [number, number, number, number, number, number], file: 'l-D.bin', bytes: 120, lines: 2 }];
    assert.throws(() => parseIndex({ ...index(), lines }), /lines\.0: must be named/);
    assert.throws(() => parseIndex({ ...j, root: { ...j.root, children: [{ ...leaf, file: 'c-aaaaaaaaaaaaaaa.bin' }] } }), /must be named/, '15 hex digits are not a name by hash');
    // Version 1: any name, the whole SHA-256 beside it, which the file is checked against.
    leaf.sha256 = sha('b');
    const v1 = parseIndex({ ...j, version: 1 });
    const back = v1.root.children[0]!;
    assert.ok(isLeaf(back));
    assert.equal(expectedDigest(back), sha('b'));
    assert.equal(expectedDigest({ file: hashedName('l', sha('c'), 'bin') }), 'c'.repeat(16), 'the name the build gives a file is read back');
    assert.throws(() => expectedDigest({ file: 'c-a.bin' }), /^IndexFormatError: c-a\.bin: is not named by its SHA-256 and the index gives none$/, 'a leaf no index would hold');
  });

  test('line chunks: read back when listed, absent when not, a bad entry refused by its place', () => {
    const lines = [{ bbox: [0, 0, 0.1, 2, 1, 3] as [number, number, number, number, number, number], file: 'l-dddddddddddddddd.bin', bytes: 120, lines: 2 }];
    assert.deepEqual(parseIndex(JSON.parse(new TextDecoder().decode(encodeIndex({ ...index(), lines })))).lines, lines);
    assert.equal(parseIndex(index()).lines, undefined, 'a cube without linear classes has no lines entry');
    assert.throws(() => parseIndex({ ...index(), lines: [{ ...lines[0], file: 'http://x/l.bin' }] }), /lines\.0\.file/);
    assert.throws(() => parseIndex({ ...index(), lines: [{ ...lines[0], lines: -1 }] }), /lines\.0\.lines/);
  });

  test('floor chunks: read back when listed, absent when not, a bad entry refused by its place', () => {
    const floor = { top: 0.25, root: { bbox: [0, 0, 0, 2, 1, 0.25] as [number, number, number, number, number, number], children: [{ bbox: [0, 0, 0, 2, 1, 0.25] as [number, number, number, number, number, number], file: 'c-eeeeeeeeeeeeeeee.bin', bytes: 90, triangles: 2 }] } };
    assert.deepEqual(parseIndex(JSON.parse(new TextDecoder().decode(encodeIndex({ ...index(), floor })))).floor, floor);
    assert.equal(parseIndex(index()).floor, undefined, 'a cube of one chunk has no floor entry');
    assert.throws(() => parseIndex({ ...index(), floor: { ...floor, top: 0 } }), /floor\.top: must be > 0/);
    assert.throws(() => parseIndex({ ...index(), floor: { top: 0.25, root: { ...floor.root, children: [{ ...floor.root.children[0]!, file: '../c.bin' }] } } }), /floor\.root\.children\.0\.file/);
  });

  test('the writer refuses what the reader would refuse', () => {
    const j = index();
    j.meta.extent = [0, 0, 1] as unknown as [number, number, number, number];
    assert.throws(() => encodeIndex(j), /^IndexFormatError: index.json: meta.extent/);
  });
});

describe('sub-index file', () => {
  test('reads back what was written', () => {
    const node: InnerNode = { bbox: [1, 0, 0, 2, 1, 3], children: [{ bbox: [1, 0, 0, 2, 1, 3], file: 'c-cccccccccccccccc.bin', bytes: 9, triangles: 1 }] };
    const json = encodeSubIndex(node);
    assert.deepEqual(JSON.parse(json), { format: 'ssc-subindex', version: 2, node });
    assert.deepEqual(parseSubIndex(JSON.parse(json), 'i-b.json'), node);
    assert.throws(() => parseSubIndex({ format: 'ssc-index', node }, 'i-b.json'), /^IndexFormatError: i-b.json: format: must be "ssc-subindex"/);
  });
});
