// Polygons with classes -> a planar partition: shared vertices, nodes, edges with a face on
// either side. Safe repairs are made and counted; anything that is not a partition is refused
// with the feature and the place named, all problems of a stage together.
import { ringArea2 } from '../geom/ring.js';
import { ProblemList } from '../io/problems.js';
import type { InputFeature } from '../io/read-input.js';
import { dropUnusedPoints } from './drop-unused-points.js';
import { buildHalfEdges } from './half-edges.js';
import { checkCrossings, checkOutside } from './partition-checks.js';
import { Refusal } from './refusal.js';
import { orientRings, repairRings } from './ring-repairs.js';
import { checkRingSelfCrossings } from './ring-self-crossings.js';
import { snapPoints } from './snap-points.js';
import type { Topology, TopologyOptions, TopologyRepairs } from './topology-types.js';
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
  };
  const refusal = new Refusal(features, opts.problems ?? new ProblemList(opts.file));
  // Points: snapped to the grid, one id per distinct point.
  const { rings: rawRings, xs, ys } = snapPoints(features, opts.precision, repairs);
  // Rings: near points merged, T-junctions inserted, outer rings counterclockwise, holes clockwise.
  const rings = repairRings(rawRings, xs, ys, opts.precision, repairs);
  checkRingSelfCrossings(rings, xs, ys, refusal);
  orientRings(rings, xs, ys, repairs, refusal);
  // Each stage names all its problems, and the input is refused at its end if it had any.
  refusal.check();
  // Half-edges with their twins; then the checks that they make a partition.
  const he = buildHalfEdges(rings, xs, ys, refusal);
  refusal.check();
  checkCrossings(he, xs, ys, refusal);
  refusal.check();
  const holes = checkOutside(he, xs, ys, refusal, opts.allowHoles ?? false);
  refusal.check();
  // Edges between nodes, face areas, and only the points the edges use.
  const { edges, nodeCount } = traceEdges(he, xs.length);
  const faceCount = features.length + 1;
  const faceArea2 = new Float64Array(faceCount);
  for (const r of rings) faceArea2[r.face]! += ringArea2(r.ids, xs, ys);
  const kept = dropUnusedPoints(edges, xs, ys);
  return { xs: kept.xs, ys: kept.ys, vertexCount: kept.count, edges, faceCount, faceArea2, nodeCount, repairs, holes };
}
