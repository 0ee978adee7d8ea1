// Reads polygon input (GeoJSON, TopoJSON, GeoPackage, Shapefile, FlatGeobuf, each optionally
// gzipped) into plain rings of numbers. The binary formats come as GeoJSON features from their
// readers (input-format.ts), so every format goes through the same checks below. Everything that
// is not a polygon is refused here, with the feature named (all such features at once).
import { promises as fs } from 'node:fs';
import { gunzipSync } from 'node:zlib';
import path from 'node:path';
import { feature as topoFeature } from 'topojson-client';
import type { Topology } from 'topojson-specification';
import { InputError, type FeatureRef } from './errors.js';
import { detectFormat, readBinaryFormat } from './input-format.js';
import { fsReason, isFsError } from './output-path.js';
import { ProblemList } from './problems.js';

export interface InputFeature {
  ref: FeatureRef;
  properties: Record<string, unknown>;
  /** polygons -> rings (first outer, then holes) -> flat x,y pairs, open (no closing point). */
  polygons: Float64Array[][];
}

export interface InputRepairs {
  closedRings: number;
  duplicatePoints: number;
}

export interface RawInput {
  file: string;
  /** The `crs` member as found, or null. */
  crsMember: unknown;
  features: InputFeature[];
  repairs: InputRepairs;
}

export interface ReadOptions {
  /** For GeoPackage: the layer to read (required when it has several); for TopoJSON: the object (default: all, in key order). */
  layer?: string;
  /** Property that names a feature in messages (default: feature.id, then "id"). */
  idProperty?: string;
  /**
   * Where the problems of single features go (the feature is then kept without polygons,
   * and the caller refuses the input later with all it found). Without it they are refused
   * together at the end of reading.
   */
  problems?: ProblemList;
}

/** Beyond this (in CRS units) no coordinate is on the earth: metres or feet stay under 2e8. */
export const MAX_COORDINATE = 1e9;

export async function readInput(file: string, opts: ReadOptions = {}): Promise<RawInput> {
  let buf: Buffer;
  try {
    buf = await fs.readFile(file);
  } catch (err) {
    throw new InputError(`cannot read input: ${isFsError(err) ? fsReason(err) : (err as Error).message}`, { file });
  }
  const gzipped = buf.length >= 2 && buf[0] === 0x1f && buf[1] === 0x8b;
  if (!gzipped && /\.gz$/i.test(file)) {
    throw new InputError('broken gzip: the file is named .gz but does not start with the gzip signature (1f 8b)', { file });
  }
  if (gzipped) {
    try {
      buf = gunzipSync(buf);
    } catch (err) {
      throw new InputError(`broken gzip: ${(err as Error).message}`, { file });
    }
  }
  const format = detectFormat(buf, file);
  if (format !== 'json') return parseDocument(await readBinaryFormat(format, buf, file, opts.layer), path.basename(file), opts);
  let doc: unknown;
  try {
    doc = parseJson(buf.toString('utf8'));
  } catch (err) {
    throw new InputError(`not valid JSON: ${(err as Error).message}`, { file });
  }
  return parseDocument(doc, path.basename(file), opts);
}

// Bare NaN, Infinity and -Infinity outside strings (as Python's json module writes them).
const NON_FINITE_TOKEN = /"(?:[^"\\]|\\.)*"|(-?)\b(NaN|Infinity)\b/g;
const NON_FINITE_MARK = '\u0000ssc-non-finite:';

/**
 * JSON.parse, except that bare NaN and Infinity tokens (not JSON, but common in files written
 * by Python) are read as numbers: the reader then refuses them naming the feature and the
 * place, instead of a parse error that names neither. Valid JSON never takes this path.
 */
