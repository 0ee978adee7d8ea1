// Input file + style -> tGAP: the steps `ssc generalize` and `ssc build` share.
import path from 'node:path';
import proj4 from 'proj4';
import { resolveCrs, type CrsInfo } from './io/crs.js';
import { describeFeature, InputError } from './io/errors.js';
import { InputProblems, ProblemList } from './io/problems.js';
import { readInput, type InputFeature, type RawInput } from './io/read-input.js';
import { defaultStyle, loadStyle, styleToJson, type Style } from './style.js';
import { generalize, type GeneralizeResult } from './tgap/generalize.js';
import type { Tgap } from '../format/tgap-model.js';
import { TGAP_VERSION } from '../format/tgap.js';
import { buildTopology, type Topology } from './topology/build-topology.js';
import { findDuplicateFeatures } from './topology/duplicate-features.js';
import { recommendBaseScale } from './style-scaffold/base-scale.js';
import { describeColourSources } from './style-scaffold/class-colours.js';
import { featureShape, guessClassProperty } from './style-scaffold/class-stats.js';
import { lapTimer } from './lap-timer.js';
import { coarsestGrid, defaultPrecision, pointGrid } from './ssc/position-grid.js';
import { PIXEL_SIZE_MM } from '../format/pixel-size.js';

/**
 * The default sliver width, in resolution pixels (0.28 mm) at the base scale: 1.4 cm on the
 * ground at 1:1,000. A twentieth of a pixel is never seen at any scale, and is well above the
 * noise of real data (a millimetre or less) and below any real feature's width.
 */
export const SLIVER_PX = 0.05;

export interface PipelineOptions {
  style?: string;
  /** Overrides the style's class property (or names one when there is no style). */
  classProperty?: string;
  crs?: string;
  layer?: string;
  precision?: number;
  baseScale?: number;
  allowHoles?: boolean;
  /** Independent events per step (see GeneralizeOptions.group). */
  group?: number;
  /** Problems of a refused input named at most (default 50). */
  maxProblems?: number;
  /** The later of two exactly equal polygons is dropped (counted), not refused. */
  dropDuplicates?: boolean;
  /** Parts thinner than this (CRS units) are slivers (default: SLIVER_PX pixel at the base scale; 0: none). */
  sliverWidth?: number;
  /** Slivers are refused, every one named, instead of dissolved into a neighbour. */
  refuseSlivers?: boolean;
  log?: (msg: string) => void;
}

export interface PipelineReport {
  topology: Pick<Topology, 'vertexCount' | 'nodeCount' | 'faceCount' | 'repairs' | 'holes'> & { edges: number; droppedDuplicates: number };
  generalize: GeneralizeResult['stats'] & { steps: number; facesLeft: number };
  timings: Record<string, number>;
  /** Without a style: what was chosen instead, and how to write a style (lines to print). */
  noStyle?: string[];
}

