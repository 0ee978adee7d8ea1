import assert from 'node:assert/strict';
import { test } from 'node:test';
import proj4 from 'proj4';
import { proj4Definition } from './crs-definition.js';

test('EPSG:28992 (RD New) has a definition that puts the Amersfoort origin where the EPSG says', () => {
  const def = proj4Definition('EPSG:28992');
  assert.ok(def, 'a definition');
  // The RD origin, the Onze Lieve Vrouwetoren in Amersfoort: x 155000, y 463000 is
  // 52.15517440 N, 5.38720621 E in WGS 84 (RDNAPTRANS); the definition's 7-parameter datum shift
  // is good to about a metre, 1e-5 degrees (epsg-index's was 160 m off).
  const [lng, lat] = proj4(def, 'EPSG:4326', [155000, 463000]);
  assert.ok(Math.abs(lng - 5.38720621) < 1e-5, `longitude ${lng}`);
  assert.ok(Math.abs(lat - 52.1551744) < 1e-5, `latitude ${lat}`);
});

test('a UTM zone has a definition, and names that are not EPSG codes or unknown codes have none', () => {
  assert.match(proj4Definition('EPSG:32631') ?? '', /\+proj=utm \+zone=31/);
  assert.equal(proj4Definition('EPSG:999999'), null);
  assert.equal(proj4Definition('my local grid'), null);
  assert.equal(proj4Definition(''), null);
});
