// The places of a refused input's problems as GeoJSON points, to open beside the data in a
// GIS (QGIS): one point per problem that has a place, with its kind, feature and message.
import { PROBLEM_KINDS, type InputProblems } from './problems.js';

export function problemsGeoJson(err: InputProblems): string {
  const features = err.problems.filter((p) => p.location).map((p) => ({
    type: 'Feature',
    properties: {
      kind: PROBLEM_KINDS[p.kind],
      feature: p.feature?.index ?? null,
      id: p.feature?.id ?? null,
      message: p.message,
    },
    geometry: { type: 'Point', coordinates: p.location },
  }));
  return JSON.stringify({
    type: 'FeatureCollection',
    // Without a crs member GeoJSON is longitude/latitude, as the input was when it had none.
    ...(err.crs ? { crs: { type: 'name', properties: { name: crsUrn(err.crs) } } } : {}),
    features,
  }, null, 1) + '\n';
}

/** EPSG:28992 -> urn:ogc:def:crs:EPSG::28992 (the form GDAL and QGIS read from GeoJSON). */
function crsUrn(code: string): string {
  const m = /^EPSG:(\d+)$/i.exec(code);
  return m ? `urn:ogc:def:crs:EPSG::${m[1]}` : code;
}