function parseJson(text: string): unknown {
  try {
    return JSON.parse(text);
  } catch (err) {
    let found = false;
    const marked = text.replace(NON_FINITE_TOKEN, (m: string, sign: string | undefined, word: string | undefined) => {
      if (word === undefined) return m; // a string: left as it is
      found = true;
      return JSON.stringify(NON_FINITE_MARK + (sign ?? '') + word);
    });
    if (!found) throw err;
    try {
      return JSON.parse(marked, (_key, v: unknown) =>
        typeof v === 'string' && v.startsWith(NON_FINITE_MARK) ? Number(v.slice(NON_FINITE_MARK.length)) : v);
    } catch {
      throw err;
    }
  }
}

export function parseDocument(doc: unknown, file: string, opts: ReadOptions = {}): RawInput {
  if (!isObject(doc)) throw new InputError('expected a GeoJSON or TopoJSON object', { file });
  const repairs: InputRepairs = { closedRings: 0, duplicatePoints: 0 };
  const features: InputFeature[] = [];
  let geojsonFeatures: unknown[];
  if (doc.type === 'Topology') {
    geojsonFeatures = topologyFeatures(doc, file, opts.layer);
  } else if (doc.type === 'FeatureCollection') {
    if (!Array.isArray(doc.features)) throw new InputError('FeatureCollection without a "features" array', { file });
    geojsonFeatures = doc.features;
  } else if (doc.type === 'Feature') {
    geojsonFeatures = [doc];
  } else {
    throw new InputError(`unsupported document type ${JSON.stringify(doc.type)} (expected FeatureCollection, Feature or Topology)`, { file });
  }
  if (geojsonFeatures.length === 0) throw new InputError('the input holds no features', { file });
  const problems = opts.problems ?? new ProblemList(file);
  geojsonFeatures.forEach((f, index) => {
    try {
      features.push(readFeature(f, index, file, opts.idProperty, repairs));
    } catch (err) {
      if (!(err instanceof InputError) || !err.feature) throw err;
      problems.addError(err, err.kind ?? 'geometry');
      features.push({ ref: err.feature, properties: featureProperties(f), polygons: [] });
    }
  });
  if (!opts.problems) problems.check();
  return { file, crsMember: doc.crs ?? null, features, repairs };
}

function topologyFeatures(doc: Record<string, unknown>, file: string, layer: string | undefined): unknown[] {
  const objects = doc.objects;
  if (!isObject(objects)) throw new InputError('TopoJSON without "objects"', { file });
  const names = layer ? [layer] : Object.keys(objects);
  if (layer && !(layer in objects)) {
    throw new InputError(`TopoJSON has no object ${JSON.stringify(layer)} (it has ${Object.keys(objects).join(', ')})`, { file });
  }
  const out: unknown[] = [];
  for (const name of names) {
    let converted: unknown;
    try {
      converted = topoFeature(doc as unknown as Topology, name);
    } catch (err) {
      throw new InputError(`TopoJSON object ${JSON.stringify(name)} cannot be decoded: ${(err as Error).message}`, { file });
    }
    if (isObject(converted) && converted.type === 'FeatureCollection' && Array.isArray(converted.features)) {
      out.push(...converted.features);
    } else {
      out.push(converted);
    }
  }
  return out;
}

function featureProperties(f: unknown): Record<string, unknown> {
  return isObject(f) && isObject(f.properties) ? f.properties : {};
}

function readFeature(f: unknown, index: number, file: string, idProperty: string | undefined, repairs: InputRepairs): InputFeature {
  const props = featureProperties(f);
  const ref: FeatureRef = { index, id: featureId(f, props, idProperty) };
  if (!isObject(f) || f.type !== 'Feature') throw new InputError('is not a GeoJSON Feature', { file, feature: ref });
  const g = f.geometry;
  if (!isObject(g)) throw new InputError('has no geometry (polygon expected)', { file, feature: ref });
  let polys: unknown[];
  if (g.type === 'Polygon') polys = [g.coordinates];
  else if (g.type === 'MultiPolygon') {
    if (!Array.isArray(g.coordinates)) throw new InputError('MultiPolygon without coordinates', { file, feature: ref });
    polys = g.coordinates;
  } else {
    // Named with its first point, so that it can be found on a map.
    const at = firstPosition(g.coordinates);
    throw new InputError(`has geometry type ${JSON.stringify(g.type)}; only Polygon and MultiPolygon are accepted`, { file, feature: ref, ...(at ? { location: at } : {}) });
  }
  const polygons: Float64Array[][] = [];
  for (const p of polys) {
    if (!Array.isArray(p) || p.length === 0) throw new InputError('has a polygon without rings', { file, feature: ref });
    polygons.push(p.map((ring) => readRing(ring, file, ref, repairs)));
  }
  if (polygons.length === 0) throw new InputError('has an empty MultiPolygon', { file, feature: ref });
  return { ref, properties: props, polygons };
}

