// Between longitude/latitude (WGS 84) and the cube's projected CRS, with the proj4 definition
// that ssc build writes into index.json (meta.proj4). Boxes are converted through their
// outlines, since a straight edge in one is curved in the other.
// proj4 is imported by `load`, once a cube's index has arrived (VarioMap decides when), not
// with the library: it was 46 of the ES build's 122 kB gzip, and a page on a slow network waits
// for all of the library before it can ask for the index (bench:session, first map on Slow 4G).
import type { Converter } from 'proj4';
import type { CubeMeta } from '../../../format/cube-index.js';
import { boxAround } from '../geometry/box-around.js';
import type { Bbox } from '../geometry/view.js';
import { LngLat } from './lng-lat.js';
import { LngLatBounds } from './lng-lat-bounds.js';

/** Points along each edge of a box converted to find the box around its image. */
const EDGE_SAMPLES = 16;


/** What the API says when a place in longitude/latitude cannot be converted. */
export class CrsError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'CrsError';
  }
}

const PROJECTED_METHODS = 'use the projected methods instead (centerProjected, boundsProjected, getCenterProjected(), getBoundsProjected(), projectProjected(), unprojectProjected(), fitBoundsProjected())';

type Proj4 = typeof import('proj4');

/** proj4 once imported; the reason it could not be, when the last try failed. */
let proj4: Proj4 | Error | null = null;
let importing: Promise<void> | null = null;

function importProj4(): Promise<void> {
  importing ??= import('proj4').then(
    (m) => {
      proj4 = m.default;
    },
    (err: unknown) => {
      proj4 = err instanceof Error ? err : new Error(String(err));
      // The next map tries again (a network blip must not leave the page without it).
      importing = null;
    },
  );
  return importing;
}

export class CrsTransform {
  private constructor(private readonly conv: Converter) {}

  /**
   * The transform of the cube described by `meta` (index at `url`), with proj4 imported first
   * when a definition needs it; rejects with a CrsError saying why there is none.
   */
  static async load(meta: CubeMeta, url: string): Promise<CrsTransform> {
    if (meta.proj4) await importProj4();
    return CrsTransform.of(meta, url);
  }

  /**
   * The same, at once: proj4 must have been imported (`load`, which the map awaits before its
   * 'meta' event), else a CrsError.
   */
  static of(meta: CubeMeta, url: string): CrsTransform {
    const crs = meta.crs ? `"${meta.crs}"` : 'not named';
    if (!meta.proj4) {
      throw new CrsError(`${url} has no proj4 definition of its CRS (meta.crs ${crs}), so longitude/latitude cannot be converted: build the cube again with ssc build, which writes meta.proj4 for EPSG codes, or ${PROJECTED_METHODS}`);
    }
    if (proj4 === null) throw new CrsError(`longitude/latitude need proj4, which is still loading for ${url}: wait for the map's 'meta' event`);
    if (proj4 instanceof Error) throw new CrsError(`proj4, which converts longitude/latitude for ${url}, could not be loaded (${proj4.message}); ${PROJECTED_METHODS}`);
    let conv: Converter;
    try {
      conv = proj4('EPSG:4326', meta.proj4);
      conv.forward([0, 0]);
    } catch (err) {
      throw new CrsError(`${url}: meta.proj4 ("${meta.proj4}") is not a proj4 definition proj4js can use (${err instanceof Error ? err.message : String(err)}); ${PROJECTED_METHODS}`);
    }
    return new CrsTransform(conv);
  }

  toProjected(p: LngLat): [number, number] {
    const [x, y] = this.conv.forward([p.lng, p.lat]);
    if (!Number.isFinite(x) || !Number.isFinite(y)) throw new CrsError(`${p.toString()} is outside what the cube's CRS can show`);
    return [x, y];
  }

  toLngLat(p: [number, number]): LngLat {
    const [lng, lat] = this.conv.inverse([p[0], p[1]]);
    return new LngLat(lng, lat);
  }

  /** The projected box around a longitude/latitude box. */
  projectedBox(b: LngLatBounds): Bbox {
    return boxAround(outline([b.getWest(), b.getSouth(), b.getEast(), b.getNorth()]).map((p) => this.toProjected(new LngLat(p[0], p[1]))));
  }

  /** The longitude/latitude box around a projected box. */
  lngLatBox(b: Bbox): LngLatBounds {
    const [w, s, e, n] = boxAround(outline(b).map((p) => this.toLngLat(p).toArray()));
    return new LngLatBounds([w, s], [e, n]);
  }
}

/** Points along the four edges of a box, corners included. */
function outline(b: Bbox): [number, number][] {
  const pts: [number, number][] = [];
  for (let i = 0; i < EDGE_SAMPLES; i++) {
    const t = i / EDGE_SAMPLES;
    const x = b[0] + (b[2] - b[0]) * t, y = b[1] + (b[3] - b[1]) * t;
    pts.push([x, b[1]], [b[2], y], [b[2] - (x - b[0]), b[3]], [b[0], b[3] - (y - b[1])]);
  }
  return pts;
}

