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
}

export interface Topology {
  xs: Float64Array;
  ys: Float64Array;
  vertexCount: number;
  edges: TopoEdge[];
  /** faceCount = features + 1; face f > 0 is input feature f - 1, face 0 is outside. */
  faceCount: number;
  /** Twice the area of each face (index 0 unused). */
  faceArea2: Float64Array;
  nodeCount: number;
  repairs: TopologyRepairs;
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
  /** Repairs already counted while reading. */
  inputRepairs?: { closedRings: number; duplicatePoints: number };
}

/** A ring of one face as point ids, without the closing point. */
export interface Ring {
  face: number;
  outer: boolean;
  ids: Int32Array;
}
