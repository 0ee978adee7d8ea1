// Polygons with classes -> a planar partition: shared vertices, nodes, edges with a face on
// either side. Safe repairs are made and counted; anything that is not a partition is refused
// with the feature and the place named, all problems of a stage together.
import { ringArea2 } from '../geom/ring.js';
import { ProblemList } from '../io/problems.js';
import type { InputFeature } from '../io/read-input.js';
import { dropUnusedPoints } from './drop-unused-points.js';
import { buildHalfEdges, type HalfEdges } from './half-edges.js';
import { checkCrossings, checkOutside } from './partition-checks.js';
import { Refusal } from './refusal.js';
import { orientRings, repairRings } from './ring-repairs.js';
import { checkRingSelfCrossings } from './ring-self-crossings.js';
import { dissolveSlivers, fillSliverGaps, hadArea, noteLeftOut, partBox, partsNarrowerThan, type SliverOptions } from './slivers.js';
import { snapPoints } from './snap-points.js';
import type { Ring, Topology, TopologyOptions, TopologyRepairs } from './topology-types.js';
import { traceEdges } from './trace-edges.js';

export type { TopoEdge, Topology, TopologyOptions, TopologyRepairs } from './topology-types.js';

export function buildTopology(features: InputFeature[], opts: TopologyOptions): Topology {
  const repairs: TopologyRepairs = {
    closedRings: opts.inputRepairs?.closedRings ?? 0,
    duplicatePoints: opts.inputRepairs?.duplicatePoints ?? 0,
    reorientedRings: 0,
    tJunctions: 0,
    snappedPoints: 0,
    mergedPoints: 0,
    spikes: 0,
    slivers: 0,
  };
  const refusal = new Refusal(features, opts.problems ?? new ProblemList(opts.file));
  const slivers: SliverOptions | null = (opts.sliverWidth ?? 0) > 0 ? { width: opts.sliverWidth!, refuse: opts.refuseSlivers ?? false, precision: opts.precision } : null;
  // Parts narrower than the precision are slivers the snapping cannot keep: left out before it.
  const narrow = slivers ? partsNarrowerThan(features, opts.precision) : [];
  const skip = new Set(narrow.map((p) => `${p.face}:${p.part}`));
  // Points: snapped to the grid, one id per distinct point.
  const { rings: rawRings, xs, ys } = snapPoints(features, opts.precision, repairs, (face, part) => skip.has(`${face}:${part}`));
  // Rings: near points merged, T-junctions inserted, outer rings counterclockwise, holes clockwise.
  const repaired = repairRings(rawRings, xs, ys, opts.precision, repairs);
  // Rings the snapping collapsed are slivers (when slivers are dissolved) unless the input had them so.
  const isSliver = (r: Ring): boolean => slivers !== null && hadArea(features, r);
  const degenerate = new Set(orientRings(repaired, xs, ys, repairs, refusal, isSliver));
  const collapsed = [...degenerate].filter(isSliver);
  const rings = repaired.filter((r) => !degenerate.has(r));
  checkRingSelfCrossings(rings, xs, ys, refusal);
  // Each stage names all its problems, and the input is refused at its end if it had any.
  refusal.check();
  // Half-edges with their twins; then the checks that they make a partition.
  let he = buildHalfEdges(rings, xs, ys, refusal);
  refusal.check();
  // A crossing may be the snapping's doing: then say how to snap less.
  checkCrossings(he, xs, ys, refusal, repairs.snappedPoints > 0 ? `the snapping to a grid of ${opts.precision} moved points; a finer --precision may keep them apart` : null);
  refusal.check();
  let gaps: { face: number; area2: number }[] = [];
  if (slivers) {
    // Parts thinner than the sliver width go to their neighbours (or are all named) ...
    he = dissolveSlivers(he, rings, xs, ys, slivers, refusal, repairs);
    // ... and so do thin gaps where slivers were left out (those narrower than the precision
    // are left out whatever the sliver width).
    const boxes = [...narrow.map((p) => partBox(features, p.face, p.part, opts.precision)), ...collapsed.map((r) => partBox(features, r.face, r.part, opts.precision))];
    ({ he, gaps } = fillSliverGaps(he, xs, ys, Math.max(slivers.width, opts.precision), boxes));
    noteLeftOut(narrow, collapsed, features, slivers, refusal, repairs);
  }
  const holes = checkOutside(he, xs, ys, refusal, opts.allowHoles ?? false);
  refusal.check();
  // Faces numbered again without the features slivers took whole.
  const { faceCount, featureOfFace, newId } = renumberFaces(he, rings, features.length);
  // Edges between nodes, face areas, and only the points the edges use.
  const { edges, nodeCount } = traceEdges(he, xs.length);
  const faceArea2 = new Float64Array(faceCount);
  for (const r of rings) faceArea2[r.face]! += ringArea2(r.ids, xs, ys);
  for (const g of gaps) faceArea2[newId[g.face]!]! += g.area2;
  const kept = dropUnusedPoints(edges, xs, ys);
  return { xs: kept.xs, ys: kept.ys, vertexCount: kept.count, edges, faceCount, faceArea2, nodeCount, repairs, holes, featureOfFace };
}

/**
 * Numbers the faces that still have a boundary 1, 2, ... in input order (in place in the
 * half-edges and rings); returns their count with the outside and each one's input feature.
 */
function renumberFaces(he: HalfEdges, rings: Ring[], featureCount: number): { faceCount: number; featureOfFace: Int32Array; newId: Int32Array } {
  const present = new Uint8Array(featureCount + 1);
  for (let h = 0; h < he.count; h++) present[he.face[h]!] = 1;
  // Old face -> new (the outside stays 0).
  const newId = new Int32Array(featureCount + 1);
  const featureOfFace = [-1];
  for (let f = 1; f <= featureCount; f++) {
    if (!present[f]) continue;
    newId[f] = featureOfFace.length;
    featureOfFace.push(f - 1);
  }
  if (featureOfFace.length <= featureCount) {
    for (let h = 0; h < he.count; h++) he.face[h] = newId[he.face[h]!]!;
    for (const r of rings) r.face = newId[r.face]!;
  }
  return { faceCount: featureOfFace.length, featureOfFace: Int32Array.from(featureOfFace), newId };
}
