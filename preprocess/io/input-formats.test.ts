// GeoPackage, Shapefile and FlatGeobuf input: the fixtures in testdata/ were made from
// bgt_otterlo_400m.geojson by GDAL's ogr2ogr (testdata/README.md), so the same map must come out
// of each as out of the GeoJSON; and broken or unknown files must be refused in one clear line.
import assert from 'node:assert/strict';
import { copyFileSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { dataset, styleFile } from '../../testing/paths.js';
import { startSscSession } from '../../testing/run-ssc.js';
import { tempDir } from '../../testing/temp-dir.js';
import { encodeTgap } from '../../format/tgap.js';
import type { Tgap } from '../../format/tgap-model.js';
import { generalizeFile } from '../pipeline.js';
import { readInput } from './read-input.js';
import { InputError } from './errors.js';

const testdata = path.join(path.dirname(fileURLToPath(import.meta.url)), 'testdata');
const geojsonFile = dataset('bgt_otterlo_400m.geojson');
const shapefileParts = ['.shp', '.shx', '.dbf', '.prj', '.cpg'];

interface GeoJsonFeature { properties: Record<string, unknown>; geometry: { type: string; coordinates: unknown } }
const geojson = JSON.parse(readFileSync(geojsonFile, 'utf8')) as { features: GeoJsonFeature[] };

/** The tGAP's bytes with the source file's name set aside: it is the one thing that may differ. */
function bytesOf(tgap: Tgap): Buffer {
  return Buffer.from(encodeTgap({ ...tgap, meta: { ...tgap.meta, source: 'input' } }));
}

let reference: Promise<Tgap> | null = null;
function referenceTgap(): Promise<Tgap> {
  reference ??= generalizeFile(geojsonFile, { style: styleFile('bgt.json') }).then((r) => r.tgap);
  return reference;
}

for (const [name, file] of [['GeoPackage', 'otterlo.gpkg'], ['FlatGeobuf', 'otterlo.fgb']] as const) {
  test(`a ${name} made from bgt_otterlo_400m by ogr2ogr gives the same tGAP as the GeoJSON`, async () => {
    const { tgap } = await generalizeFile(path.join(testdata, file), { style: styleFile('bgt.json') });
    assert.equal(tgap.meta.crs, 'EPSG:28992', 'the CRS read from the file');
    assert.equal(tgap.meta.source, file);
    assert.ok(bytesOf(tgap).equals(bytesOf(await referenceTgap())), 'same tGAP bytes');
  });
}

test('a Shapefile (.shp, .shx, .dbf, .prj, .cpg) made by ogr2ogr gives the same tGAP as the GeoJSON, blank texts aside', async () => {
  const { tgap } = await generalizeFile(path.join(testdata, 'otterlo.shp'), { style: styleFile('bgt.json') });
  // The .prj is ESRI WKT without an EPSG code ("RD_New"): matched by its parameters.
  assert.equal(tgap.meta.crs, 'EPSG:28992');
  // A .dbf cannot tell an empty text from a missing one; GDAL reads both as null, and so do we.
  const ref = await referenceTgap();
  const blanks = geojson.features.filter((f) => Object.values(f.properties).includes('')).length;
  assert.ok(blanks > 0, 'the GeoJSON has empty texts, so this case is tested');
  const expected = (ref.meta.attributes).map((a) =>
    Object.fromEntries(Object.entries(a).map(([k, v]) => [k, v === '' ? null : v])));
  assert.ok(bytesOf(tgap).equals(bytesOf({ ...ref, meta: { ...ref.meta, attributes: expected } })), 'same tGAP bytes');
});

test('the .dbf attributes come in record order with the UTF-8 of the .cpg', async () => {
  const raw = await readInput(path.join(testdata, 'otterlo.shp'));
  assert.equal(raw.features.length, geojson.features.length);
  raw.features.forEach((f, i) => {
    const want = geojson.features[i]!.properties;
    for (const [k, v] of Object.entries(want)) assert.equal(f.properties[k], v === '' ? null : v, `feature ${i} ${k}`);
  });
});

test('a GeoPackage with several layers: --layer picks one; none or a wrong name is refused, listing the layers', async () => {
  const file = path.join(testdata, 'two-layers.gpkg');
  await assert.rejects(readInput(file), (err: Error) => {
    assert.ok(err instanceof InputError);
    assert.match(err.message, /two-layers\.gpkg: GeoPackage has 2 feature layers; pick one with --layer: "buildings", "water"$/);
    return true;
  });
  await assert.rejects(readInput(file, { layer: 'roads' }), /two-layers\.gpkg: GeoPackage has no feature layer "roads"; its layers are "buildings", "water"$/);
  const water = await readInput(file, { layer: 'water' });
  const want = geojson.features.filter((f) => f.properties.layer === 'waterdeel');
  assert.equal(water.features.length, want.length);
  water.features.forEach((f, i) => {
    assert.equal(f.properties.lokaalid, want[i]!.properties.lokaalid, `feature ${i} in file order`);
    const ring = (want[i]!.geometry.type === 'Polygon' ? want[i]!.geometry.coordinates : (want[i]!.geometry.coordinates as unknown[])[0]) as number[][][];
    assert.deepEqual([f.polygons[0]![0]![0], f.polygons[0]![0]![1]], ring[0]![0], `feature ${i} first point`);
  });
});

test('an unknown format, a truncated GeoPackage, Shapefile or FlatGeobuf: one line naming the file and the format', async (t) => {
  const dir = tempDir(t);
  const unknown = path.join(dir, 'landcover.dat');
  writeFileSync(unknown, Buffer.from([0x00, 0x01, 0x02, 0x03, 0xff, 0xfe, 0x53, 0x51, 0x00, 0x0a, 0x00]));
  const half = (name: string): string => {
    const bytes = readFileSync(path.join(testdata, name));
    const out = path.join(dir, name);
    writeFileSync(out, bytes.subarray(0, bytes.length >> 1));
    return out;
  };
  for (const ext of shapefileParts.filter((e) => e !== '.shp')) copyFileSync(path.join(testdata, `otterlo${ext}`), path.join(dir, `otterlo${ext}`));
  const cases: [string, RegExp][] = [
    [unknown, /^ssc generalize: .*landcover\.dat: is in a format ssc does not read; it reads GeoJSON .*TopoJSON .*GeoPackage .*Shapefile .*FlatGeobuf/],
    [half('otterlo.gpkg'), /^ssc generalize: .*otterlo\.gpkg: is not a valid GeoPackage \(truncated or corrupt\?\): database disk image is malformed$/],
    [half('otterlo.shp'), /^ssc generalize: .*otterlo\.shp: is not a valid Shapefile \(truncated or corrupt\?\): its header gives a length of 192836 bytes, the file has 96418$/],
    [half('otterlo.fgb'), /^ssc generalize: .*otterlo\.fgb: is not a valid FlatGeobuf \(truncated or corrupt\?\): it breaks off after \d+ of the 475 features its header announces$/],
  ];
  const ssc = startSscSession();
  t.after(() => ssc.close());
  for (const [input, want] of cases) {
    const r = await ssc.run(['generalize', input, '--out', path.join(dir, 'o.tgap'), '--quiet']);
    assert.equal(r.code, 1, `${input}: exit code`);
    assert.match(r.stderr.trimEnd(), want);
    assert.equal(r.stderr.trimEnd().split('\n').length, 1, `${input}: one line, no stack trace: ${r.stderr}`);
    // eslint-disable-next-line no-control-regex
    assert.doesNotMatch(r.stderr.trimEnd(), /[\u0000-\u0008\u000b-\u001f\ufffd]/, `${input}: no raw bytes`);
  }
});

test('a Shapefile whose .dbf is cut short is refused, not read with features missing', async (t) => {
  const dir = tempDir(t);
  for (const ext of shapefileParts) copyFileSync(path.join(testdata, `otterlo${ext}`), path.join(dir, `otterlo${ext}`));
  const dbf = readFileSync(path.join(dir, 'otterlo.dbf'));
  writeFileSync(path.join(dir, 'otterlo.dbf'), dbf.subarray(0, dbf.length >> 1));
  await assert.rejects(readInput(path.join(dir, 'otterlo.shp')), /otterlo\.shp: its \.dbf is truncated or corrupt: it has \d+ bytes, too few for the 475 records its header announces$/);
});
