// @kninnug/constrainautor, typed here. The package's `types` point at its .ts source, which
// would be compiled under our stricter options (noUncheckedIndexedAccess) and fail; so the
// module is loaded by a specifier the compiler does not follow, and its API used here is
// declared below. Its default export is the class (an ES module at run time).
interface DelaunatorLike {
  coords: { readonly length: number; readonly [n: number]: number };
  triangles: { length: number; [n: number]: number };
  halfedges: { length: number; [n: number]: number };
}

export interface Constrainautor {
  constrainOne(segP1: number, segP2: number): number;
  isConstrained(edg: number): boolean;
  /** The half-edge from p1 to p2, negative (or -Infinity) when there is none. */
  findEdge(p1: number, p2: number): number;
  untriangulatedPoints(): number[];
}

type ConstrainautorClass = new (del: DelaunatorLike, edges?: readonly [number, number][]) => Constrainautor;

const specifier: string = '@kninnug/constrainautor';
const mod = (await import(specifier)) as { default: ConstrainautorClass };
export const Constrainautor: ConstrainautorClass = mod.default;
