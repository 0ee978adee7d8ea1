// Below the floor's top, whether a view shows the floor chunks or the cube's (docs/FORMAT.md,
// "Floor chunks"); just above it, whether a first view draws the floor under itself while its
// own chunks come (interimFloor). One rule for the worker's scheduler and for the map's head
// start on the first view (ChunkSource), which fetches what that view needs first before the
// worker runs.
import type { ChunkLeaf, CubeIndex, InnerNode } from '../../../format/cube-index.js';
import { boxMeets, queryIndex, viewPriority, type QueryBox, type QueryResult } from '../../../format/index-query.js';
import { zAtScale } from '../../../format/scale.js';
import type { ViewRequest } from './worker-protocol.js';

/**
 * A first view up to this many times the base scale may draw the floor under itself until its
 * own chunks have come (interimFloor): its ground is at most 4 times a base-scale view's.
 */
export const INTERIM_SCALE = 2;

/**
 * The floor's on screen must be at most this share of the cube's bytes on screen for the
 * interim floor to pay: it delays the view's own chunks by its bytes.
 */
export const INTERIM_SHARE = 0.5;

/**
 * The floor chunks a query needs, or null when the cube has none or the query reaches above
 * their top. `loaded`: the sub-index files at hand.
 */
export function floorQuery(index: CubeIndex, q: QueryBox, loaded: (ref: string) => InnerNode | undefined): QueryResult | null {
  const floor = index.floor;
  if (!floor || q.zMax >= floor.top) return null;
  return queryIndex(floor.root, q, loaded);
}

/**
 * `floor` when the view shows the floor chunks, else null (the cube's on screen): the cube's
 * win when they leave fewer bytes to fetch on screen (they are here already, say, after a zoom
 * back in); while the cube's sub-index files are missing their cost is not known, and the floor
 * wins. `toFetch(leaves)`: the bytes of those of `leaves` on screen still to fetch, Infinity
 * when one of them has failed (offline, it may never have been fetched).
 */
export function floorChoice(floor: QueryResult | null, cube: QueryResult, toFetch: (leaves: readonly ChunkLeaf[]) => number): QueryResult | null {
  if (!floor) return null;
  const floorBytes = toFetch(floor.leaves);
  if (floorBytes === Infinity) return null;
  return cube.missing.length === 0 && toFetch(cube.leaves) < floorBytes ? null : floor;
}

/**
 * The files a first view asks for first, as the scheduler would choose them with nothing fetched
 * yet and only index.json at hand: the floor chunks it shows on screen, nearest first; above the
 * floor, the sub-index files its query reaches (the build keeps the cube's tree in them when
 * there are floor chunks), after its interim floor (interimFloor) if any, then the cube's
 * chunks on screen that index.json itself lists. The sub-index files of the floor (shown or
 * interim) that its query reaches come too, as the scheduler loads them.
 */
export function firstViewFiles(index: CubeIndex, view: ViewRequest): string[] {
  const onScreen = { ground: view.visible, zMin: view.zMin, zMax: view.zMax };
  const none = (): undefined => undefined;
  const floor = floorQuery(index, onScreen, none);
  const cube = queryIndex(index.root, { ground: view.margin, zMin: view.zMin, zMax: view.zMax }, none);
  const bytesIn = (leaves: readonly ChunkLeaf[], box: QueryBox): number => leaves.reduce((sum, l) => sum + (boxMeets(l.bbox, box) ? l.bytes : 0), 0);
  const shown = floorChoice(floor, cube, (leaves) => bytesIn(leaves, onScreen));
  const nearestFirst = (leaves: readonly ChunkLeaf[]): string[] =>
    leaves
      .map((leaf) => ({ file: leaf.file, priority: viewPriority(leaf.bbox, view.visible, view) }))
      .sort((a, b) => a.priority - b.priority)
      .map((l) => l.file);
  // The floor's own sub-index files (a floor too large for index.json) come first: until they
  // have, the floor chunks under them are not known.
  if (shown) return [...shown.missing, ...nearestFirst(shown.leaves)];
  const under = interimApplies(index, view) ? floorQuery(index, underView(view.visible), none) : null;
  const interim = interimFloor(index, view, under, cube, bytesIn);
  return [...(under?.missing ?? []), ...nearestFirst(interim), ...cube.missing, ...nearestFirst(cube.leaves.filter((l) => boxMeets(l.bbox, onScreen)))];
}

/** The box of the floor under a view's ground: its triangles lie at z 0, under every slice. */
export function underView(ground: QueryBox['ground']): QueryBox {
  return { ground, zMin: 0, zMax: 0 };
}

/**
 * Whether a view may draw the floor under itself while its own chunks come (interimFloor): the
 * cube has floor chunks, the view reaches above their top, and it is at most INTERIM_SCALE times
 * the base scale.
 */
export function interimApplies(index: CubeIndex, view: ViewRequest): boolean {
  const floor = index.floor;
  return floor !== undefined && view.zMax >= floor.top && view.z <= zAtScale(index.meta, INTERIM_SCALE * index.meta.baseScale);
}

/**
 * Above the floor's top, the floor chunks on screen (`under`: the floor's query in
 * underView(view's ground)) that a first view draws under its own chunks until they have all
 * come (docs/CLIENT.md, "The first map just above the base scale"): a complete picture of the
 * base scale, refined as the view's own chunks arrive. Just above the base scale the cube's
 * chunks on screen are 4 to 5 times the floor's bytes (bgt_otterlo_1800m at 1:1,020: 164
 * against 39 kB). Empty unless interimApplies, or when the floor's bytes on screen are more
 * than INTERIM_SHARE of the cube's, once those are known (while the cube's sub-index files are
 * missing, they are taken to be more). `toFetch(leaves, box)`: the bytes of those of `leaves`
 * meeting `box` still to fetch, Infinity when one of them has failed.
 */
export function interimFloor(index: CubeIndex, view: ViewRequest, under: QueryResult | null, cube: QueryResult, toFetch: (leaves: readonly ChunkLeaf[], box: QueryBox) => number): ChunkLeaf[] {
  if (!under || !interimApplies(index, view)) return [];
  const floorBytes = toFetch(under.leaves, underView(view.visible));
  if (floorBytes === Infinity) return [];
  if (cube.missing.length === 0 && floorBytes > INTERIM_SHARE * toFetch(cube.leaves, { ground: view.visible, zMin: view.zMin, zMax: view.zMax })) return [];
  return under.leaves;
}
