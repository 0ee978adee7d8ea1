// Decides whether input coordinates are metres in a projected CRS, or longitude/latitude
// that must be projected first (they are never silently treated as metres).
import proj4 from 'proj4';
import { InputError } from './errors.js';
import { epsgFromWkt, wktName } from './crs-from-wkt.js';
import type { RawInput } from './read-input.js';

export interface CrsInfo {
  /** The CRS of the coordinates the pipeline works in, e.g. "EPSG:28992". */
  code: string;
  /** Set when the input was longitude/latitude and we projected it. */
  projectedFrom?: string;
  /** proj4 definition of the working CRS when we chose it (UTM). */
  proj4?: string;
}

// Geographic (degree-based) CRSs that appear in practice; anything listed here gets projected.
const GEOGRAPHIC = new Set([
  'EPSG:4326', 'EPSG:4258', 'EPSG:4269', 'EPSG:4267', 'EPSG:4230', 'EPSG:4283', 'EPSG:4617',
  'EPSG:4674', 'EPSG:4759', 'EPSG:4152', 'EPSG:4289', 'EPSG:4490', 'EPSG:4612', 'EPSG:6318',
  'EPSG:7844', 'EPSG:4019', 'OGC:CRS84', 'OGC:CRS83', 'OGC:CRS27',
]);

/** Normalises the many spellings of a CRS name to "EPSG:n" or "OGC:CRS84". */
export function normaliseCrsName(name: string): string {
  const s = name.trim();
  const urn = /^urn:ogc:def:crs:EPSG:[\d.]*:(\d+)$/i.exec(s);
  if (urn) return `EPSG:${urn[1]}`;
  const epsg = /^EPSG:+(\d+)$/i.exec(s) ?? /epsg\.io\/(\d+)/i.exec(s) ?? /opengis\.net\/def\/crs\/EPSG\/[\d.]+\/(\d+)/i.exec(s);
  if (epsg) return `EPSG:${epsg[1]}`;
  if (/CRS84$/i.test(s)) return 'OGC:CRS84';
  if (/CRS83$/i.test(s)) return 'OGC:CRS83';
  if (/CRS27$/i.test(s)) return 'OGC:CRS27';
  return s;
}

function crsFromMember(member: unknown, input: RawInput, ext: [number, number, number, number]): string | null {
  if (typeof member !== 'object' || member === null) return null;
  const m = member as { type?: unknown; properties?: { name?: unknown; code?: unknown; wkt?: unknown } };
  // The readers of Shapefile, GeoPackage and FlatGeobuf give a CRS without an EPSG code as WKT.
  if (m.type === 'wkt' && m.properties && typeof m.properties.wkt === 'string') {
    const [x0, y0, x1, y1] = ext;
    const code = epsgFromWkt(m.properties.wkt, [[x0, y0], [x1, y1], [x0, y1], [x1, y0], [(x0 + x1) / 2, (y0 + y1) / 2]]);
    if (code === null) {
      throw new InputError(
        `declares the CRS ${JSON.stringify(wktName(m.properties.wkt))}, which matches no EPSG definition ssc knows; pass --crs EPSG:<code> to say which it is`,
        { file: input.file },
      );
    }
    return code;
  }
  if (m.properties && typeof m.properties.name === 'string') return normaliseCrsName(m.properties.name);
  if (m.type === 'EPSG' && m.properties && (typeof m.properties.code === 'number' || typeof m.properties.code === 'string')) {
    return `EPSG:${m.properties.code}`;
  }
  return null;
}

function extentOf(input: RawInput): [number, number, number, number] {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const f of input.features) {
    for (const p of f.polygons) {
      for (const r of p) {
        for (let i = 0; i < r.length; i += 2) {
          const x = r[i]!, y = r[i + 1]!;
          if (x < x0) x0 = x;
          if (x > x1) x1 = x;
          if (y < y0) y0 = y;
          if (y > y1) y1 = y;
        }
      }
    }
  }
  return [x0, y0, x1, y1];
}

function looksGeographic(ext: [number, number, number, number]): boolean {
  return ext[0] >= -180 && ext[2] <= 180 && ext[1] >= -90 && ext[3] <= 90;
}

/**
 * Resolves the working CRS, projecting longitude/latitude input to its UTM zone in place.
 * `override` is the --crs option and wins over the file's own member.
 */
export function resolveCrs(input: RawInput, override?: string): CrsInfo {
  const ext = extentOf(input);
  const declared = override ? normaliseCrsName(override) : crsFromMember(input.crsMember, input, ext);
  // RFC 7946: GeoJSON without a crs member is WGS 84 longitude/latitude.
  const geographic = declared === null ? looksGeographic(ext) : GEOGRAPHIC.has(declared);
  if (declared === null && !geographic) {
    throw new InputError(
      'does not say its CRS (no "crs" member, .prj or spatial reference) and its coordinates are not longitude/latitude; pass --crs EPSG:<code> to say which projected CRS (in metres) they are in',
      { file: input.file },
    );
  }
  if (!geographic) {
    if (declared !== null && looksGeographic(ext) && ext[2] - ext[0] < 10 && ext[3] - ext[1] < 10) {
      throw new InputError(
        `declares ${declared} (projected, metres) but its coordinates look like degrees (${ext.map((v) => v.toFixed(4)).join(', ')}); pass --crs EPSG:4326 if they are longitude/latitude`,
        { file: input.file },
      );
    }
    return { code: declared! };
  }
  if (!looksGeographic(ext)) {
    throw new InputError(
      `declares ${declared ?? 'longitude/latitude'} but has coordinates outside [-180, 180] x [-90, 90] (${ext.join(', ')})`,
      { file: input.file },
    );
  }
  const lon = (ext[0] + ext[2]) / 2, lat = (ext[1] + ext[3]) / 2;
  const zone = Math.min(60, Math.floor((lon + 180) / 6) + 1);
  const south = lat < 0;
  const def = `+proj=utm +zone=${zone}${south ? ' +south' : ''} +datum=WGS84 +units=m +no_defs`;
  const conv = proj4('EPSG:4326', def);
  for (const f of input.features) {
    for (const p of f.polygons) {
      for (const r of p) {
        for (let i = 0; i < r.length; i += 2) {
          const [x, y] = conv.forward([r[i]!, r[i + 1]!]);
          r[i] = x!;
          r[i + 1] = y!;
        }
      }
    }
  }
  return { code: `EPSG:${south ? 32700 + zone : 32600 + zone}`, projectedFrom: declared ?? 'OGC:CRS84', proj4: def };
}
