// The planar partition buildTopology makes, its options, and the rings it is made from.
import type { ProblemList } from '../io/problems.js';

export interface TopoEdge {
  start: number;
  end: number;
  /** Face on the left going from start to end (0 = outside the domain). */
  left: number;
  right: number;
  verts: Int32Array;
}

export interface TopologyRepairs {
  closedRings: number;
  duplicatePoints: number;
  reorientedRings: number;
  tJunctions: number;
  snappedPoints: number;
  mergedPoints: number;
  spikes: number;
  /** Parts (rings) thinner than the sliver width dissolved into a neighbour (slivers.ts). */
  slivers: number;
}

export interface Topology {
  xs: Float64Array;
  ys: Float64Array;
  vertexCount: number;
  edges: TopoEdge[];
  /** faceCount = features + 1 (less the features dissolved whole as slivers); face 0 is outside. */
  faceCount: number;
  /** Twice the area of each face (index 0 unused). */
  faceArea2: Float64Array;
  nodeCount: number;
  repairs: TopologyRepairs;
  /** Per face, the input feature it is (face f is feature f - 1 unless slivers dissolved whole features; -1 for face 0). */
  featureOfFace: Int32Array;
  /** Holes in the domain accepted with allowHoles: area and one point on each. */
  holes: { area: number; x: number; y: number }[];
}

export interface TopologyOptions {
  /** Coordinates are snapped to this grid and vertices this close to a segment are put on it (CRS units). */
  precision: number;
  file?: string;
  /**
   * Holes in the union of the faces are refused as gaps unless this is set: then they are
   * taken as outside the domain (an enclave of another territory) and listed in the result.
   */
  allowHoles?: boolean;
  /** Where problems are gathered (problems found before, while reading, are refused with these). */
  problems?: ProblemList;
  /**
   * Parts of a face thinner than this (2 x area / perimeter, CRS units) are dissolved into the
   * neighbour with the longest shared boundary; those narrower than the precision, and rings
   * the snapping collapsed, are left out before the partition is built (thin gaps they leave
   * go to a neighbour too). All are counted as slivers (slivers.ts). 0, the default: none, and
   * a collapsed ring is refused.
   */
  sliverWidth?: number;
  /** Slivers are refused (every one named) instead of dissolved. */
  refuseSlivers?: boolean;
  /** Repairs already counted while reading. */
  inputRepairs?: { closedRings: number; duplicatePoints: number };
}

/** A ring of one face as point ids, without the closing point. */
export interface Ring {
  face: number;
  outer: boolean;
  ids: Int32Array;
  /** Where it comes from: the polygon (part) of its feature and the ring in it (0: outer). */
  part: number;
  ring: number;
}
