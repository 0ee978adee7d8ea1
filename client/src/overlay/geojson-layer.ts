// GeoJsonLayer: points, lines and polygons from GeoJSON drawn over the map in WebGL (as circles,
// lines and fills with a simple paint), with click and hover events, in the manner of Leaflet's
// L.geoJSON and of a MapLibre GeoJSON source with its layers. The data is checked when given,
// projected to the cube's CRS once the cube is known, and uploaded once: the GPU applies the
// view, so the layer moves with the map through every animation.
import type { CubeMeta } from '../../../format/cube-index.js';
import { Evented } from '../events.js';
import { CrsError } from '../geo/crs-transform.js';
import { LngLat } from '../geo/lng-lat.js';
import type { OverlayPaintParams } from '../render/overlay-pass.js';
import type { VarioMap } from '../vario-map.js';
import { DEFAULT_GEOJSON_PAINT, mergePaint, paintParams, type GeoJsonPaint } from './geojson-paint.js';
import { emptyParts, GeoJsonError, mapParts, readGeoJson, type GeoJsonData, type GeoJsonFeature, type Parts, type ReadFeature, type XY } from './geojson-read.js';
import type { LayerGeometry } from './layer-geometry.js';
import { OverlayStack, type PointerPlace, type StackedLayer } from './overlay-stack.js';

export interface GeoJsonLayerOptions {
  /** GeoJSON in longitude/latitude (RFC 7946): a FeatureCollection, a Feature or a geometry. */
  data?: GeoJsonData;
  /** The same in the cube's projected CRS, instead of `data`. */
  dataProjected?: GeoJsonData;
  paint?: Partial<GeoJsonPaint>;
  /** Fires click and hover events and shows a pointer cursor over its features (default true). */
  interactive?: boolean;
  /** CSS px around lines and circles that still count as on them (default 3). */
  hitTolerance?: number;
}

export type GeoJsonLayerEventType = 'click' | 'mouseenter' | 'mousemove' | 'mouseleave';

export interface GeoJsonLayerEvent extends PointerPlace {
  type: GeoJsonLayerEventType;
  target: GeoJsonLayer;
  /** The layer's features under the pointer, topmost first (the GeoJSON features given); [] on mouseleave. */
  features: GeoJsonFeature[];
}

export interface GeoJsonLayerEvents {
  click: GeoJsonLayerEvent;
  mouseenter: GeoJsonLayerEvent;
  mousemove: GeoJsonLayerEvent;
  mouseleave: GeoJsonLayerEvent;
  /**
   * The data could not be projected when the cube became known (setData throws instead once it
   * is), or the layer's code (loaded with the page's first layer) could not be loaded.
   */
  error: { error: Error };
}

const POINTER_EVENTS: GeoJsonLayerEventType[] = ['click', 'mouseenter', 'mousemove', 'mouseleave'];

/** The data as given, read, and in the cube's CRS once known. */
interface Source {
  given: GeoJsonData;
  read: ReadFeature[];
  lngLat: boolean;
  /** Null until projected on a map whose cube is known (and the geometry code has loaded). */
  projected: LayerGeometry | null;
}

type GeometryModule = typeof import('./layer-geometry.js');

/** The geometry code, once loaded: layers project at once from then on. */
let geometryModule: GeometryModule | null = null;
let geometryLoading: Promise<GeometryModule> | null = null;

/** The geometry code, loaded once for every layer of the page. */
function loadGeometry(): Promise<GeometryModule> {
  geometryLoading ??= import('./layer-geometry.js').then(
    (m) => (geometryModule = m),
    (err: unknown) => {
      // A later layer tries again (the network may be back).
      geometryLoading = null;
      throw err;
    },
  );
  return geometryLoading;
}

