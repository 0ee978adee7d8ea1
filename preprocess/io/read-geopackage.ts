// Reads one feature layer of a GeoPackage (an SQLite file) as GeoJSON features, in the order of
// their feature ids, with the layer's CRS from gpkg_spatial_ref_sys. SQLite is sql.js (SQLite
// compiled to WebAssembly: no native build); the geometries are WKB read by wkx.
import initSqlJs, { type Database, type SqlValue } from 'sql.js';
import wkx from 'wkx';
import { InputError } from './errors.js';
import { brokenFileError, type FeatureDocument } from './input-format.js';

interface Layer {
  table: string;
  geometryColumn: string;
  srsId: number;
}

export async function readGeopackage(buf: Buffer, file: string, layerName: string | undefined): Promise<FeatureDocument> {
  const SQL = await initSqlJs();
  let db: Database | undefined;
  try {
    db = new SQL.Database(buf);
    const layer = pickLayer(featureLayers(db, file), layerName, file);
    return { type: 'FeatureCollection', crs: layerCrs(db, layer.srsId), features: readFeatures(db, layer, file) };
  } catch (err) {
    throw brokenFileError(file, 'geopackage', err);
  } finally {
    db?.close();
  }
}

function featureLayers(db: Database, file: string): Layer[] {
  const hasContents = rows(db, "SELECT name FROM sqlite_master WHERE type = 'table' AND name IN ('gpkg_contents', 'gpkg_geometry_columns')");
  if (hasContents.length < 2) throw new InputError('is an SQLite database but not a GeoPackage (it has no gpkg_contents and gpkg_geometry_columns tables)', { file });
  // gpkg_contents in its own order, as GDAL and QGIS list the layers.
  return rows(
    db,
    `SELECT c.table_name, g.column_name, g.srs_id FROM gpkg_contents c
       JOIN gpkg_geometry_columns g ON g.table_name = c.table_name
      WHERE c.data_type = 'features' ORDER BY c.rowid`,
  ).map(([table, column, srs]) => ({ table: String(table), geometryColumn: String(column), srsId: Number(srs) }));
}

function pickLayer(layers: Layer[], name: string | undefined, file: string): Layer {
  const names = layers.map((l) => JSON.stringify(l.table)).join(', ');
  if (layers.length === 0) throw new InputError('is a GeoPackage without feature layers', { file });
  if (name !== undefined) {
    const found = layers.find((l) => l.table === name);
    if (!found) throw new InputError(`GeoPackage has no feature layer ${JSON.stringify(name)}; its layers are ${names}`, { file });
    return found;
  }
  if (layers.length > 1) throw new InputError(`GeoPackage has ${layers.length} feature layers; pick one with --layer: ${names}`, { file });
  return layers[0]!;
}

/** The layer's CRS as a GeoJSON-style member: an EPSG name, a WKT definition, or null (undefined). */
function layerCrs(db: Database, srsId: number): unknown {
  const [row] = rows(db, 'SELECT organization, organization_coordsys_id, definition FROM gpkg_spatial_ref_sys WHERE srs_id = ?', [srsId]);
  if (!row) return null;
  const [org, code, definition] = row;
  if (typeof org === 'string' && org.toUpperCase() === 'EPSG' && typeof code === 'number' && code > 0) {
    return { type: 'name', properties: { name: `EPSG:${code}` } };
  }
  // srs_id -1 and 0 are the undefined Cartesian and geographic systems, whose definition is "undefined".
  if (typeof definition === 'string' && definition.trim() !== '' && definition.trim().toLowerCase() !== 'undefined') {
    return { type: 'wkt', properties: { wkt: definition } };
  }
  return null;
}

function readFeatures(db: Database, layer: Layer, file: string): unknown[] {
  const columns = rows(db, `PRAGMA table_info(${quote(layer.table)})`).map(([, name, type, , , pk]) => ({
    name: String(name),
    type: String(type).toUpperCase(),
    pk: Number(pk) > 0,
  }));
  const pk = columns.find((c) => c.pk);
  const fields = columns.filter((c) => !c.pk && c.name !== layer.geometryColumn);
  const select = [pk ? quote(pk.name) : 'rowid', quote(layer.geometryColumn), ...fields.map((c) => quote(c.name))].join(', ');
  const features: unknown[] = [];
  const stmt = db.prepare(`SELECT ${select} FROM ${quote(layer.table)} ORDER BY ${pk ? quote(pk.name) : 'rowid'}`);
  try {
    while (stmt.step()) {
      const [fid, blob, ...values] = stmt.get();
      const properties: Record<string, unknown> = {};
      fields.forEach((c, i) => {
        properties[c.name] = fieldValue(values[i] ?? null, c.type);
      });
      const id = typeof fid === 'number' ? fid : null;
      features.push({ type: 'Feature', id, properties, geometry: geometry(blob ?? null, file, features.length, id) });
    }
  } finally {
    stmt.free();
  }
  return features;
}

/** A GeoPackage geometry blob ("GP", flags, srs id, envelope, then WKB) as GeoJSON, or null when empty. */
function geometry(blob: SqlValue, file: string, index: number, id: number | null): unknown {
  if (blob === null) return null;
  const feature = { index, id };
  if (!(blob instanceof Uint8Array) || blob.length < 8 || blob[0] !== 0x47 || blob[1] !== 0x50) {
    throw new InputError('has a geometry that is not a GeoPackage geometry blob', { file, feature });
  }
  const flags = blob[3]!;
  if (flags & 0x10) return null; // the empty geometry flag
  const envelopeBytes = [0, 32, 48, 48, 64][(flags >> 1) & 0x07];
  if (envelopeBytes === undefined) throw new InputError('has a geometry blob with an invalid envelope code', { file, feature });
  const wkb = Buffer.from(blob.buffer, blob.byteOffset + 8 + envelopeBytes, blob.length - 8 - envelopeBytes);
  try {
    return wkx.Geometry.parse(wkb).toGeoJSON();
  } catch (err) {
    throw new InputError(`has a geometry whose WKB cannot be read (${(err as Error).message})`, { file, feature });
  }
}

/** Column values as GeoJSON properties: BOOLEAN columns (stored 0/1) as booleans, blobs as base64. */
function fieldValue(v: SqlValue, type: string): unknown {
  if (v instanceof Uint8Array) return Buffer.from(v).toString('base64');
  if (type === 'BOOLEAN' && typeof v === 'number') return v !== 0;
  return v;
}

function rows(db: Database, sql: string, params: SqlValue[] = []): SqlValue[][] {
  return db.exec(sql, params)[0]?.values ?? [];
}

function quote(name: string): string {
  return `"${name.replace(/"/g, '""')}"`;
}
