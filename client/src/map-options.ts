// The types of VarioMap's public API: its options, events and camera options.
import type { SurfaceSpec } from '../../format/slicing-surface.js';
import type { CubeStyle, StyleJson } from '../../format/style.js';
import type { Bbox } from './geometry/view.js';
import type { EngineEvents, EngineOptions } from './engine/map-engine.js';
import type { LngLatLike } from './geo/lng-lat.js';
import type { LngLatBoundsLike } from './geo/lng-lat-bounds.js';
import type { MapPointerEvent } from './interaction/feature-events.js';
import type { HandlerFlags } from './interaction/handlers.js';
import type { InteractionSettings } from './interaction/interaction-context.js';
import type { Easing } from './motion/easing.js';

export interface VarioMapOptions extends Partial<HandlerFlags>, Omit<EngineOptions, 'source' | 'uploadBytesPerFrame'> {
  container: HTMLElement | string;
  /** URL of the cube's index.json (a path ending in .json), or of its directory (with or without a trailing /). */
  source: string;
  /** The centre, longitude/latitude (default: the centre of `bounds`, or of the extent). */
  center?: LngLatLike;
  /** The centre in the cube's projected CRS, instead of `center`. */
  centerProjected?: [number, number];
  /** Instead of the whole extent: the longitude/latitude box the first view shows whole. */
  bounds?: LngLatBoundsLike;
  /** The same in the cube's projected CRS: x0, y0, x1, y1. */
  boundsProjected?: Bbox;
  /** Scale denominator; or `zoom`, MapLibre's zoom at the centre's latitude. Default: `bounds` (or the extent) fits. */
  scaleDenominator?: number;
  zoom?: number;
  /** Pins the slice's base z (steps) instead of following the scale. */
  sliceZ?: number | null;
  /** The slicing surface (default flat). */
  surface?: SurfaceSpec | string;
  /** Smallest scale denominator (most detail) and largest; defaults: a quarter of the base scale, 4x the extent. */
  minScale?: number;
  maxScale?: number;
  /** The longitude/latitude box the visible area stays inside (the projected box around it): no pan or zoom out leaves it. */
  maxBounds?: LngLatBoundsLike;
  /** The same in the cube's projected CRS: x0, y0, x1, y1. */
  maxBoundsProjected?: Bbox;
  /**
   * The style to draw instead of the cube's own, as `setStyle` takes it, from the first frame.
   * One that does not fit the cube is not drawn: an 'error' event (kind 'style') says why.
   */
  style?: StyleJson;
  /** A map inside a page that scrolls: the wheel zooms only with Ctrl (or ⌘), one finger scrolls the page and two move the map. */
  cooperativeGestures?: boolean;
  /** false turns every input handler off. */
  interactive?: boolean;
  /** Keeps the view in the URL's hash as MapLibre's `hash` option does (#zoom/lat/lng). */
  hash?: boolean;
  /** Replace animations with jumps; default: the user's prefers-reduced-motion. */
  reduceMotion?: boolean;
  /** Factor of the scale per zoom step (default 2). */
  zoomStep?: number;
  /** ms of a zoom step's animation (default 300; 0: none). */
  zoomDuration?: number;
  /** ms of keyboard pans (default 300; 0: none, and no inertia). */
  panDuration?: number;
  /** A zoom step shows at least this many slices, however slow the frames (default 12). */
  minZoomFrames?: number;
  /** The comparison mode: content only at a few discrete scales, as a classic multi-scale map. */
  comparisonMode?: boolean;
  /** Factor between the comparison mode's scales (default 2). */
  comparisonFactor?: number;
  /** The canvas container's accessible name (default "Map"). */
  ariaLabel?: string;
  /** Shows the dataset's attribution (default true). */
  attributionControl?: boolean;
}

export interface MapMoveEvent {
  /** The input that caused it, when one did. */
  originalEvent?: Event;
}

export interface VarioMapSettings extends InteractionSettings {
  comparisonMode: boolean;
}

/** Passed on from the engine as they are. */
export type DataEvents = Pick<EngineEvents, 'load' | 'complete' | 'idle' | 'error' | 'contextlost' | 'contextrestored' | 'dataloading' | 'data' | 'meta'>;

export interface VarioMapEvents extends DataEvents {
  movestart: MapMoveEvent;
  move: MapMoveEvent;
  moveend: MapMoveEvent;
  zoomstart: MapMoveEvent;
  zoom: MapMoveEvent;
  zoomend: MapMoveEvent;
  click: MapPointerEvent;
  pointermove: MapPointerEvent;
  /** Every frame drawn: its slice's base z and scale. */
  render: { frame: number; z: number; scaleDenominator: number; triangles: number };
  /** The settings changed (setSettings, setBlending). */
  settings: VarioMapSettings;
  /** The slicing surface changed. */
  surface: SurfaceSpec;
  /** The style drawn is known (after 'meta') or changed (setStyle, setClassStyle). */
  style: CubeStyle;
  remove: Record<string, never>;
}

export interface CameraOptions {
  /** Longitude/latitude. */
  center?: LngLatLike | undefined;
  /** The centre in the cube's projected CRS, instead of `center`. */
  centerProjected?: [number, number] | undefined;
  scaleDenominator?: number | undefined;
  /** MapLibre's zoom at the latitude of the new centre. */
  zoom?: number | undefined;
  /** Pins the slice's base z (steps); null: it follows the scale again. Taken at the start. */
  sliceZ?: number | null;
}

export interface FitBoundsOptions extends AnimationOptions {
  /** CSS px kept free around the box. */
  padding?: number;
  sliceZ?: number | null;
}

export interface AnimationOptions {
  /** ms; 0 jumps (at once, before the call returns). */
  duration?: number;
  easing?: Easing;
}

export interface FlyToOptions extends CameraOptions {
  /** Path length per second (default 1.2, as MapLibre); `duration` wins when given. */
  speed?: number;
  duration?: number;
  /** Curvature of the path (default 1.42). */
  rho?: number;
  easing?: Easing;
}
