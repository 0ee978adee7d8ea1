// The EPSG code of a CRS given as WKT (a Shapefile's .prj, a GeoPackage or FlatGeobuf definition).
// Its own EPSG identifier when it has one; else (ESRI's .prj has none) the EPSG definition that
// proj4 computes the same: same ellipsoid, same units, and the same positions to 1 mm for the
// data's own points. The tGAP, the cube and the map's longitude/latitude need an EPSG code.
import proj4 from 'proj4';
import { createRequire } from 'node:module';

type Proj4List = Record<string, [string, string] | undefined>;

interface ProjLike {
  projName?: string;
  a?: number;
  b?: number;
  to_meter?: number;
  x0?: number;
  units?: string;
  datumCode?: string;
  forward(p: { x: number; y: number }): { x: number; y: number };
  inverse(p: { x: number; y: number }): { x: number; y: number };
}

/** The CRS's name as the WKT gives it (its first quoted string), for messages. */
export function wktName(wkt: string): string {
  return /^\s*\w+\s*\[\s*"([^"]*)"/.exec(wkt)?.[1] ?? wkt.slice(0, 40);
}

export function isGeographicWkt(wkt: string): boolean {
  return /^\s*(GEOGCS|GEOGCRS|GEOGRAPHICCRS|GEODCRS)\s*\[/i.test(wkt);
}

/**
 * "EPSG:n" for `wkt`, or null when it matches none. `points` are coordinates in that CRS (the
 * data's corners and centre): where two definitions differ, they differ there.
 */
export function epsgFromWkt(wkt: string, points: [number, number][]): string | null {
  // The CRS's own identifier is its last member (WKT 1 AUTHORITY, WKT 2 ID).
  const own = /(?:AUTHORITY\s*\[\s*"EPSG"\s*,\s*"?(\d+)"?\s*\]|ID\s*\[\s*"EPSG"\s*,\s*(\d+)\s*(?:,[^\]]*)?\])\s*\]\s*$/i.exec(wkt);
  if (own) return `EPSG:${own[1] ?? own[2]}`;
  const target = parse(wkt);
  if (!target) return null;
  const geographic = target.projName === 'longlat';
  let best: { code: string; rank: number } | null = null;
  for (const entry of Object.values(list())) {
    if (!entry) continue;
    const [code, def] = entry;
    // Cheap filters before proj4 parses a definition (all 5000 would take about a second).
    // Compound CRSs (+vunits) share their horizontal part's definition: the 2D one is meant.
    if (/\+proj=longlat\b/.test(def) !== geographic || /\+proj=geocent|\+vunits=|\+geoidgrids=/.test(def)) continue;
    if (!geographic && toMetre(target) === 1 && Math.abs(falseEasting(def) - (target.x0 ?? 0)) > 1e-3) continue;
    const cand = parse(def);
    if (!cand || !sameShape(target, cand, geographic, points)) continue;
    // Same datum name first, then the lowest code (the older, usual one of duplicates).
    const rank = (sameDatum(target, cand) ? 0 : 1e9) + Number(code.replace(/\D/g, ''));
    if (!best || rank < best.rank) best = { code, rank };
  }
  return best ? best.code.toUpperCase() : null;
}

let cache: Proj4List | null = null;
function list(): Proj4List {
  cache ??= createRequire(import.meta.url)('proj4-list') as Proj4List;
  return cache;
}

function parse(def: string): ProjLike | null {
  try {
    return proj4.Proj(def);
  } catch {
    return null;
  }
}

function sameShape(p: ProjLike, q: ProjLike, geographic: boolean, points: [number, number][]): boolean {
  // The semi-minor axes of WGS 84 and GRS 80 differ by 0.1 mm.
  if (Math.abs((p.a ?? NaN) - (q.a ?? NaN)) > 1e-6 || Math.abs((p.b ?? NaN) - (q.b ?? NaN)) > 1e-6) return false;
  if (geographic) return true;
  if (Math.abs(toMetre(p) - toMetre(q)) > 1e-12) return false;
  for (const [x, y] of points) {
    let back: { x: number; y: number };
    try {
      back = q.forward(p.inverse({ x, y }));
    } catch {
      return false;
    }
    if (!(Math.abs(back.x - x) <= 1e-3 && Math.abs(back.y - y) <= 1e-3)) return false;
  }
  return true;
}

/** A proj4 definition's false easting in metres (UTM's is implied). */
function falseEasting(def: string): number {
  const x0 = /\+x_0=(\S+)/.exec(def);
  return x0 ? Number(x0[1]) : /\+proj=utm\b/.test(def) ? 500000 : 0;
}

function toMetre(p: ProjLike): number {
  if (typeof p.to_meter === 'number') return p.to_meter;
  return p.units === undefined || /^(m|meter|metre)$/i.test(p.units) ? 1 : NaN;
}

function sameDatum(p: ProjLike, q: ProjLike): boolean {
  return p.datumCode !== undefined && q.datumCode !== undefined && p.datumCode.toLowerCase() === q.datumCode.toLowerCase();
}
