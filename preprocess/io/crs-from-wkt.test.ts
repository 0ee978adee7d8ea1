import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { epsgFromWkt, wktName } from './crs-from-wkt.js';

const prj = readFileSync(path.join(path.dirname(fileURLToPath(import.meta.url)), 'testdata/otterlo.prj'), 'utf8');
const rdPoints: [number, number][] = [[181082, 456831], [181482, 457231], [155000, 463000]];
const utmPoints: [number, number][] = [[450000, 5750000], [550000, 5850000]];

const esriUtm = (geog: string, spheroid: string): string =>
  `PROJCS["UTM_31N",GEOGCS["${geog}",DATUM["D_${geog}",SPHEROID[${spheroid}]],PRIMEM["Greenwich",0.0],UNIT["Degree",0.0174532925199433]],PROJECTION["Transverse_Mercator"],PARAMETER["False_Easting",500000.0],PARAMETER["False_Northing",0.0],PARAMETER["Central_Meridian",3.0],PARAMETER["Scale_Factor",0.9996],PARAMETER["Latitude_Of_Origin",0.0],UNIT["Meter",1.0]]`;

test('an ESRI .prj without EPSG code (as ogr2ogr writes RD New) is matched to its EPSG code by its parameters', () => {
  assert.equal(wktName(prj), 'RD_New');
  assert.equal(epsgFromWkt(prj, rdPoints), 'EPSG:28992');
  // The same projection 1 km further east is another CRS, which EPSG does not have.
  assert.equal(epsgFromWkt(prj.replace('"False_Easting",155000.0', '"False_Easting",156000.0'), rdPoints), null);
});

test('UTM zone 31N on WGS 84 and on ETRS89 (GRS 80, 0.1 mm apart in the semi-minor axis) are told apart', () => {
  assert.equal(epsgFromWkt(esriUtm('WGS_1984', '"WGS_1984",6378137.0,298.257223563'), utmPoints), 'EPSG:32631');
  // EPSG has ETRS89 / UTM 31N twice: 25831 and its deprecated twin 3043 (ETRS-TM31), one definition.
  const etrs = epsgFromWkt(esriUtm('ETRS_1989', '"GRS_1980",6378137.0,298.257222101'), utmPoints);
  assert.ok(etrs === 'EPSG:25831' || etrs === 'EPSG:3043', `got ${etrs}`);
});

test('a WKT with its own EPSG identifier gives that code; geographic WGS 84 gives EPSG:4326', () => {
  const wkt1 = 'PROJCS["WGS 84 / Pseudo-Mercator",GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,298.257223563]],PRIMEM["Greenwich",0],UNIT["degree",0.0174532925199433]],PROJECTION["Mercator_1SP"],PARAMETER["central_meridian",0],PARAMETER["scale_factor",1],PARAMETER["false_easting",0],PARAMETER["false_northing",0],UNIT["metre",1],AUTHORITY["EPSG","3857"]]';
  assert.equal(epsgFromWkt(wkt1, []), 'EPSG:3857');
  assert.equal(epsgFromWkt('GEOGCS["GCS_WGS_1984",DATUM["D_WGS_1984",SPHEROID["WGS_1984",6378137.0,298.257223563]],PRIMEM["Greenwich",0.0],UNIT["Degree",0.0174532925199433]]', [[5.8, 52.1]]), 'EPSG:4326');
});
