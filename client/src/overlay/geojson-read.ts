// GeoJSON (RFC 7946) as the overlay layer takes it: a FeatureCollection, a Feature or a bare
// geometry, checked in full so that one error names every problem (feature index, where in it,
// what is wrong), and read into the points, lines and polygons the layer draws. Coordinates
// stay as given here; projecting them to the cube's CRS is a second step (projectParts). Pure.

/** A position: [x, y] (longitude, latitude), further values (elevation) ignored. */
export type Position = number[];

export type GeoJsonGeometry =
  | { type: 'Point'; coordinates: Position }
  | { type: 'MultiPoint'; coordinates: Position[] }
  | { type: 'LineString'; coordinates: Position[] }
  | { type: 'MultiLineString'; coordinates: Position[][] }
  | { type: 'Polygon'; coordinates: Position[][] }
  | { type: 'MultiPolygon'; coordinates: Position[][][] }
  | { type: 'GeometryCollection'; geometries: GeoJsonGeometry[] };

export interface GeoJsonFeature {
  type: 'Feature';
  geometry: GeoJsonGeometry | null;
  properties: Record<string, unknown> | null;
  id?: string | number;
}

export interface GeoJsonFeatureCollection {
  type: 'FeatureCollection';
  features: GeoJsonFeature[];
}

export type GeoJsonData = GeoJsonFeatureCollection | GeoJsonFeature | GeoJsonGeometry;

export type XY = [number, number];

/** One feature's geometry as drawn: points, lines (2+ positions) and polygons (rings, outer first, not closed). */
export interface Parts {
  points: XY[];
  lines: XY[][];
  polygons: XY[][][];
}

export interface ReadFeature {
  /** What events give: the feature as passed (a bare geometry is wrapped in a Feature). */
  feature: GeoJsonFeature;
  /** How errors name it: "features[3]" (with its id), or "the Feature", "the geometry". */
  name: string;
  parts: Parts;
}

/** Errors listed in one message beyond which the rest are counted. */
const MAX_LISTED = 20;

const GEOMETRY_TYPES = ['Point', 'MultiPoint', 'LineString', 'MultiLineString', 'Polygon', 'MultiPolygon', 'GeometryCollection'];

/** All the problems of one input, thrown together. */
export class GeoJsonError extends Error {
  constructor(
    readonly what: string,
    readonly problems: string[],
  ) {
    const listed = problems.slice(0, MAX_LISTED).map((p) => `\n  ${p}`).join('');
    const more = problems.length > MAX_LISTED ? `\n  ... and ${problems.length - MAX_LISTED} more` : '';
    super(`${what}: ${problems.length === 1 ? 'a problem' : `${problems.length} problems`} in the GeoJSON:${listed}${more}`);
    this.name = 'GeoJsonError';
  }
}

/**
 * The features of `data`, or a GeoJsonError (`what` starts its message) naming every problem.
 * `lngLat`: positions are longitude/latitude, so latitudes must lie in [-90, 90].
 */
export function readGeoJson(data: unknown, lngLat: boolean, what: string): ReadFeature[] {
  const problems: string[] = [];
  const out: ReadFeature[] = [];
  const reader = new PartsReader(lngLat, problems);
  const type = isObject(data) ? data.type : undefined;
  if (!isObject(data)) problems.push(`the data must be a GeoJSON object (FeatureCollection, Feature or geometry), not ${describe(data)}`);
  else if (type === 'FeatureCollection') {
    if (!Array.isArray(data.features)) problems.push(`the FeatureCollection's "features" must be an array, not ${describe(data.features)}`);
    else data.features.forEach((f: unknown, i) => readFeature(f, `features[${i}]`, reader, out));
  } else if (type === 'Feature') readFeature(data, 'the Feature', reader, out);
  else if (typeof type === 'string' && GEOMETRY_TYPES.includes(type)) {
    const parts = reader.geometry(data, 'the geometry', '');
    out.push({ feature: { type: 'Feature', geometry: data as unknown as GeoJsonGeometry, properties: {} }, name: 'the geometry', parts });
  } else problems.push(`the data's "type" must be FeatureCollection, Feature or a geometry type (${GEOMETRY_TYPES.join(', ')}), not ${describe(type)}`);
  if (problems.length > 0) throw new GeoJsonError(what, problems);
  return out;
}

function readFeature(f: unknown, where: string, reader: PartsReader, out: ReadFeature[]): void {
  if (!isObject(f) || f.type !== 'Feature') {
    reader.problems.push(`${where} must be a Feature (an object with "type": "Feature"), not ${isObject(f) ? `an object with "type" ${describe(f.type)}` : describe(f)}`);
    return;
  }
  const id = f.id;
  const name = typeof id === 'string' || typeof id === 'number' ? `${where} (id ${JSON.stringify(id)})` : where;
  if (id !== undefined && typeof id !== 'string' && typeof id !== 'number') reader.problems.push(`${name}: "id" must be a string or a number, not ${describe(id)}`);
  if (f.properties !== undefined && f.properties !== null && !isObject(f.properties)) reader.problems.push(`${name}: "properties" must be an object or null, not ${describe(f.properties)}`);
  if (!('geometry' in f)) reader.problems.push(`${name} has no "geometry" (null for none)`);
  const parts = f.geometry === null || f.geometry === undefined ? emptyParts() : reader.geometry(f.geometry, name, 'geometry');
  out.push({ feature: f as unknown as GeoJsonFeature, name, parts });
}

/**
 * Reads geometries into parts, adding what is wrong to `problems`. The place of a wrong
 * position (geometry.coordinates[1][4]) is kept as indices on a stack and written out only
 * when something is wrong: most data is right, and large.
 */
