// Reads a FlatGeobuf file as GeoJSON features in file order (through the `flatgeobuf` package),
// with the CRS from its header.
import { deserialize } from 'flatgeobuf/lib/mjs/geojson.js';
import type { HeaderMeta } from 'flatgeobuf';
import { brokenFileError, type FeatureDocument } from './input-format.js';

export async function readFlatgeobuf(buf: Buffer, file: string): Promise<FeatureDocument> {
  let header: HeaderMeta | undefined;
  const features: unknown[] = [];
  try {
    const bytes = new Uint8Array(buf.buffer, buf.byteOffset, buf.byteLength);
    for await (const f of deserialize(bytes, { headerMetaFn: (h: HeaderMeta) => { header = h; } })) {
      // A FlatGeobuf feature leaves out its null fields; GeoJSON (as GDAL writes it) has them as null.
      const props = f.properties ?? {};
      const properties: Record<string, unknown> = {};
      for (const c of header?.columns ?? []) properties[c.name] = props[c.name] ?? null;
      for (const [k, v] of Object.entries(props)) if (!(k in properties)) properties[k] = v;
      features.push({ type: 'Feature', properties, geometry: f.geometry });
    }
  } catch (err) {
    // Where the library stumbles on a cut file, how far it got says more than its own words.
    const got = header && header.featuresCount > 0 ? new Error(`it breaks off after ${features.length} of the ${header.featuresCount} features its header announces`) : err;
    throw brokenFileError(file, 'flatgeobuf', got);
  }
  if (header && header.featuresCount > 0 && features.length !== header.featuresCount) {
    throw brokenFileError(file, 'flatgeobuf', new Error(`its header announces ${header.featuresCount} features, it holds ${features.length}`));
  }
  return { type: 'FeatureCollection', crs: headerCrs(header), features };
}

/** The header's CRS as a GeoJSON-style member. Its organisation, when not given, is EPSG (the spec). */
function headerCrs(header: HeaderMeta | undefined): unknown {
  const crs = header?.crs;
  if (!crs) return null;
  if ((crs.org === null || crs.org.toUpperCase() === 'EPSG') && crs.code > 0) return { type: 'name', properties: { name: `EPSG:${crs.code}` } };
  if (crs.wkt) return { type: 'wkt', properties: { wkt: crs.wkt } };
  if (crs.code_string) return { type: 'name', properties: { name: crs.code_string } };
  if (crs.org && crs.code > 0) return { type: 'name', properties: { name: `${crs.org}:${crs.code}` } };
  return null;
}
