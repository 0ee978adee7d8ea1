// The library's public surface: the map, its controls, markers, popups and GeoJSON layers, the research tools,
// the scale helpers and longitude/latitude as MapLibre's. The builds start from bundle.ts,
// which adds the stylesheet; the type declarations (tsconfig.lib.json) from here.

export { VarioMap } from '../vario-map.js';
export type {
  AnimationOptions,
  Bbox,
  BlendingOptions,
  BlendMode,
  BoundaryOptions,
  Camera,
  CameraOptions,
  ClassStyleJson,
  Control,
  ControlPosition,
  CubeStyle,
  DrawnState,
  FaceFeature,
  Feature,
  FeatureRef,
  FeatureState,
  FitBoundsOptions,
  FlyToOptions,
  HandlerName,
  InteractionSettings,
  LineFeature,
  MapMoveEvent,
  MapPointerEvent,
  QueryOptions,
  SourceErrorInfo,
  StatePaint,
  StyleJson,
  SurfaceSpec,
  VarioMapEvents,
  VarioMapOptions,
  VarioMapSettings,
} from '../vario-map.js';
export type { Handler } from '../interaction/interaction-context.js';
export type { CubeMeta } from '../../../format/cube-index.js';
export { AttributionControl } from '../ui/attribution-control.js';
export { FullscreenControl, type FullscreenOptions } from '../ui/fullscreen-control.js';
export { IdwControl, type IdwPoint } from '../ui/idw-control.js';
export { LegendControl, type LegendOptions } from '../ui/legend-control.js';
export { LensControl, type LensOptions } from '../ui/lens-control.js';
export { ScaleBar } from '../ui/scale-bar.js';
export { SettingsPanel, type SurfaceMode } from '../ui/settings-panel.js';
export { ZoomControl } from '../ui/zoom-control.js';
export { InteractionLog, type LogEntry } from '../research/interaction-log.js';
export { scaleAtZoom, zoomAtScale } from '../geometry/zoom-levels.js';
export { LngLat, type LngLatLike } from '../geo/lng-lat.js';
export { LngLatBounds, type LngLatBoundsLike } from '../geo/lng-lat-bounds.js';
export { CrsError } from '../geo/crs-transform.js';
export { Marker, type MarkerOptions } from '../overlay/marker.js';
export { Popup, type PopupEvents, type PopupOptions } from '../overlay/popup.js';
export type { Anchor, Offset } from '../overlay/overlay-position.js';
export { GeoJsonLayer, type GeoJsonLayerEvent, type GeoJsonLayerEvents, type GeoJsonLayerEventType, type GeoJsonLayerOptions } from '../overlay/geojson-layer.js';
export { DEFAULT_GEOJSON_PAINT, type GeoJsonPaint } from '../overlay/geojson-paint.js';
export { GeoJsonError, type GeoJsonData, type GeoJsonFeature, type GeoJsonFeatureCollection, type GeoJsonGeometry, type Position } from '../overlay/geojson-read.js';
export type { PointerPlace } from '../overlay/overlay-stack.js';
