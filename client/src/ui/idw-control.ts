// Control points of an inverse-distance-weighted slicing surface, placed and dragged by the
// user: a click on the map places a point (with more detail than the view: a quarter of its
// scale), dragging moves it, the wheel over it changes its z, a double click removes it.
import type { SliceMap } from '../slice-map.js';
import { scaleAtZ, zAtScale } from '../../../format/scale.js';
import { groundToPixel } from '../shared/view.js';

export interface IdwPoint {
  x: number;
  y: number;
  z: number;
}

const CLICK_SLOP_PX = 4;

export class IdwControl {
  readonly points: IdwPoint[] = [];
  private readonly markers: HTMLElement[] = [];
  private enabled = false;
  private down: { x: number; y: number; id: number } | null = null;

  constructor(
    private readonly map: SliceMap,
    public power = 2,
  ) {}

  enable(): this {
    if (this.enabled) return this;
    this.enabled = true;
    this.map.canvas.addEventListener('pointerdown', this.onDown);
    this.map.canvas.addEventListener('pointerup', this.onUp);
    this.map.on('move', this.place);
    return this;
  }

  disable(): this {
    this.enabled = false;
    this.map.canvas.removeEventListener('pointerdown', this.onDown);
    this.map.canvas.removeEventListener('pointerup', this.onUp);
    this.map.off('move', this.place);
    return this;
  }

  /** z given to a new point: the view's base z at a quarter of its scale (more detail). */
  newPointZ(): number {
    const meta = this.map.cubeMeta;
    if (!meta) return 0;
    const info = { baseScale: meta.baseScale, baseFaces: meta.baseFaces, scaleTable: meta.scaleTable, zMax: meta.zMax };
    return zAtScale(info, scaleAtZ(info, this.map.getZ()) / 4);
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
    this.map.container.appendChild(m);
    this.markers.push(m);
    this.update();
  }

  removeAt(i: number): void {
    if (i < 0 || i >= this.points.length) return;
    this.points.splice(i, 1);
    this.markers.splice(i, 1)[0]!.remove();
    this.update();
  }

  private update(): void {
    this.map.setSurface({ kind: 'idw', power: this.power, points: this.points.map((p) => ({ ...p })) });
    this.place();
  }

  private readonly place = (): void => {
    const view = this.map.getView();
    const ratio = view.width / Math.max(1, this.map.container.getBoundingClientRect().width);
    this.points.forEach((p, i) => {
      const [px, py] = groundToPixel(view, p.x, p.y);
      const m = this.markers[i]!;
      m.style.left = `${px / ratio}px`;
      m.style.top = `${py / ratio}px`;
      m.title = `z ${p.z.toFixed(1)}`;
    });
  };

  private local(ev: MouseEvent): [number, number] {
    const rect = this.map.container.getBoundingClientRect();
    return [ev.clientX - rect.left, ev.clientY - rect.top];
  }

  private readonly onDown = (ev: PointerEvent): void => {
    if (ev.button !== 0) return;
    const [x, y] = this.local(ev);
    this.down = { x, y, id: ev.pointerId };
  };

  private readonly onUp = (ev: PointerEvent): void => {
    const d = this.down;
    this.down = null;
    if (!d || d.id !== ev.pointerId) return;
    const [x, y] = this.local(ev);
    if (Math.hypot(x - d.x, y - d.y) > CLICK_SLOP_PX) return; // a drag, not a click
    const [gx, gy] = this.map.unproject([x, y]);
    this.add({ x: gx, y: gy, z: this.newPointZ() });
  };

  private dragStart(ev: PointerEvent, m: HTMLElement): void {
    if (ev.button !== 0) return;
    ev.preventDefault();
    ev.stopPropagation();
    m.setPointerCapture(ev.pointerId);
    const move = (e: PointerEvent): void => {
      const i = this.markers.indexOf(m);
      if (i < 0) return;
      const [gx, gy] = this.map.unproject(this.local(e));
      this.points[i]!.x = gx;
      this.points[i]!.y = gy;
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
    const i = this.markers.indexOf(m);
    const meta = this.map.cubeMeta;
    if (i < 0 || !meta) return;
    // One wheel click changes the point's scale by a factor sqrt(2): up is more detail.
    const info = { baseScale: meta.baseScale, baseFaces: meta.baseFaces, scaleTable: meta.scaleTable, zMax: meta.zMax };
    const factor = Math.SQRT2 ** Math.sign(ev.deltaY);
    this.points[i]!.z = zAtScale(info, scaleAtZ(info, this.points[i]!.z) * factor);
    this.update();
  }
}
