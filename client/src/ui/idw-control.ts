// Control points of an inverse-distance-weighted slicing surface, placed and dragged by the
// user: a click on the map places a point (with more detail than the view: a quarter of its
// scale), dragging moves it, the wheel over it changes its z, a double click removes it.
import { scaleAtZ, zAtScale } from '../../../format/scale.js';
import type { VarioMap } from '../vario-map.js';
import { SurfaceTool } from './surface-tool.js';

export interface IdwPoint {
  x: number;
  y: number;
  z: number;
}

const CLICK_SLOP_PX = 4;

export class IdwControl extends SurfaceTool {
  readonly points: IdwPoint[] = [];
  private readonly markers: HTMLElement[] = [];
  private down: { x: number; y: number; id: number } | null = null;

  constructor(public power = 2) {
    super('idw', 'Place control points of detail', '\u2022');
  }

  /** z given to a new point: the view's base z at a quarter of its scale (more detail). */
  newPointZ(): number {
    const meta = this.map?.getMetadata();
    if (!this.map || !meta) return 0;
    return zAtScale(meta, scaleAtZ(meta, this.map.getSliceZ()) / 4);
  }

  add(point: IdwPoint): void {
    this.points.push(point);
    const m = document.createElement('div');
    m.className = 'ssc-control-point';
    m.style.cssText = 'position:absolute;width:14px;height:14px;margin:-7px 0 0 -7px;border-radius:50%;background:#2a6fdb;border:2px solid #fff;box-shadow:0 0 2px #000;cursor:move;touch-action:none;box-sizing:border-box';
    m.addEventListener('pointerdown', (ev) => this.dragStart(ev, m));
    m.addEventListener('wheel', (ev) => this.onWheel(ev, m), { passive: false });
    m.addEventListener('dblclick', (ev) => {
      ev.stopPropagation();
      this.removeAt(this.markers.indexOf(m));
    });
    this.markers.push(m);
    if (this.map && this.enabled) this.map.getCanvasContainer().appendChild(m);
    this.update();
  }

  removeAt(i: number): void {
    if (i < 0 || i >= this.points.length) return;
    this.points.splice(i, 1);
    this.markers.splice(i, 1)[0]?.remove();
    this.update();
  }

  protected start(map: VarioMap): void {
    const cc = map.getCanvasContainer();
    cc.addEventListener('pointerdown', this.onDown);
    cc.addEventListener('pointerup', this.onUp);
    // Markers follow every frame drawn: moves, resizes and surface changes alike.
    map.on('render', this.place);
    for (const m of this.markers) cc.appendChild(m);
    if (this.points.length > 0) this.update();
  }

  protected stop(map: VarioMap): void {
    const cc = map.getCanvasContainer();
    cc.removeEventListener('pointerdown', this.onDown);
    cc.removeEventListener('pointerup', this.onUp);
    map.off('render', this.place);
    for (const m of this.markers) m.remove();
  }

  private update(): void {
    if (!this.map || !this.enabled) return;
    this.map.setSlicingSurface({ kind: 'idw', power: this.power, points: this.points.map((p) => ({ ...p })) });
    this.place();
  }

  private readonly place = (): void => {
    const map = this.map;
    if (!map) return;
    this.points.forEach((p, i) => {
      const m = this.markers[i];
      if (!m) return;
      const [x, y] = map.projectProjected([p.x, p.y]);
      m.style.left = `${x}px`;
      m.style.top = `${y}px`;
      m.title = `z ${p.z.toFixed(1)}`;
    });
  };

  private local(ev: MouseEvent): [number, number] {
    const r = this.map?.getCanvasContainer().getBoundingClientRect();
    return r ? [ev.clientX - r.left, ev.clientY - r.top] : [ev.clientX, ev.clientY];
  }

  private readonly onDown = (ev: PointerEvent): void => {
    if (ev.button !== 0) return;
    const [x, y] = this.local(ev);
    this.down = { x, y, id: ev.pointerId };
  };

  private readonly onUp = (ev: PointerEvent): void => {
    const d = this.down;
    this.down = null;
    if (!d || d.id !== ev.pointerId || !this.map) return;
    const [x, y] = this.local(ev);
    if (Math.hypot(x - d.x, y - d.y) > CLICK_SLOP_PX) return; // a drag, not a click
    const [gx, gy] = this.map.unprojectProjected([x, y]);
    this.add({ x: gx, y: gy, z: this.newPointZ() });
  };

  private dragStart(ev: PointerEvent, m: HTMLElement): void {
    if (ev.button !== 0) return;
    ev.preventDefault();
    ev.stopPropagation();
    m.setPointerCapture(ev.pointerId);
    const move = (e: PointerEvent): void => {
      // The map's handlers do not see a point's drag.
      e.stopPropagation();
      const p = this.points[this.markers.indexOf(m)];
      if (!p || !this.map) return;
      [p.x, p.y] = this.map.unprojectProjected(this.local(e));
      this.update();
    };
    const up = (e: PointerEvent): void => {
      move(e);
      m.releasePointerCapture(e.pointerId);
      m.removeEventListener('pointermove', move);
      m.removeEventListener('pointerup', up);
    };
    m.addEventListener('pointermove', move);
    m.addEventListener('pointerup', up);
  }

  private onWheel(ev: WheelEvent, m: HTMLElement): void {
    ev.preventDefault();
    ev.stopPropagation();
    const p = this.points[this.markers.indexOf(m)];
    const meta = this.map?.getMetadata();
    if (!p || !meta) return;
    // One wheel click changes the point's scale by a factor sqrt(2): up is more detail.
    p.z = zAtScale(meta, scaleAtZ(meta, p.z) * Math.SQRT2 ** Math.sign(ev.deltaY));
    this.update();
  }
}
