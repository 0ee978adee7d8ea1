// The canvas the map draws on: made in the container, sized to whole device pixels and measured
// again when the container or the device pixel ratio changes.
import type { ViewGeometry } from '../geometry/view.js';
import type { MapView } from '../camera/map-view.js';

export class MapCanvas {
  readonly element: HTMLCanvasElement;
  private cssWidth = 0;
  private cssHeight = 0;
  private readonly resizeObserver: ResizeObserver;
  private dprQuery: MediaQueryList | null = null;

  /** `resized` runs when the canvas got a new size. */
  constructor(
    private readonly container: HTMLElement,
    private readonly pixelRatioOption: number | undefined,
    private readonly resized: () => void,
  ) {
    const c = document.createElement('canvas');
    c.className = 'ssc-canvas';
    // No touch-action of its own: the container's governs (cooperative gestures leave one finger to the page).
    c.style.cssText = 'position:absolute;left:0;top:0;width:100%;height:100%;display:block';
    container.appendChild(c);
    this.element = c;
    this.resizeObserver = new ResizeObserver(() => this.measure());
    this.resizeObserver.observe(container);
    this.watchPixelRatio();
  }

  /** Device pixels per CSS pixel asked for. */
  get pixelRatio(): number {
    return this.pixelRatioOption ?? window.devicePixelRatio ?? 1;
  }

  /** The exact ratio the canvas has: it is sized to whole device pixels. */
  deviceRatio(): number {
    return this.cssWidth > 0 ? this.element.width / this.cssWidth : this.pixelRatio;
  }

  deviceSize(): { width: number; height: number } {
    return { width: Math.max(1, this.element.width), height: Math.max(1, this.element.height) };
  }

  /** The view of `mapView` on this canvas, in device pixels (what the GPU draws). */
  geometry(mapView: MapView, camera = mapView.camera): ViewGeometry {
    const g = this.deviceSize();
    return mapView.geometry(g.width, g.height, this.deviceRatio(), camera);
  }

  /** Sizes the canvas to the container (the owner calls it once it is ready for `resized`). */
  measure(): void {
    const rect = this.container.getBoundingClientRect();
    const w = Math.max(1, rect.width), h = Math.max(1, rect.height);
    const dpr = this.pixelRatio;
    const c = this.element;
    const dw = Math.max(1, Math.round(w * dpr)), dh = Math.max(1, Math.round(h * dpr));
    if (w === this.cssWidth && h === this.cssHeight && dw === c.width && dh === c.height) return;
    this.cssWidth = w;
    this.cssHeight = h;
    c.width = dw;
    c.height = dh;
    this.resized();
  }

  remove(): void {
    this.resizeObserver.disconnect();
    this.dprQuery?.removeEventListener('change', this.onDprChange);
    this.element.remove();
  }

  private readonly onDprChange = (): void => {
    this.watchPixelRatio();
    this.measure();
  };

  private watchPixelRatio(): void {
    this.dprQuery?.removeEventListener('change', this.onDprChange);
    if (this.pixelRatioOption !== undefined || typeof matchMedia !== 'function') return;
    this.dprQuery = matchMedia(`(resolution: ${window.devicePixelRatio}dppx)`);
    this.dprQuery.addEventListener('change', this.onDprChange);
  }
}
