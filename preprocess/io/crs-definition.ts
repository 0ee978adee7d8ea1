// The proj4 definition of a cube's CRS, written into index.json so that the map can take and
// give longitude/latitude: from proj4-list (proj4js's definitions of the EPSG codes, as GDAL
// wrote them) for "EPSG:n". epsg-index was weighed: its EPSG:28992 carries the datum shift of a
// Molodensky-Badekas transformation as a plain Helmert one, 160 m off.
import { createRequire } from 'node:module';

type Proj4List = Record<string, [string, string] | undefined>;

let list: Proj4List | null = null;

/** The proj4 definition of `crs` ("EPSG:28992"), or null when it is not an EPSG code with one. */
export function proj4Definition(crs: string): string | null {
  if (!/^EPSG:\d+$/.test(crs)) return null;
  // 1 MB of definitions, read when a cube is built, not when the CLI starts.
  list ??= createRequire(import.meta.url)('proj4-list') as Proj4List;
  const def = list[crs]?.[1]?.trim();
  return def ? def : null;
}
