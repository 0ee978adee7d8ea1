// Which chunks the view needs and which stay on the GPU: the view (and the views ahead of a
// flight) go to the worker, its answer says what is on screen, in the margin and ahead; chunks
// that arrive wait here and go up within a per-frame byte budget; the rest are evicted.
import { boxMeets, type QueryBox } from '../../../format/index-query.js';
import { surfaceRange } from '../../../format/slicing-surface.js';
import type { MapView } from '../camera/map-view.js';
import type { Camera } from '../geometry/camera.js';
import { growBbox, viewBbox, type Bbox, type ViewGeometry } from '../geometry/view.js';
import { payloadBytes, type AheadView, type ChunkStatus, type NeededChunks, type Payload, type ViewRequest } from '../source/worker-protocol.js';

/** The worker's side (ChunkSource) as residency uses it. */
export interface ChunkRequests {
  setView(view: ViewRequest): void;
  uploaded(file: string): void;
  evicted(files: string[]): void;
  status(file: string): ChunkStatus;
  /** The map still fetches some of the first view's chunks for the worker (ChunkSource's head start). */
  readonly handingOver: boolean;
}

/** The GPU's side (Renderer) as residency uses it. */
export interface GpuChunks {
  upload(payload: Payload, frame: number): unknown;
  /** Frees memory beyond the budget, never a chunk in either set; returns the files freed. */
  evict(visible: ReadonlySet<string>, kept: ReadonlySet<string>): string[];
  readonly store: { has(file: string): boolean };
}

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

/** What the index is asked for a view: its boxes and the z range of the surface over the margin. */
export function queryView(mapView: MapView, view: ViewGeometry, marginFactor: number, z = mapView.z()): ViewQuery {
  const visible = viewBbox(view);
  const margin = growBbox(visible, marginFactor);
  const [zMin, zMax] = surfaceRange({ base: z, spec: mapView.surface().spec }, margin, mapView.meta?.zMax ?? 0);
  return { view, visible, margin, zMin, zMax, z };
}

const EMPTY: ReadonlySet<string> = new Set();

export class ChunkResidency {
  private needed: NeededChunks | null = null;
  private visibleSet = new Set<string>();
  /** Kept on the GPU beyond the budget besides those on screen: margin and ahead. */
  private keptSet = new Set<string>();
  /** The interim floor: drawn under the view until every chunk it shows is on the GPU. */
  private interimSet = new Set<string>();
  private readonly pending: Payload[] = [];
  private ahead: Camera[] = [];
  private aheadChanged = false;
  private sentSeq = -1;
  /** The worker's last index query, ms. */
  queryMs = 0;

  constructor(
    private readonly source: ChunkRequests,
    private readonly renderer: GpuChunks,
    private readonly uploadBytesPerFrame: number,
    /** A chunk went to the GPU. */
    private readonly uploaded: (file: string) => void,
  ) {}

  /** The worker's answer for view `n.seq`. */
  answer(n: NeededChunks): void {
    // While the view moves every frame the answer is for a view a frame or two old: close
    // enough to protect chunks from eviction; loaded() waits for the current view's answer.
    // The same view is answered again when its sub-index files have come in.
    if (this.needed && n.seq < this.needed.seq) return;
    this.needed = n;
    this.visibleSet = new Set(n.visible);
    this.interimSet = new Set(n.interim);
    this.keptSet = new Set([...n.margin, ...n.ahead, ...n.interim]);
    this.queryMs = n.queryMs;
  }

  arrived(chunk: Payload): void {
    this.pending.push(chunk);
  }

  get hasPending(): boolean {
    return this.pending.length > 0;
  }

  /** The map still fetches some of the first view's chunks for the worker: their bodies pass through this thread. */
  get handingOver(): boolean {
    return this.source.handingOver;
  }

  /** Views to come (a flight's path), fetched after the view's own; [] forgets them. */
  prefetch(cameras: Camera[]): void {
    this.ahead = cameras.slice();
    this.aheadChanged = true;
  }