class PartsReader {
  /** The geometry being read: its feature's name and where its coordinates are. */
  private name = '';
  private where = '';
  /** Indices into the coordinates down to the array being read. */
  private readonly idx: number[] = [];

  constructor(
    private readonly lngLat: boolean,
    readonly problems: string[],
  ) {}

  geometry(g: unknown, name: string, path: string, into: Parts = emptyParts()): Parts {
    const at = (sub: string): string => [path, sub].filter((s) => s !== '').join('.');
    const say = (where: string, msg: string): void => {
      this.problems.push(`${name}: ${where === '' ? '' : `${where}: `}${msg}`);
    };
    if (!isObject(g)) {
      say(path, `a geometry must be an object, not ${describe(g)}`);
      return into;
    }
    const type = g.type;
    if (type === 'GeometryCollection') {
      if (!Array.isArray(g.geometries)) say(at('geometries'), `must be an array, not ${describe(g.geometries)}`);
      else g.geometries.forEach((sub: unknown, i) => this.geometry(sub, name, at(`geometries[${i}]`), into));
      return into;
    }
    if (typeof type !== 'string' || !GEOMETRY_TYPES.includes(type)) {
      say(at('type'), `${describe(type)} is not a GeoJSON geometry type (${GEOMETRY_TYPES.join(', ')})`);
      return into;
    }
    this.name = name;
    this.where = at('coordinates');
    const c: unknown = g.coordinates;
    switch (type) {
      case 'Point': {
        const p = this.position(c);
        if (p) into.points.push(p);
        break;
      }
      case 'MultiPoint':
        this.each(c, (p) => {
          const xy = this.position(p);
          if (xy) into.points.push(xy);
        });
        break;
      case 'LineString':
        this.line(c, into);
        break;
      case 'MultiLineString':
        this.each(c, (l) => this.line(l, into));
        break;
      case 'Polygon':
        this.polygon(c, into);
        break;
      case 'MultiPolygon':
        this.each(c, (poly) => this.polygon(poly, into));
        break;
    }
    return into;
  }

  private say(msg: string): void {
    this.problems.push(`${this.name}: ${this.where}${this.idx.map((i) => `[${i}]`).join('')}: ${msg}`);
  }

  /** Calls `f` on every element of the array `list` (with its index on the stack); false if `list` is no array. */
  private each(list: unknown, f: (item: unknown) => void): boolean {
    if (!Array.isArray(list)) {
      this.say(`must be an array, not ${describe(list)}`);
      return false;
    }
    for (let i = 0; i < list.length; i++) {
      this.idx.push(i);
      f(list[i]);
      this.idx.pop();
    }
    return true;
  }

  private position(p: unknown): XY | null {
    if (!Array.isArray(p) || p.length < 2) {
      this.say(`a position must be an array of at least two numbers, not ${describe(p)}`);
      return null;
    }
    const [x, y] = p as unknown[];
    if (typeof x !== 'number' || typeof y !== 'number' || !Number.isFinite(x) || !Number.isFinite(y)) {
      this.say(`a position's coordinates must be finite numbers, not ${describe(p)}`);
      return null;
    }
    if (this.lngLat && (y < -90 || y > 90)) {
      this.say(`latitude ${y} is outside [-90, 90] (longitude/latitude expected; projected coordinates go to setDataProjected)`);
      return null;
    }
    return [x, y];
  }

  /** The positions of a list, or null if any is wrong (each said). */
  private positions(list: unknown): XY[] | null {
    const out: XY[] = [];
    let ok = true;
    if (!this.each(list, (p) => {
      const xy = this.position(p);
      if (xy) out.push(xy);
      else ok = false;
    })) ok = false;
    return ok ? out : null;
  }

  private line(list: unknown, into: Parts): void {
    const pts = this.positions(list);
    if (!pts) return;
    if (pts.length < 2) this.say(`a line needs at least two positions, not ${pts.length}`);
    else into.lines.push(pts);
  }

  private polygon(rings: unknown, into: Parts): void {
    const out: XY[][] = [];
    let ok = true;
    const isArray = this.each(rings, (r) => {
      const pts = this.positions(r);
      if (!pts) {
        ok = false;
        return;
      }
      // The closing position is optional here (as MapLibre reads rings); it is not kept.
      const last = pts[pts.length - 1], first = pts[0];
      if (pts.length > 1 && first && last && first[0] === last[0] && first[1] === last[1]) pts.pop();
      if (pts.length < 3) {
        this.say(`a ring needs at least three distinct positions, not ${pts.length}`);
        ok = false;
      } else out.push(pts);
    });
    if (isArray && ok && out.length > 0) into.polygons.push(out);
  }
}

export function emptyParts(): Parts {
  return { points: [], lines: [], polygons: [] };
}

/** The parts with every position passed through `f` (to the cube's CRS). */
export function mapParts(p: Parts, f: (xy: XY) => XY): Parts {
  return { points: p.points.map(f), lines: p.lines.map((l) => l.map(f)), polygons: p.polygons.map((poly) => poly.map((r) => r.map(f))) };
}

function isObject(v: unknown): v is Record<string, unknown> {
  return typeof v === 'object' && v !== null && !Array.isArray(v);
}

/** A short description of a value for a message. */
function describe(v: unknown): string {
  if (v === undefined) return 'missing';
  if (Array.isArray(v)) return v.length <= 4 && v.every((x) => typeof x !== 'object') ? JSON.stringify(v) : `an array of ${v.length}`;
  if (typeof v === 'object' && v !== null) return 'an object';
  if (typeof v === 'number' && !Number.isFinite(v)) return String(v);
  return JSON.stringify(v) ?? String(v);
}
