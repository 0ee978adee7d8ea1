// The cube's index (docs/FORMAT.md, "index.json"): its metadata and the R-tree of chunk boxes,
// checked on reading so that the rest of the client can trust the shapes. Pure.

/** x0, y0, z0, x1, y1, z1 in ground units and steps. */
export type Box3 = [number, number, number, number, number, number];

export interface PatternJson {
  kind: 'hatch' | 'dots' | 'cross';
  color: string;
  minScale?: number;
  maxScale?: number;
}

export interface StyleClassJson {
  key: string;
  label: string;
  color: string;
  pattern?: PatternJson;
}

export interface CubeStyle {
  name?: string;
  background: string;
  classes: StyleClassJson[];
}

export interface PageList {
  count: number;
  pageSize: number;
  pages: { first: number; file: string }[];
}

export interface CubeMeta {
  name: string;
  crs: string;
  extent: [number, number, number, number];
  zMax: number;
  steps: number;
  phases: number;
  baseScale: number;
  baseFaces: number;
  pixelSizeMm: number;
  scaleTable: [number, number][];
  style: CubeStyle;
  attribution: string;
  faces: PageList;
  attributes: PageList;
}

export interface ChunkLeaf {
  bbox: Box3;
  file: string;
  bytes: number;
  triangles: number;
  sha256: string;
}

export interface ExternalNode {
  bbox: Box3;
  ref: string;
  chunks: number;
}

export interface InnerNode {
  bbox: Box3;
  children: IndexNode[];
}

export type IndexNode = InnerNode | ExternalNode | ChunkLeaf;

export interface CubeIndex {
  meta: CubeMeta;
  root: InnerNode;
}

export class IndexFormatError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'IndexFormatError';
  }
}

const isObj = (v: unknown): v is Record<string, unknown> => typeof v === 'object' && v !== null && !Array.isArray(v);
const isNum = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);

function fail(where: string, what: string): never {
  throw new IndexFormatError(`${where}: ${what}`);
}

function box(v: unknown, where: string): Box3 {
  if (!Array.isArray(v) || v.length !== 6 || !v.every(isNum)) fail(where, 'bbox must be 6 numbers');
  return v as Box3;
}

// Chunk and page names are plain file names in the cube directory: never a path or a URL that
// could send the client elsewhere.
const FILE = /^[A-Za-z0-9][A-Za-z0-9._-]*$/;
function fileName(v: unknown, where: string): string {
  if (typeof v !== 'string' || !FILE.test(v)) fail(where, `bad file name ${JSON.stringify(v)}`);
  return v as string;
}

export function parseNode(v: unknown, where = 'root'): IndexNode {
  if (!isObj(v)) fail(where, 'node must be an object');
  const bbox = box(v.bbox, where);
  if ('file' in v) {
    const sha = v.sha256;
    if (typeof sha !== 'string' || !/^[0-9a-f]{64}$/.test(sha)) fail(where, 'sha256 must be 64 lowercase hex digits');
    if (!isNum(v.bytes) || v.bytes < 0) fail(where, 'bytes must be a number');
    if (!isNum(v.triangles) || v.triangles < 0) fail(where, 'triangles must be a number');
    return { bbox, file: fileName(v.file, where), bytes: v.bytes, triangles: v.triangles, sha256: sha as string };
  }
  if ('ref' in v) {
    return { bbox, ref: fileName(v.ref, where), chunks: isNum(v.chunks) ? v.chunks : 0 };
  }
  if (!Array.isArray(v.children)) fail(where, 'node needs children, ref or file');
  return { bbox, children: (v.children as unknown[]).map((c, i) => parseNode(c, `${where}.children[${i}]`)) };
}

function pageList(v: unknown, where: string): PageList {
  if (!isObj(v) || !isNum(v.count) || !isNum(v.pageSize) || !Array.isArray(v.pages)) fail(where, 'expected {count, pageSize, pages}');
  const pages = (v.pages as unknown[]).map((p, i) => {
    if (!isObj(p) || !isNum(p.first)) fail(`${where}.pages[${i}]`, 'expected {first, file}');
    return { first: p.first as number, file: fileName(p.file, `${where}.pages[${i}]`) };
  });
  return { count: v.count as number, pageSize: v.pageSize as number, pages };
}

