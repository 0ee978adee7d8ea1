// Reads a Shapefile (the .shp given, with the .dbf, .prj and .cpg beside it) as GeoJSON features
// in record order, through the `shapefile` package. The CRS is the .prj's WKT (crs.ts matches it
// to an EPSG code); the .cpg names the .dbf's text encoding (default: Windows-1252, as ArcGIS).
import { promises as fs } from 'node:fs';
import path from 'node:path';
import * as shapefile from 'shapefile';
import { InputError } from './errors.js';
import { brokenFileError, type FeatureDocument } from './input-format.js';

export async function readShapefile(shp: Buffer, file: string): Promise<FeatureDocument> {
  const dbfFile = await sidecar(file, '.dbf');
  if (dbfFile === null) {
    throw new InputError(`Shapefile has no .dbf beside it (${baseName(file)}.dbf): its attributes are missing`, { file });
  }
  const dbf = await readSidecar(dbfFile, file);
  const records = dbf.length >= 12 ? dbf.readUInt32LE(4) : -1;
  if (records < 0 || dbf.length < dbf.readUInt16LE(8) + records * dbf.readUInt16LE(10)) {
    throw new InputError(`its .dbf is truncated or corrupt: it has ${dbf.length} bytes, ${records < 0 ? 'less than a header' : `too few for the ${records} records its header announces`}`, { file });
  }
  const prjFile = await sidecar(file, '.prj');
  const wkt = prjFile === null ? '' : (await readSidecar(prjFile, file)).toString('utf8').trim();
  const cpgFile = await sidecar(file, '.cpg');
  const encoding = cpgFile === null ? 'windows-1252' : encodingLabel((await readSidecar(cpgFile, file)).toString('latin1'));
  if (!isKnownEncoding(encoding)) {
    throw new InputError(`its .cpg names the encoding ${JSON.stringify(encoding)}, which ssc cannot decode`, { file: cpgFile ?? file });
  }
  // The shapefile package stops quietly where a file ends: a cut file would lose features unsaid.
  if (shp.length < 100) throw brokenFileError(file, 'shapefile', new Error(`it has ${shp.length} bytes, less than a header`));
  const declared = shp.readUInt32BE(24) * 2;
  if (declared > shp.length) {
    throw brokenFileError(file, 'shapefile', new Error(`its header gives a length of ${declared} bytes, the file has ${shp.length}`));
  }
  const features: unknown[] = [];
  try {
    const source = await shapefile.open(toArrayBuffer(shp), toArrayBuffer(dbf), { encoding });
    for (let r = await source.read(); !r.done; r = await source.read()) {
      const f = r.value;
      features.push({ type: 'Feature', properties: plainProperties(f.properties ?? {}), geometry: f.geometry });
    }
  } catch (err) {
    throw brokenFileError(file, 'shapefile', err);
  }
  if (records !== features.length) {
    throw new InputError(`Shapefile has ${features.length} shapes but its .dbf has ${records} records (is one of them truncated?)`, { file });
  }
  return { type: 'FeatureCollection', crs: wkt ? { type: 'wkt', properties: { wkt } } : null, features };
}

/** The file beside `file` with the same base name and extension `ext`, in any letter case, or null. */
async function sidecar(file: string, ext: string): Promise<string | null> {
  const dir = path.dirname(file);
  const base = baseName(file);
  let names: string[];
  try {
    names = await fs.readdir(dir);
  } catch {
    return null;
  }
  const name = names.find((n) => n === base + ext) ?? names.find((n) => n.toLowerCase() === (base + ext).toLowerCase());
  return name === undefined ? null : path.join(dir, name);
}

/** "dir/roads.shp" (or "roads.shp.gz") -> "roads". */
function baseName(file: string): string {
  const shp = path.basename(file).replace(/\.gz$/i, '');
  return shp.slice(0, shp.length - path.extname(shp).length);
}

async function readSidecar(sidecarFile: string, file: string): Promise<Buffer> {
  try {
    return await fs.readFile(sidecarFile);
  } catch (err) {
    throw new InputError(`cannot read ${path.basename(sidecarFile)}: ${(err as Error).message}`, { file });
  }
}

/** A .cpg's code page as a WHATWG encoding label: "1252" is windows-1252, "UTF8" is utf-8. */
function encodingLabel(cpg: string): string {
  const s = cpg.trim();
  if (/^\d{3,4}$/.test(s)) return s.startsWith('125') ? `windows-${s}` : `cp${s}`;
  if (/^utf-?8$/i.test(s)) return 'utf-8';
  return s.toLowerCase();
}

function isKnownEncoding(label: string): boolean {
  try {
    new TextDecoder(label);
    return true;
  } catch {
    return false;
  }
}

/** dBASE dates come as Date objects at local midnight; as "YYYY-MM-DD", the way GDAL writes them. */
function plainProperties(props: Record<string, unknown>): Record<string, unknown> {
  const out: Record<string, unknown> = {};
  for (const [k, v] of Object.entries(props)) {
    if (v instanceof Date) {
      out[k] = Number.isNaN(v.getTime()) ? null
        : `${String(v.getFullYear()).padStart(4, '0')}-${String(v.getMonth() + 1).padStart(2, '0')}-${String(v.getDate()).padStart(2, '0')}`;
    } else {
      out[k] = v;
    }
  }
  return out;
}

function toArrayBuffer(b: Buffer): ArrayBuffer {
  return b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength) as ArrayBuffer;
}