  /** Sends view `seq` to the worker unless it has it; `aheadQuery` turns a view to come into its query; `frameMs`: the device's time per frame. */
  request(seq: number, q: ViewQuery, aheadQuery: (c: Camera) => ViewQuery, frameMs = 0): void {
    if (this.sentSeq === seq && !this.aheadChanged) return;
    this.sentSeq = seq;
    this.aheadChanged = false;
    const ahead = this.ahead.map((c): AheadView => {
      const a = aheadQuery(c);
      return { box: a.margin, zMin: a.zMin, zMax: a.zMax, centerX: c.x, centerY: c.y, z: a.z };
    });
    this.source.setView({ seq, visible: q.visible, margin: q.margin, zMin: q.zMin, zMax: q.zMax, centerX: q.view.centerX, centerY: q.view.centerY, z: q.z, ahead, frameMs });
  }

  /** Uploads chunks that arrived, within the per-frame byte budget; true when any that went up meets `drawn` or is of the interim floor. */
  upload(frameNo: number, seq: number, drawn: QueryBox): boolean {
    let bytes = 0;
    let changed = false;
    const dropped: string[] = [];
    while (bytes < this.uploadBytesPerFrame) {
      const c = this.pending.shift();
      if (!c) break;
      // A chunk the view no longer needs is not kept (it is fetched again if it comes back).
      if (this.needed?.seq === seq && !this.visibleSet.has(c.file) && !this.keptSet.has(c.file)) {
        dropped.push(c.file);
        continue;
      }
      this.renderer.upload(c, frameNo);
      this.source.uploaded(c.file);
      this.uploaded(c.file);
      bytes += payloadBytes(c);
      if (boxMeets(c.bbox, drawn) || this.interimSet.has(c.file)) changed = true;
    }
    this.source.evicted(dropped);
    return changed;
  }

  /** Frees GPU memory beyond the budget, never a chunk the view needs. */
  evict(): void {
    this.source.evicted(this.renderer.evict(this.visibleSet, this.keptSet));
  }

  /** Every chunk view `seq` shows is on the GPU. */
  loaded(seq: number): boolean {
    return this.pending.length === 0 && this.shows(seq, this.renderer.store);
  }

  /** The worker answered view `seq` and every chunk it shows is among `files`. */
  shows(seq: number, files: { has(file: string): boolean }): boolean {
    const n = this.needed;
    return n?.seq === seq && n.indexComplete && n.visible.every((f) => files.has(f));
  }

  /**
   * The chunks view `seq` shows, once the worker has answered it and all are on the GPU; null
   * before. Others on the GPU may meet the view too: at the floor the cube's chunks (its margin)
   * beside the floor chunks, the same floor.
   */
  shownChunks(seq: number): ReadonlySet<string> | null {
    return this.shows(seq, this.renderer.store) ? this.visibleSet : null;
  }

  /**
   * The interim floor (docs/CLIENT.md, "The first map just above the base scale"): floor chunks
   * drawn under view `seq`, whatever its z, until every chunk it shows is there. The last answer's
   * for a view it has not answered yet (a gesture's views are answered a frame or two late): the
   * frame loop draws those meeting the view's ground. A new set for each answer.
   */
  interimChunks(seq: number): ReadonlySet<string> {
    return this.needed && this.needed.seq <= seq ? this.interimSet : EMPTY;
  }

  /** The worker answered view `seq` and nothing it needs is still to come (failed chunks will not). */
  settled(seq: number): boolean {
    const n = this.needed;
    if (n?.seq !== seq || !n.indexComplete) return false;
    return !n.visible.some((f) => !this.renderer.store.has(f) && this.source.status(f) !== 'failed');
  }

  /** The chunks the current view needs: on screen, in the prefetch margin and ahead. */
  neededChunks(): { visible: string[]; margin: string[]; ahead: string[] } {
    const n = this.needed;
    return { visible: [...this.visibleSet], margin: n ? [...n.margin] : [], ahead: n ? [...n.ahead] : [] };
  }
}
