// The cube's index (docs/FORMAT.md, "index.json" and "Sub-index file"): its metadata and the
// R-tree of chunk boxes. One schema serves the writer (the build checks what it writes) and the
// reader (the map and the CLI trust the shapes after decoding). Pure.
import * as v from 'valibot';
import { FormatError } from './format-error.js';
import { PIXEL_SIZE_MM } from './pixel-size.js';
import { describeIssues } from './schema-issues.js';
import { drawnStyle, StyleSchema, type CubeStyle } from './style.js';

export const INDEX_FORMAT = 'ssc-index';
export const SUBINDEX_FORMAT = 'ssc-subindex';
/** The version the build writes; a reader reads this one and version 1 (`READ_VERSIONS`). */
export const INDEX_VERSION = 2;
const READ_VERSIONS = [1, 2] as const;
const VERSION_MESSAGE = `must be ${READ_VERSIONS.join(' or ')} (the versions this reader reads)`;

const num = () => v.pipe(v.number('must be a number'), v.finite('must be a finite number'));
const count = () => v.pipe(num(), v.minValue(0, 'must be >= 0'));

/** x0, y0, z0, x1, y1, z1 in ground units and steps. */
export type Box3 = [number, number, number, number, number, number];
const Box3Schema = v.tuple([num(), num(), num(), num(), num(), num()], 'must be 6 numbers');

// Chunk and page names are plain file names in the cube directory: never a path or a URL that
// could send the client elsewhere.
const FILE = /^[A-Za-z0-9][A-Za-z0-9._-]*$/;
const FileNameSchema = v.pipe(v.string('must be a file name'), v.regex(FILE, 'must be a plain file name'));

