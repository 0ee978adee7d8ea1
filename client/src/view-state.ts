// Where the map looks: the centre (ground coordinates), the scale denominator, the base z of the
// slice (following the scale, or pinned), and the slicing surface around it. From these: the
// view in device pixels and the box and z range to ask the index for.
import type { CubeMeta } from '../../format/cube-index.js';
import { zAtScale, type ScaleInfo } from '../../format/scale.js';
import { surfaceRange, type Surface, type SurfaceSpec } from '../../format/slicing-surface.js';
import { growBbox, resolutionAtScale, viewBbox, type Bbox, type ViewGeometry } from './shared/view.js';
import { PIXEL_SIZE_MM } from '../../format/pixel-size.js';

export interface ViewQuery {
  view: ViewGeometry;
  visible: Bbox;
  /** The visible box with the prefetch margin. */
  margin: Bbox;
  /** z range of the surface over the margin box. */
  zMin: number;
  zMax: number;
  /** Base z. */
  z: number;
}

export class ViewState {
  centerX = NaN;
  centerY = NaN;
  scale = NaN;
  zPinned: number | null = null;
  spec: SurfaceSpec = { kind: 'flat' };
  meta: CubeMeta | null = null;
  scaleInfo: ScaleInfo | null = null;

  setMeta(meta: CubeMeta): void {
    this.meta = meta;
    this.scaleInfo = { baseScale: meta.baseScale, baseFaces: meta.baseFaces, scaleTable: meta.scaleTable, zMax: meta.zMax };
  }

  get pixelSizeMm(): number {
    return this.meta?.pixelSizeMm ?? PIXEL_SIZE_MM;
  }

  /** The base z of the slice (steps). */
  z(): number {
    if (this.zPinned !== null) return this.zPinned;
    if (!this.scaleInfo || !Number.isFinite(this.scale)) return 0;
    return zAtScale(this.scaleInfo, this.scale);
  }

  surface(): Surface {
    return { base: this.z(), spec: this.spec };
  }

  /** The view on a canvas of the given device pixels, `ratio` device pixels per CSS pixel. */
  geometry(width: number, height: number, ratio: number): ViewGeometry {
    return { centerX: this.centerX, centerY: this.centerY, resolution: resolutionAtScale(this.scale, this.pixelSizeMm) / ratio, width, height };
  }

  /** Centre and scale that show `bbox` whole on such a canvas (square pixels, centred). */
  fit(bbox: Bbox, width: number, height: number, ratio: number): void {
    const deviceRes = Math.max((bbox[2] - bbox[0]) / width, (bbox[3] - bbox[1]) / height);
    this.centerX = (bbox[0] + bbox[2]) / 2;
    this.centerY = (bbox[1] + bbox[3]) / 2;
    this.scale = (deviceRes * ratio * 1000) / this.pixelSizeMm;
  }

  query(view: ViewGeometry, marginFactor: number): ViewQuery {
    const visible = viewBbox(view);
    const margin = growBbox(visible, marginFactor);
    const [zMin, zMax] = surfaceRange(this.surface(), margin, this.meta?.zMax ?? 0);
    return { view, visible, margin, zMin, zMax, z: this.z() };
  }
}