export class GeoJsonLayer extends Evented<GeoJsonLayerEvents> {
  private map: VarioMap | null = null;
  private stack: OverlayStack | null = null;
  private source: Source;
  private paint: GeoJsonPaint;
  private params: OverlayPaintParams;
  private readonly interactive: boolean;
  private readonly tolerance: number;
  /** The pointer is over one of its features (mouseenter fired, mouseleave not yet). */
  private hovering = false;
  /** What the map's overlay stack sees of the layer (not public). */
  private readonly stacked: StackedLayer;

  constructor(options: GeoJsonLayerOptions = {}) {
    super();
    if (options.data !== undefined && options.dataProjected !== undefined) throw new Error('GeoJsonLayer: give data (longitude/latitude) or dataProjected, not both');
    this.paint = mergePaint(DEFAULT_GEOJSON_PAINT, options.paint ?? {}, 'GeoJsonLayer paint');
    this.params = paintParams(this.paint);
    this.interactive = options.interactive ?? true;
    this.tolerance = options.hitTolerance ?? 3;
    if (!(this.tolerance >= 0)) throw new Error(`GeoJsonLayer: hitTolerance must be a number of CSS px >= 0, not ${options.hitTolerance}`);
    const empty: GeoJsonData = { type: 'FeatureCollection', features: [] };
    this.source = options.dataProjected !== undefined ? this.read(options.dataProjected, false, 'GeoJsonLayer dataProjected') : this.read(options.data ?? empty, true, 'GeoJsonLayer data');
    this.stacked = {
      drawable: () => ({ mesh: this.source.projected?.mesh ?? null, paint: this.params }),
      hover: (place, left) => this.hover(place, left),
      click: (place) => this.click(place),
      detached: () => this.detach(),
    };
  }

  /** Draws it over the map, on top of the layers added before. Throws if its data cannot be projected to the cube's CRS. */
  addTo(map: VarioMap): this {
    this.remove();
    const stack = OverlayStack.of(map);
    const meta = map.getMetadata();
    // Projected first: data the cube's CRS cannot take leaves the layer off the map.
    if (meta) this.project(this.source, meta, stack, 'GeoJsonLayer addTo');
    else map.on('meta', this.onMeta);
    this.map = map;
    this.stack = stack;
    stack.add(this.stacked);
    return this;
  }

  remove(): this {
    const map = this.map;
    if (!map) return this;
    map.off('meta', this.onMeta);
    this.stack?.remove(this.stacked);
    this.detach();
    return this;
  }

  /** New data in longitude/latitude; throws a GeoJsonError naming every problem (the layer keeps its data then). */
  setData(data: GeoJsonData): this {
    return this.replace(this.read(data, true, 'GeoJsonLayer setData'));
  }

  /** New data in the cube's projected CRS. */
  setDataProjected(data: GeoJsonData): this {
    return this.replace(this.read(data, false, 'GeoJsonLayer setDataProjected'));
  }

  /** The data as last given. */
  getData(): GeoJsonData {
    return this.source.given;
  }

  /** Changes some paint properties; throws naming every wrong value (the paint stays as it was then). */
  setPaint(paint: Partial<GeoJsonPaint>): this {
    this.paint = mergePaint(this.paint, paint, 'GeoJsonLayer setPaint');
    this.params = paintParams(this.paint);
    this.stack?.changed();
    return this;
  }

  getPaint(): GeoJsonPaint {
    return { ...this.paint };
  }

  /** The features drawn under a CSS px point of the map, topmost first (whether interactive or not). */
  queryFeatures(point: [number, number]): GeoJsonFeature[] {
    const map = this.map;
    const hits = this.source.projected?.hits;
    if (!map || !hits) return [];
    const at = map.unprojectProjected(point);
    const right = map.unprojectProjected([point[0] + 1, point[1]]);
    const p = this.paint;
    const indices = hits.at(at, {
      resolution: Math.hypot(right[0] - at[0], right[1] - at[1]),
      lineHalfWidth: p.lineWidth / 2,
      circleRadius: p.circleRadius + p.circleStrokeWidth,
      tolerance: this.tolerance,
      outlines: p.lineWidth > 0,
    });
    return indices.map((i) => this.source.read[i]!.feature);
  }

