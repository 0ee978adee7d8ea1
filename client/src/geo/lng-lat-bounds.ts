// A longitude/latitude box as MapLibre GL JS's LngLatBounds: south-west and north-east corners;
// LngLatBoundsLike for what a caller may pass. Pure.
import { LngLat, type LngLatLike } from './lng-lat.js';

export type LngLatBoundsLike = LngLatBounds | [LngLatLike, LngLatLike] | [number, number, number, number];

export class LngLatBounds {
  private readonly sw: LngLat;
  private readonly ne: LngLat;

  constructor(sw: LngLatLike, ne: LngLatLike) {
    this.sw = LngLat.convert(sw);
    this.ne = LngLat.convert(ne);
    if (this.sw.lat > this.ne.lat) throw new Error(`Invalid LngLatBounds: the south (${this.sw.lat}) is north of the north (${this.ne.lat})`);
  }

  getSouthWest(): LngLat {
    return this.sw;
  }

  getNorthEast(): LngLat {
    return this.ne;
  }

  getNorthWest(): LngLat {
    return new LngLat(this.sw.lng, this.ne.lat);
  }

  getSouthEast(): LngLat {
    return new LngLat(this.ne.lng, this.sw.lat);
  }

  getWest(): number {
    return this.sw.lng;
  }

  getSouth(): number {
    return this.sw.lat;
  }

  getEast(): number {
    return this.ne.lng;
  }

  getNorth(): number {
    return this.ne.lat;
  }

  getCenter(): LngLat {
    return new LngLat((this.sw.lng + this.ne.lng) / 2, (this.sw.lat + this.ne.lat) / 2);
  }

  contains(p: LngLatLike): boolean {
    const q = LngLat.convert(p);
    return q.lng >= this.sw.lng && q.lng <= this.ne.lng && q.lat >= this.sw.lat && q.lat <= this.ne.lat;
  }

  /** [[west, south], [east, north]], as MapLibre's. */
  toArray(): [[number, number], [number, number]] {
    return [this.sw.toArray(), this.ne.toArray()];
  }

  toString(): string {
    return `LngLatBounds(${this.sw.toString()}, ${this.ne.toString()})`;
  }

  static convert(input: LngLatBoundsLike): LngLatBounds {
    if (input instanceof LngLatBounds) return input;
    if (Array.isArray(input) && input.length === 4) return new LngLatBounds([input[0], input[1]], [input[2], input[3]]);
    if (Array.isArray(input) && input.length === 2) return new LngLatBounds(input[0], input[1]);
    throw new Error(`Invalid LngLatBoundsLike ${JSON.stringify(input)}: give [west, south, east, north], [[west, south], [east, north]] or a LngLatBounds`);
  }
}