export interface ChunkLeaf {
  bbox: Box3;
  file: string;
  bytes: number;
  triangles: number;
  /** The file's whole SHA-256: written by version 1 only; version 2 checks against the name. */
  sha256?: string;
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

// A chunk file is named `<kind>-<the first 16 hex digits of its SHA-256>.<ext>`: the name is
// what the reader checks the bytes against. Version 1 also carried the whole SHA-256 in each
// leaf, 41% of a gzipped index on bgt_otterlo_1800m (17.5 kB of which 7.2) and on the first
// map's path; 64 bits still catch any corruption a network or a disk makes.
const HASHED_NAME = /^[a-z]+-([0-9a-f]{16})\.[a-z]+$/;

/** A cube file's name from its kind, its SHA-256 (hex) and its extension: what HASHED_NAME reads back. */
export function hashedName(kind: string, sha256: string, ext: string): string {
  return `${kind}-${sha256.slice(0, 16)}.${ext}`;
}
const Sha256Schema = v.pipe(v.string(), v.regex(/^[0-9a-f]{64}$/, 'must be 64 lowercase hex digits'));
const checkedByName = <T extends { file: string; sha256?: string | undefined }>() =>
  v.check<T, string>((leaf) => leaf.sha256 !== undefined || HASHED_NAME.test(leaf.file), 'must be named <kind>-<16 hex digits of its SHA-256>.<ext> (or carry sha256, as version 1 did)');

const LeafSchema = v.pipe(
  v.object({ bbox: Box3Schema, file: FileNameSchema, bytes: count(), triangles: count(), sha256: v.optional(Sha256Schema) }),
  checkedByName(),
);
/** A line chunk (docs/FORMAT.md, "Line chunk file"): its box (z0, z1: the lines' z range) and how many lines it holds. */
const LineLeafSchema = v.pipe(
  v.object({ bbox: Box3Schema, file: FileNameSchema, bytes: count(), lines: count(), sha256: v.optional(Sha256Schema) }),
  checkedByName(),
);
export type LineChunkLeaf = v.InferOutput<typeof LineLeafSchema>;

const ExternalSchema = v.object({ bbox: Box3Schema, ref: FileNameSchema, chunks: count() });
const InnerSchema: v.GenericSchema<InnerNode> = v.object({
  bbox: Box3Schema,
  children: v.array(v.lazy(() => NodeSchema)),
});
// Told apart by their one distinguishing key, so that an error names the right kind's fields.
const NodeSchema: v.GenericSchema<IndexNode> = v.lazy((input): v.GenericSchema<IndexNode> => {
  if (typeof input === 'object' && input !== null && 'file' in input) return LeafSchema;
  if (typeof input === 'object' && input !== null && 'ref' in input) return ExternalSchema;
  return InnerSchema;
});

const PageListSchema = v.object({
  count: count(),
  pageSize: v.pipe(num(), v.minValue(1, 'must be >= 1')),
  pages: v.array(v.object({ first: count(), file: FileNameSchema })),
});
export type PageList = v.InferOutput<typeof PageListSchema>;

const MetaSchema = v.object({
  name: v.optional(v.string(), ''),
  crs: v.optional(v.string(), ''),
  projectedFrom: v.optional(v.string()),
  proj4: v.optional(v.string()),
  extent: v.tuple([num(), num(), num(), num()], 'must be 4 numbers'),
  zMax: num(),
  steps: num(),
  phases: v.optional(num(), 8),
  baseScale: num(),
  baseFaces: num(),
  pixelSizeMm: v.optional(v.pipe(num(), v.gtValue(0, 'must be > 0')), PIXEL_SIZE_MM),
  /** Built with smooth merges (tilted surfaces); absent in a classic cube. */
  smooth: v.optional(v.boolean('must be true or false')),
  /** [step, facesAlive] knots in increasing step order. */
  scaleTable: v.pipe(v.array(v.tuple([num(), num()]), 'must be [step, facesAlive] pairs'), v.minLength(1, 'must not be empty')),
  style: StyleSchema,
  attribution: v.optional(v.string(), ''),
  source: v.optional(v.string()),
  faces: PageListSchema,
  attributes: PageListSchema,
});

const IndexSchema = v.object({
  format: v.literal(INDEX_FORMAT, `must be "${INDEX_FORMAT}"`),
  version: v.picklist(READ_VERSIONS, VERSION_MESSAGE),
  meta: MetaSchema,
  root: InnerSchema,
  /** Floor chunks: the floor again, as its faces' boundaries, for slices below `top` (docs/FORMAT.md, "Floor chunks"). */
  floor: v.optional(v.object({ top: v.pipe(num(), v.gtValue(0, 'must be > 0')), root: InnerSchema })),
  /** Line chunks, a flat list (absent when the style has no linear classes). */
  lines: v.optional(v.array(LineLeafSchema)),
});

const SubIndexSchema = v.object({
  format: v.literal(SUBINDEX_FORMAT, `must be "${SUBINDEX_FORMAT}"`),
  version: v.optional(v.picklist(READ_VERSIONS, VERSION_MESSAGE)),
  node: InnerSchema,
});

/** index.json as the build writes it (the style as stored in the tGAP). */
export type CubeIndexJson = v.InferInput<typeof IndexSchema>;
export type CubeMetaJson = v.InferInput<typeof MetaSchema>;

export type { CubeStyle };

export type CubeMeta = Omit<v.InferOutput<typeof MetaSchema>, 'style'> & { style: CubeStyle };

/** The floor chunks' tree and the z below which they are all a slice needs. */
export interface FloorIndex {
  top: number;
  root: InnerNode;
}

export interface CubeIndex {
  meta: CubeMeta;
  root: InnerNode;
  floor?: FloorIndex;
  lines?: LineChunkLeaf[];
}

export class IndexFormatError extends FormatError {
  constructor(message: string, file?: string) {
    super(message, file);
    this.name = 'IndexFormatError';
  }
}

/**
 * The hex digits a leaf's file's SHA-256 must start with: its `sha256` where the index carries
 * one (version 1), else the 16 of its name. A parsed index has one of them on every leaf.
 */
export function expectedDigest(leaf: { file: string; sha256?: string | undefined }): string {
  const digest = leaf.sha256 ?? HASHED_NAME.exec(leaf.file)?.[1];
  if (digest === undefined) throw new IndexFormatError('is not named by its SHA-256 and the index gives none', leaf.file);
  return digest;
}

function check<S extends v.GenericSchema>(schema: S, json: unknown, file: string): v.InferOutput<S> {
  const r = v.safeParse(schema, json);
  if (!r.success) {
    const problems = describeIssues(r.issues);
    throw new IndexFormatError(problems.length === 1 ? problems[0]! : `${problems.length} problems: ${problems.join('; ')}`, file);
  }
  return r.output;
}

/** The bytes of index.json: the index is checked against the schema first. */
export function encodeIndex(index: CubeIndexJson): Uint8Array {
  check(IndexSchema, index, 'index.json');
  return new TextEncoder().encode(JSON.stringify(index));
}

/** The JSON text of a sub-index file holding `node`. */
export function encodeSubIndex(node: InnerNode): string {
  const json = { format: SUBINDEX_FORMAT, version: INDEX_VERSION, node };
  check(SubIndexSchema, json, 'sub-index');
  return JSON.stringify(json);
}

/** A parsed index.json. */
export function parseIndex(json: unknown, file = 'index.json'): CubeIndex {
  const out = check(IndexSchema, json, file);
  return {
    meta: { ...out.meta, style: drawnStyle(out.meta.style) },
    root: out.root,
    ...(out.floor ? { floor: out.floor } : {}),
    ...(out.lines ? { lines: out.lines } : {}),
  };
}

/** A parsed sub-index file's node. */
export function parseSubIndex(json: unknown, file: string): InnerNode {
  return check(SubIndexSchema, json, file).node;
}

export const isLeaf = (n: IndexNode): n is ChunkLeaf => 'file' in n;
export const isExternal = (n: IndexNode): n is ExternalNode => 'ref' in n;