  private read(data: GeoJsonData, lngLat: boolean, what: string): Source {
    return { given: data, read: readGeoJson(data, lngLat, what), lngLat, projected: null };
  }

  private replace(source: Source): this {
    const meta = this.map?.getMetadata();
    if (meta && this.stack) this.project(source, meta, this.stack, source.lngLat ? 'GeoJsonLayer setData' : 'GeoJsonLayer setDataProjected');
    this.source = source;
    this.stack?.changed();
    return this;
  }

  /** Projects the source to the cube's CRS and makes its mesh; a GeoJsonError names every position that cannot be. */
  private project(source: Source, meta: CubeMeta, stack: OverlayStack, what: string): void {
    let to: (xy: XY) => XY = (xy) => xy;
    if (source.lngLat) {
      const crs = stack.toProjected();
      to = (xy) => crs.toProjected(new LngLat(xy[0], xy[1]));
    }
    const problems: string[] = [];
    const parts = source.read.map((r): Parts => {
      try {
        return mapParts(r.parts, to);
      } catch (err) {
        if (!(err instanceof CrsError)) throw err;
        problems.push(`${r.name}: ${err.message}`);
        return emptyParts();
      }
    });
    if (problems.length > 0) throw new GeoJsonError(`${what} (the cube's CRS is ${meta.crs ?? 'not named'})`, problems);
    if (geometryModule) {
      source.projected = geometryModule.layerGeometry(parts);
      return;
    }
    // The first layer of the page: the map waits for the geometry code before it goes idle, and
    // draws the layer when it has come, unless the layer has new data or left the map by then.
    const loaded = loadGeometry()
      .then((m) => {
        if (this.source !== source || this.stack !== stack) return;
        source.projected = m.layerGeometry(parts);
        stack.changed();
      })
      // The browser's message names the file that did not come. A layer that has new data or
      // left the map meanwhile reports its own attempt, if any.
      .catch((err: unknown) => {
        if (this.source === source && this.stack === stack) this.report(new Error(`${what}: ${err instanceof Error ? err.message : String(err)}`));
      });
    stack.holdIdle(loaded);
  }

  private readonly onMeta = (meta: CubeMeta): void => {
    if (!this.stack) return;
    try {
      this.project(this.source, meta, this.stack, 'GeoJsonLayer');
    } catch (err) {
      this.report(err instanceof Error ? err : new Error(String(err)));
    }
    this.stack?.changed();
  };

  private report(error: Error): void {
    // As MapLibre's Evented: an error nobody listens for goes to the console.
    if (this.listens('error')) this.fire('error', { error });
    else console.error(error);
  }

  private detach(): void {
    this.map = null;
    this.stack = null;
    this.hovering = false;
    if (this.source.lngLat) this.source.projected = null;
  }

  /** Listens for pointer events: hit tests are worth doing and the cursor shows it. */
  private answersPointer(): boolean {
    return this.interactive && POINTER_EVENTS.some((t) => this.listens(t));
  }

  private event(type: GeoJsonLayerEventType, place: PointerPlace, features: GeoJsonFeature[]): GeoJsonLayerEvent {
    return { type, target: this, features, ...place };
  }

  private hover(place: PointerPlace, left: boolean): boolean {
    if (!this.answersPointer()) return false;
    const features = left ? [] : this.queryFeatures(place.point);
    if (features.length > 0) {
      if (!this.hovering) {
        this.hovering = true;
        this.fire('mouseenter', this.event('mouseenter', place, features));
      }
      this.fire('mousemove', this.event('mousemove', place, features));
      return true;
    }
    if (this.hovering) {
      this.hovering = false;
      this.fire('mouseleave', this.event('mouseleave', place, []));
    }
    return false;
  }

  private click(place: PointerPlace): void {
    if (!this.interactive || !this.listens('click')) return;
    const features = this.queryFeatures(place.point);
    if (features.length > 0) this.fire('click', this.event('click', place, features));
  }
}
