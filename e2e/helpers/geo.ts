// Longitude/latitude and MapLibre's zoom computed in Node, apart from the map's own code: the
// test data's CRS, EPSG:28992 (Amersfoort / RD New), written out here from the EPSG dataset's
// parameters (GDAL's proj4 text), not read from the cube.
import proj4 from 'proj4';

export const RD_NEW = '+proj=sterea +lat_0=52.15616055555555 +lon_0=5.38763888888889 +k=0.9999079 +x_0=155000 +y_0=463000 +ellps=bessel +towgs84=565.417,50.3319,465.552,-0.398957,0.343988,-1.8774,4.0725 +units=m +no_defs';

const rd = proj4('EPSG:4326', RD_NEW);

export function rdToLngLat(xy: [number, number]): [number, number] {
  const [lng, lat] = rd.inverse([xy[0], xy[1]]);
  return [lng, lat];
}

export function lngLatToRd(lngLat: [number, number]): [number, number] {
  const [x, y] = rd.forward([lngLat[0], lngLat[1]]);
  return [x, y];
}

/** MapLibre GL JS's zoom where a CSS pixel covers `metresPerPixel` at `latitude`: 512-px web mercator tiles. */
export function mapLibreZoom(metresPerPixel: number, latitude: number): number {
  return Math.log2((40075016.686 * Math.cos((latitude * Math.PI) / 180)) / (512 * metresPerPixel));
}