export async function generalizeFile(input: string, opts: PipelineOptions = {}): Promise<{ tgap: Tgap; report: PipelineReport }> {
  const log = opts.log ?? (() => {});
  const { timings, lap } = lapTimer();
  const styleGiven = opts.style ? await loadStyle(opts.style) : null;
  const problems = new ProblemList(path.basename(input), opts.maxProblems);
  const raw = await readInput(input, {
    ...(opts.layer ? { layer: opts.layer } : {}),
    ...(styleGiven?.idProperty ? { idProperty: styleGiven.idProperty } : {}),
    problems,
  });
  const crs = resolveCrsOf(raw, opts.crs, problems);
  lap('read');
  const droppedDuplicates = checkDuplicates(raw.features, problems, opts.dropDuplicates ?? false);
  const classProperty = opts.classProperty ?? styleGiven?.classProperty ?? null;
  // Each feature's class value; null after a problem was noted.
  const values = raw.features.map((f): string | null => {
    if (classProperty === null) return 'all';
    const v = f.properties[classProperty];
    if (v === undefined || v === null) {
      problems.add({ kind: 'class', message: v === null ? `has the class property ${JSON.stringify(classProperty)} set to null` : `has no class property ${JSON.stringify(classProperty)}`, feature: f.ref, ...firstPoint(f) });
      return null;
    }
    return String(v);
  });
  let style: Style;
  let noStyle: string[] | undefined;
  if (styleGiven) {
    style = styleGiven;
  } else {
    const found = [...new Set(values.filter((v) => v !== null))];
    style = defaultStyle(found, classProperty);
    const hint = classProperty === null ? guessClassProperty(raw.features).property : null;
    noStyle = [
      classProperty === null
        ? `no style: one class, one colour${hint ? ` (the property ${JSON.stringify(hint)} looks like a class: --class-property ${hint})` : ''}`
        : `no style: class property ${JSON.stringify(classProperty)}, ${style.classes.length} classes coloured by ${describeColourSources(found)}`,
    ];
  }
  const classIndex = new Map(style.classes.map((c, i) => [c.key, i]));
  const classes = new Uint16Array(raw.features.length + 1);
  raw.features.forEach((f, i) => {
    const v = values[i];
    if (v === null || v === undefined) return;
    const ci = classIndex.get(v);
    if (ci === undefined) {
      problems.add({
        kind: 'class',
        message: `has class ${JSON.stringify(v)} (property ${JSON.stringify(classProperty)}), which the style ${opts.style ? path.basename(opts.style) + ' ' : ''}does not define`,
        feature: f.ref, ...firstPoint(f),
      });
      return;
    }
    classes[i + 1] = ci;
  });
  const allowHoles = opts.allowHoles ?? style.allowHoles;
  // The base scale before the topology: it sets the snapping grid and the sliver width.
  const baseScale = opts.baseScale ?? (style.baseScale > 0 ? style.baseScale : autoBaseScale(raw.features, style.resolutionMm));
  const precision = opts.precision ?? defaultPrecision(baseScale, PIXEL_SIZE_MM);
  // Rounded to 12 digits: the tGAP's options say 0.014, not 0.014000000000000002.
  const sliverWidth = opts.sliverWidth ?? Number(((SLIVER_PX * style.resolutionMm * baseScale) / 1000).toPrecision(12));
  const topo = buildTopology(raw.features, {
    precision, file: raw.file, inputRepairs: raw.repairs, allowHoles, problems, sliverWidth, refuseSlivers: opts.refuseSlivers ?? false,
  });
  // Faces are the features less those dissolved whole as slivers.
  const attributes = Array.from(topo.featureOfFace.subarray(1), (i) => raw.features[i]!.properties);
  // The coordinates now live in the topology; let the input's go.
  raw.features.length = 0;
  lap('topology');
  // The grid every input point lies on: the precision, or the input's own where coarser
  // (position-grid.ts); the points the build makes go to it where they can.
  const n = topo.vertexCount;
  const grid = Math.max(precision, pointGrid(baseScale, PIXEL_SIZE_MM, [topo.xs.subarray(0, n), topo.ys.subarray(0, n)]) ?? 0);
  log(`topology: ${topo.faceCount - 1} faces, ${topo.edges.length} edges, ${topo.nodeCount} nodes, ${topo.vertexCount} vertices`);

  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let v = 0; v < topo.vertexCount; v++) {
    const x = topo.xs[v]!, y = topo.ys[v]!;
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
  }
  noStyle?.push(
    `no style: base scale 1:${baseScale}${opts.baseScale !== undefined ? ' (--base-scale)' : ' (chosen from the data: its mean face is 20 pixels across there)'}`,
    `no style: to write one, run ssc style ${path.basename(input)} --out style.json and see docs/STYLE.md`,
  );
  const g = generalize(topo, (f) => classes[topo.featureOfFace[f]! + 1]!, style, {
    baseScale,
    resolutionMm: style.resolutionMm,
    snapStep: 2 ** coarsestGrid(baseScale, PIXEL_SIZE_MM, grid),
    ...(opts.group !== undefined ? { group: opts.group } : {}),
    onProgress: (k, alive) => log(`generalize: step ${k}, ${alive} faces left`),
  });
  lap('generalize');
  const steps = g.events.length === 0 ? 0 : g.events[g.events.length - 1]!.step;
  const meta: Tgap['meta'] = {
    version: TGAP_VERSION,
    crs: crs.code,
    ...(crs.projectedFrom ? { projectedFrom: crs.projectedFrom } : {}),
    ...(crs.proj4 ? { proj4: crs.proj4 } : {}),
    extent: [x0, y0, x1, y1],
    baseScale,
    resolutionMm: style.resolutionMm,
    baseFaces: topo.faceCount - 1,
    steps,
    facesAlive: g.facesAlive,
    holes: topo.holes,
    repairs: { ...topo.repairs },
    source: path.basename(input),
    style: styleToJson({ ...style, baseScale }),
    attributes,
    options: { precision, grid, allowHoles, group: opts.group ?? 1, sliverWidth },
  };
  const report: PipelineReport = {
    topology: { vertexCount: topo.vertexCount, nodeCount: topo.nodeCount, faceCount: topo.faceCount - 1, edges: topo.edges.length, repairs: topo.repairs, holes: topo.holes, droppedDuplicates },
    generalize: { ...g.stats, steps, facesLeft: g.facesAlive[g.facesAlive.length - 1]! },
    timings,
    ...(noStyle ? { noStyle } : {}),
  };
  return { tgap: { meta, xs: g.xs, ys: g.ys, faces: g.faces, edges: g.edges, events: g.events }, report };
}

