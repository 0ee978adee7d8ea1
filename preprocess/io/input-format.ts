// Which format an input file is in, from its first bytes and then its extension, and the reader
// for each binary format. Every reader gives a GeoJSON FeatureCollection, so that all formats go
// through the same feature checks, property handling and feature order (read-input.ts).
import path from 'node:path';
import { InputError } from './errors.js';

export type InputFormat = 'json' | 'geopackage' | 'shapefile' | 'flatgeobuf';

/** A binary format's features as GeoJSON, with the CRS member read-input and crs.ts expect. */
export interface FeatureDocument {
  type: 'FeatureCollection';
  /** {type: 'name', properties: {name: 'EPSG:n'}}, {type: 'wkt', properties: {wkt}} or null. */
  crs: unknown;
  features: unknown[];
}

export const FORMAT_NAMES: Record<InputFormat, string> = {
  json: 'GeoJSON/TopoJSON',
  geopackage: 'GeoPackage',
  shapefile: 'Shapefile',
  flatgeobuf: 'FlatGeobuf',
};

export const SUPPORTED_FORMATS =
  'GeoJSON (.geojson, .json), TopoJSON (.topojson), GeoPackage (.gpkg), Shapefile (.shp with its .dbf and .prj) and FlatGeobuf (.fgb), each also gzipped (.gz)';

const SQLITE_MAGIC = Buffer.from('SQLite format 3\0', 'latin1');
const FLATGEOBUF_MAGIC = Buffer.from([0x66, 0x67, 0x62, 0x03]); // "fgb" and major version 3
const ZIP_MAGIC = Buffer.from([0x50, 0x4b, 0x03, 0x04]);

const EXTENSIONS: Record<string, InputFormat> = {
  '.geojson': 'json', '.json': 'json', '.topojson': 'json',
  '.gpkg': 'geopackage', '.shp': 'shapefile', '.fgb': 'flatgeobuf',
};

/**
 * The format of `buf` (already gunzipped), read from `file`: the content decides where it has a
 * signature; the extension (under any .gz) decides for a file too short or broken to have one,
 * so that a truncated GeoPackage is reported as a broken GeoPackage, not as unknown.
 */
export function detectFormat(buf: Buffer, file: string): InputFormat {
  if (startsWith(buf, SQLITE_MAGIC)) return 'geopackage';
  if (startsWith(buf, FLATGEOBUF_MAGIC)) return 'flatgeobuf';
  if (buf.length >= 4 && buf.readUInt32BE(0) === 9994) return 'shapefile';
  const first = firstNonBlank(buf);
  if (first === 0x7b /* { */ || first === 0x5b /* [ */) return 'json';
  const ext = path.extname(file.replace(/\.gz$/i, '')).toLowerCase();
  const byName = EXTENSIONS[ext];
  if (byName) return byName;
  if (startsWith(buf, ZIP_MAGIC)) {
    throw new InputError(`is a zip archive; unpack it and give the file inside. ssc reads ${SUPPORTED_FORMATS}`, { file });
  }
  if (ext === '.dbf' || ext === '.shx' || ext === '.prj') {
    throw new InputError(`is part of a Shapefile; give its .shp file. ssc reads ${SUPPORTED_FORMATS}`, { file });
  }
  throw new InputError(`is in a format ssc does not read; it reads ${SUPPORTED_FORMATS}`, { file });
}

/** Reads a binary format into a FeatureDocument; `layer` picks one of a GeoPackage's layers. */
export async function readBinaryFormat(format: Exclude<InputFormat, 'json'>, buf: Buffer, file: string, layer: string | undefined): Promise<FeatureDocument> {
  // Each reader's library is loaded only when a file of its format is read.
  if (format === 'geopackage') return (await import('./read-geopackage.js')).readGeopackage(buf, file, layer);
  if (format === 'flatgeobuf') return (await import('./read-flatgeobuf.js')).readFlatgeobuf(buf, file);
  return (await import('./read-shapefile.js')).readShapefile(buf, file);
}

/**
 * The error for a file that breaks its format: one line naming the file and the format, with the
 * library's words cleaned of control characters and raw bytes, and cut short.
 */
export function brokenFileError(file: string, format: InputFormat, err: unknown): InputError {
  if (err instanceof InputError) return err;
  const raw = err instanceof Error ? err.message : String(err);
  // eslint-disable-next-line no-control-regex
  let said = raw.replace(/[\u0000-\u001f\u007f-\u009f\ufffd]+/g, ' ').replace(/\s+/g, ' ').trim();
  if (said.length > 160) said = said.slice(0, 157) + '...';
  return new InputError(`is not a valid ${FORMAT_NAMES[format]} (truncated or corrupt?)${said ? `: ${said}` : ''}`, { file });
}

function startsWith(buf: Buffer, magic: Buffer): boolean {
  return buf.length >= magic.length && buf.subarray(0, magic.length).equals(magic);
}

/** The first byte that is not whitespace or a UTF-8 byte order mark, or -1. */
function firstNonBlank(buf: Buffer): number {
  let i = buf.length >= 3 && buf[0] === 0xef && buf[1] === 0xbb && buf[2] === 0xbf ? 3 : 0;
  while (i < buf.length && (buf[i] === 0x20 || buf[i] === 0x09 || buf[i] === 0x0a || buf[i] === 0x0d)) i++;
  return i < buf.length ? buf[i]! : -1;
}