function style(v: unknown): CubeStyle {
  if (!isObj(v)) fail('meta.style', 'must be an object');
  const classesIn = v.classes;
  let classes: StyleClassJson[];
  const one = (c: unknown, key: string, i: number): StyleClassJson => {
    if (!isObj(c) || typeof c.color !== 'string') fail(`meta.style.classes[${i}]`, 'needs a color');
    const out: StyleClassJson = { key, label: typeof c.label === 'string' ? c.label : key, color: c.color as string };
    const p = c.pattern;
    if (isObj(p) && (p.kind === 'hatch' || p.kind === 'dots' || p.kind === 'cross') && typeof p.color === 'string') {
      out.pattern = { kind: p.kind, color: p.color };
      if (isNum(p.minScale)) out.pattern.minScale = p.minScale;
      if (isNum(p.maxScale)) out.pattern.maxScale = p.maxScale;
    }
    return out;
  };
  if (Array.isArray(classesIn)) {
    classes = classesIn.map((c, i) => one(c, isObj(c) && (typeof c.key === 'string' || isNum(c.key)) ? String(c.key) : String(i), i));
  } else if (isObj(classesIn)) {
    classes = Object.entries(classesIn).map(([k, c], i) => one(c, k, i));
  } else {
    fail('meta.style', 'classes must be an array or an object');
  }
  return {
    name: typeof v.name === 'string' ? v.name : undefined,
    background: typeof v.background === 'string' ? v.background : '#ffffff',
    classes,
  } as CubeStyle;
}

export function parseMeta(v: unknown): CubeMeta {
  if (!isObj(v)) fail('meta', 'must be an object');
  const num = (k: string): number => {
    const x = v[k];
    if (!isNum(x)) fail('meta', `${k} must be a number`);
    return x as number;
  };
  const extent = v.extent;
  if (!Array.isArray(extent) || extent.length !== 4 || !extent.every(isNum)) fail('meta', 'extent must be 4 numbers');
  const st = v.scaleTable;
  if (!Array.isArray(st) || st.length === 0 || !st.every((k) => Array.isArray(k) && k.length === 2 && k.every(isNum))) {
    fail('meta', 'scaleTable must be [step, facesAlive] pairs');
  }
  return {
    name: typeof v.name === 'string' ? v.name : '',
    crs: typeof v.crs === 'string' ? v.crs : '',
    extent: extent as [number, number, number, number],
    zMax: num('zMax'),
    steps: num('steps'),
    phases: isNum(v.phases) ? v.phases : 8,
    baseScale: num('baseScale'),
    baseFaces: num('baseFaces'),
    pixelSizeMm: isNum(v.pixelSizeMm) ? v.pixelSizeMm : 0.28,
    scaleTable: st as [number, number][],
    style: style(v.style),
    attribution: typeof v.attribution === 'string' ? v.attribution : '',
    faces: pageList(v.faces, 'meta.faces'),
    attributes: pageList(v.attributes, 'meta.attributes'),
  };
}

export function parseIndex(json: unknown): CubeIndex {
  if (!isObj(json) || json.format !== 'ssc-index') fail('index.json', 'format must be "ssc-index"');
  if (json.version !== 1) fail('index.json', `version ${String(json.version)} is not supported`);
  const root = parseNode(json.root);
  if (!('children' in root)) fail('root', 'must be an inner node');
  return { meta: parseMeta(json.meta), root };
}

/** A sub-index file's node. */
export function parseSubIndex(json: unknown, file: string): InnerNode {
  if (!isObj(json) || json.format !== 'ssc-subindex') fail(file, 'format must be "ssc-subindex"');
  const node = parseNode(json.node, file);
  if (!('children' in node)) fail(file, 'node must be an inner node');
  return node;
}

export const isLeaf = (n: IndexNode): n is ChunkLeaf => 'file' in n;
export const isExternal = (n: IndexNode): n is ExternalNode => 'ref' in n;