/** The working CRS; a problem of the whole file stops the run with what reading found before. */
function resolveCrsOf(raw: RawInput, override: string | undefined, problems: ProblemList): CrsInfo {
  let crs: CrsInfo;
  try {
    crs = resolveCrs(raw, override);
  } catch (err) {
    if (!(err instanceof InputError)) throw err;
    problems.addError(err, 'file');
    throw new InputProblems(problems, false);
  }
  // Problems are named in the input's own coordinates, also when it was projected.
  if (crs.proj4) {
    const back = proj4(crs.proj4, 'EPSG:4326');
    problems.toInput = (x, y) => back.forward<[number, number]>([x, y]);
  } else {
    problems.crs = crs.code;
  }
  return crs;
}

/** Notes each exact duplicate polygon, or drops it (in place) and returns how many were dropped. */
function checkDuplicates(features: InputFeature[], problems: ProblemList, drop: boolean): number {
  const pairs = findDuplicateFeatures(features);
  if (drop) {
    const later = new Set(pairs.map(([, j]) => j));
    const kept = features.filter((_, i) => !later.has(i));
    features.length = 0;
    features.push(...kept);
    return later.size;
  }
  for (const [i, j] of pairs) {
    problems.add({ kind: 'duplicate', message: `is an exact duplicate of ${describeFeature(features[i]!.ref)} (--drop-duplicates drops the later one)`, feature: features[j]!.ref, ...firstPoint(features[j]!) });
  }
  return 0;
}

/** A feature's first point, to find it on a map. */
function firstPoint(f: InputFeature): { location?: [number, number] } {
  const r = f.polygons[0]?.[0];
  return r && r.length >= 2 ? { location: [r[0]!, r[1]!] } : {};
}

/** The recommended base scale (style-scaffold/base-scale.ts, as ssc style gives it) from the input's features. */
function autoBaseScale(features: readonly InputFeature[], resolutionMm: number): number {
  let area = 0;
  for (const f of features) area += featureShape(f).area;
  return recommendBaseScale(area, features.length, resolutionMm);
}