function readRing(ring: unknown, file: string, ref: FeatureRef, repairs: InputRepairs): Float64Array {
  if (!Array.isArray(ring)) throw new InputError('has a ring that is not an array of positions', { file, feature: ref });
  const out: number[] = [];
  for (const pos of ring) {
    if (!Array.isArray(pos) || pos.length < 2) throw new InputError('has a position that is not [x, y]', { file, feature: ref });
    const x = pos[0], y = pos[1];
    if (typeof x !== 'number' || typeof y !== 'number' || !Number.isFinite(x) || !Number.isFinite(y)) {
      // The place is the point before; for a ring's first point, the first good point after it.
      const near = out.length >= 2 ? ([out[out.length - 2]!, out[out.length - 1]!] as [number, number]) : firstPosition(ring);
      // JSON.stringify would print NaN and Infinity as null, naming a value the file does not hold.
      const shown = `[${pos.map((v: unknown) => (typeof v === 'number' ? String(v) : JSON.stringify(v))).join(', ')}]`;
      throw new InputError(`has a coordinate that is not a finite number: ${shown}`, { file, feature: ref, kind: 'coordinate', ...(near ? { location: near } : {}) });
    }
    if (Math.abs(x) > MAX_COORDINATE || Math.abs(y) > MAX_COORDINATE) {
      const near = out.length >= 2 ? ([out[out.length - 2]!, out[out.length - 1]!] as [number, number]) : firstPosition(ring);
      throw new InputError(`has a coordinate out of range: [${x}, ${y}] (no CRS reaches beyond ±${MAX_COORDINATE} units)`, { file, feature: ref, kind: 'coordinate', ...(near ? { location: near } : {}) });
    }
    const n = out.length;
    if (n >= 2 && out[n - 2] === x && out[n - 1] === y) {
      repairs.duplicatePoints++;
      continue;
    }
    out.push(x, y);
  }
  const n = out.length;
  if (n >= 4 && out[0] === out[n - 2] && out[1] === out[n - 1]) {
    out.length = n - 2; // drop the closing point: rings are stored open
  } else if (n >= 2) {
    repairs.closedRings++;
  }
  return Float64Array.from(out);
}

function featureId(f: unknown, props: Record<string, unknown>, idProperty: string | undefined): string | number | null {
  if (idProperty !== undefined) {
    const v = props[idProperty];
    return typeof v === 'string' || typeof v === 'number' ? v : null;
  }
  if (isObject(f) && (typeof f.id === 'string' || typeof f.id === 'number')) return f.id;
  const v = props.id;
  return typeof v === 'string' || typeof v === 'number' ? v : null;
}

/** The first [x, y] of finite numbers within range in nested coordinate arrays, if any. */
function firstPosition(coords: unknown): [number, number] | undefined {
  if (!Array.isArray(coords)) return undefined;
  const [x, y] = coords as unknown[];
  if (typeof x === 'number' && typeof y === 'number' && Math.abs(x) <= MAX_COORDINATE && Math.abs(y) <= MAX_COORDINATE) return [x, y];
  for (const c of coords) {
    const p = firstPosition(c);
    if (p) return p;
  }
  return undefined;
}

function isObject(v: unknown): v is Record<string, unknown> {
  return typeof v === 'object' && v !== null && !Array.isArray(v);
}
