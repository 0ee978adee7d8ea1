// MapLibre's camera for a view of the vario map: the same ground at the same place. The map's
// scale denominator counts units of the cube's projected CRS per CSS pixel (a pixel being
// pixelSizeMm on paper); MapLibre's zoom counts web-mercator pixels: at zoom z the world's
// mercator width is 512 * 2^z CSS pixels (512-px tiles), whatever the latitude. Pure.
import proj4 from 'proj4';

export interface ProjectedView {
  center: [number, number];
  scale: number;
}

export interface LngLatView {
  center: [number, number];
  zoom: number;
}

/** Web mercator x, y in world widths (0..1). */
function mercator(lon: number, lat: number): [number, number] {
  const phi = (lat * Math.PI) / 180;
  return [(lon + 180) / 360, (1 - Math.log(Math.tan(Math.PI / 4 + phi / 2)) / Math.PI) / 2];
}

/**
 * A converter from views in the CRS of `proj4Def` to MapLibre's, for a viewport `widthPx` CSS
 * pixels wide. Both ends of the view's horizontal centre line are carried to longitude/latitude
 * and then to mercator; the zoom that fits that mercator length into widthPx pixels shows the
 * same ground at the centre. This takes in the CRS's own scale factor there (0.9999 for RD
 * New, 0.9996..1.0004 for UTM) as well as mercator's 1 / cos(latitude) stretch, which
 * zoomAtScale(scale, latitude) leaves out by taking a CRS unit for a metre on the ground.
 */
export function toMapLibreView(proj4Def: string, widthPx: number, pixelSizeMm: number): (v: ProjectedView) => LngLatView {
  const toLngLat = proj4(proj4Def, 'EPSG:4326');
  return ({ center: [x, y], scale }) => {
    const half = ((scale * pixelSizeMm) / 1000) * (widthPx / 2);
    const [lon, lat] = toLngLat.forward<[number, number]>([x, y]);
    const [ax, ay] = mercator(...(toLngLat.forward<[number, number]>([x - half, y])));
    const [bx, by] = mercator(...(toLngLat.forward<[number, number]>([x + half, y])));
    return { center: [lon, lat], zoom: Math.log2(widthPx / (512 * Math.hypot(bx - ax, by - ay))) };
  };
}
