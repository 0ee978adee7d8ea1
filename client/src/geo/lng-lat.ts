// Longitude/latitude as MapLibre GL JS gives and takes them: LngLat, and LngLatLike for what a
// caller may pass ([lng, lat], { lng, lat }, { lon, lat }). Pure.

export type LngLatLike = LngLat | { lng: number; lat: number } | { lon: number; lat: number } | [number, number];

export class LngLat {
  lng: number;
  lat: number;

  constructor(lng: number, lat: number) {
    if (!Number.isFinite(lng) || !Number.isFinite(lat)) throw new Error(`Invalid LngLat (${lng}, ${lat}): longitude and latitude must be finite numbers`);
    if (lat < -90 || lat > 90) throw new Error(`Invalid LngLat (${lng}, ${lat}): latitude must be between -90 and 90 degrees`);
    this.lng = lng;
    this.lat = lat;
  }

  toArray(): [number, number] {
    return [this.lng, this.lat];
  }

  toString(): string {
    return `LngLat(${this.lng}, ${this.lat})`;
  }

  /** A LngLat from any LngLatLike; a clear error for anything else. */
  static convert(input: LngLatLike): LngLat {
    if (input instanceof LngLat) return input;
    if (Array.isArray(input)) {
      if (input.length === 2) return new LngLat(Number(input[0]), Number(input[1]));
    } else if (typeof input === 'object' && input !== null && 'lat' in input) {
      const lng = 'lng' in input ? input.lng : 'lon' in input ? input.lon : undefined;
      if (lng !== undefined) return new LngLat(Number(lng), Number(input.lat));
    }
    throw new Error(`Invalid LngLatLike ${JSON.stringify(input)}: give [lng, lat], { lng, lat } or { lon, lat } in degrees`);
  }
}
