// For usability research: a timestamped log of where the map looked (centre, scale
// denominator, slice z) and of the input that moved it (wheel, pointer, keys, buttons), and of
// settings changes, as the seed paper's study recorded; exported as JSON or CSV.
import type { VarioMap } from '../vario-map.js';

export interface LogEntry {
  /** ms since the log started. */
  t: number;
  kind: 'view' | 'input' | 'settings';
  x: number;
  y: number;
  scale: number;
  z: number;
  /** For input: the event type (wheel, pointerdown, keydown, button, ...). */
  event: string;
  /** For input: the key, the wheel delta, the pointer position or the button; for settings: them as JSON. */
  detail: string;
}

const CSV_COLUMNS: (keyof LogEntry)[] = ['t', 'kind', 'x', 'y', 'scale', 'z', 'event', 'detail'];

export class InteractionLog {
  private readonly list: LogEntry[] = [];
  private startedAt = 0;
  private startedIso = '';
  private recording = false;

  constructor(private readonly map: VarioMap) {}

  get entries(): readonly LogEntry[] {
    return this.list;
  }

  get active(): boolean {
    return this.recording;
  }

  start(): this {
    if (this.recording) return this;
    this.recording = true;
    if (this.list.length === 0) {
      this.startedAt = performance.now();
      this.startedIso = new Date().toISOString();
    }
    this.map.on('move', this.onMove);
    this.map.on('settings', this.onSettings);
    const el = this.map.getContainer();
    for (const t of INPUT_EVENTS) el.addEventListener(t, this.onInput, { capture: true, passive: true });
    this.add('view', 'start', '');
    return this;
  }

  stop(): this {
    if (!this.recording) return this;
    this.recording = false;
    this.map.off('move', this.onMove);
    this.map.off('settings', this.onSettings);
    const el = this.map.getContainer();
    for (const t of INPUT_EVENTS) el.removeEventListener(t, this.onInput, { capture: true });
    return this;
  }

  clear(): this {
    this.list.length = 0;
    this.startedAt = performance.now();
    this.startedIso = new Date().toISOString();
    return this;
  }

  toJSON(): { startedAt: string; entries: LogEntry[] } {
    return { startedAt: this.startedIso, entries: this.list.map((e) => ({ ...e })) };
  }

  toCSV(): string {
    const quote = (v: string | number): string => (typeof v === 'number' ? String(v) : /[",\n]/.test(v) ? `"${v.replace(/"/g, '""')}"` : v);
    return [CSV_COLUMNS.join(','), ...this.list.map((e) => CSV_COLUMNS.map((k) => quote(e[k])).join(','))].join('\n') + '\n';
  }

  private add(kind: LogEntry['kind'], event: string, detail: string): void {
    const [x, y] = this.map.getCenterProjected();
    this.list.push({ t: Math.round((performance.now() - this.startedAt) * 10) / 10, kind, x, y, scale: this.map.getScaleDenominator(), z: this.map.getSliceZ(), event, detail });
  }

  private readonly onMove = (): void => this.add('view', 'move', '');

  private readonly onSettings = (): void => this.add('settings', 'settings', JSON.stringify({ ...this.map.getSettings(), blending: this.map.getBlending() }));

  private readonly onInput = (ev: Event): void => {
    const target = ev.target as Element | null;
    if (ev instanceof KeyboardEvent) {
      this.add('input', ev.type, ev.key);
    } else if (ev instanceof WheelEvent) {
      this.add('input', 'wheel', `${ev.deltaY} mode ${ev.deltaMode} at ${this.local(ev)}`);
    } else if (ev.type === 'click' && target?.closest('button')) {
      this.add('input', 'button', target.closest('button')!.getAttribute('aria-label') ?? '');
    } else if (ev instanceof PointerEvent) {
      this.add('input', ev.type, `${ev.pointerType} ${ev.pointerId} at ${this.local(ev)}`);
    } else if (ev instanceof MouseEvent && ev.type === 'dblclick') {
      this.add('input', 'dblclick', `at ${this.local(ev)}${ev.shiftKey ? ' shift' : ''}`);
    }
  };

  private local(ev: MouseEvent): string {
    const r = this.map.getCanvasContainer().getBoundingClientRect();
    return `${Math.round(ev.clientX - r.left)} ${Math.round(ev.clientY - r.top)}`;
  }
}

const INPUT_EVENTS = ['wheel', 'pointerdown', 'pointerup', 'keydown', 'dblclick', 'click'] as const;
