// Below the floor's top, whether a view shows the floor chunks or the cube's (docs/FORMAT.md,
// "Floor chunks"): one rule for the worker's scheduler and for the map's head start on the
// first view (ChunkSource), which fetches what that view needs first before the worker runs.
import type { ChunkLeaf, CubeIndex, InnerNode } from '../../../format/cube-index.js';
import { boxMeets, queryIndex, viewPriority, type QueryBox, type QueryResult } from '../../../format/index-query.js';
import type { ViewRequest } from './worker-protocol.js';

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
 * there are floor chunks), then the cube's chunks on screen that index.json itself lists.
 */
export function firstViewFiles(index: CubeIndex, view: ViewRequest): string[] {
  const onScreen = { ground: view.visible, zMin: view.zMin, zMax: view.zMax };
  const none = (): undefined => undefined;
  const floor = floorQuery(index, onScreen, none);
  const cube = queryIndex(index.root, { ground: view.margin, zMin: view.zMin, zMax: view.zMax }, none);
  const onScreenBytes = (leaves: readonly ChunkLeaf[]): number => leaves.reduce((sum, l) => sum + (boxMeets(l.bbox, onScreen) ? l.bytes : 0), 0);
  const shown = floorChoice(floor, cube, onScreenBytes);
  const nearestFirst = (leaves: readonly ChunkLeaf[]): string[] =>
    leaves
      .map((leaf) => ({ file: leaf.file, priority: viewPriority(leaf.bbox, view.visible, view) }))
      .sort((a, b) => a.priority - b.priority)
      .map((l) => l.file);
  if (shown) return nearestFirst(shown.leaves);
  return [...cube.missing, ...nearestFirst(cube.leaves.filter((l) => boxMeets(l.bbox, onScreen)))];
}
