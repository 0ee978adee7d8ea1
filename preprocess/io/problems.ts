// All the problems of an input, gathered in one run: each check goes on after a problem, and
// the run stops at the end of a stage (or at the limit) with every problem found so far.
import { describeFeature, formatLocation, InputError, type FeatureRef } from './errors.js';

/** The kinds of problem, in the order their groups are listed. */
export const PROBLEM_KINDS = {
  file: 'file',
  geometry: 'not a polygon',
  coordinate: 'coordinate out of range',
  class: 'class',
  duplicate: 'duplicate polygon',
  ring: 'degenerate ring',
  sliver: 'sliver',
  selfIntersection: 'self-intersection',
  overlap: 'overlap',
  gap: 'gap',
} as const;

export type ProblemKind = keyof typeof PROBLEM_KINDS;

export interface Problem {
  kind: ProblemKind;
  /** What is wrong, without the feature or the place (`has a ring of zero area`). */
  message: string;
  feature?: FeatureRef;
  /** In the input's own coordinates. */
  location?: [number, number];
}

export const DEFAULT_MAX_PROBLEMS = 50;

export class ProblemList {
  readonly items: Problem[] = [];
  /**
   * Brings a place found after the input was projected back to the input's coordinates
   * (set once the CRS is resolved; identity until then).
   */
  toInput: ((x: number, y: number) => [number, number]) | null = null;
  /** The CRS of the locations, for the problems GeoJSON (null: longitude/latitude or unknown). */
  crs: string | null = null;

  constructor(readonly file: string | undefined, readonly limit = DEFAULT_MAX_PROBLEMS) {}

  get count(): number {
    return this.items.length;
  }

  /** Adds a problem; at the limit the run stops with what was found. */
  add(p: Problem): void {
    const location = p.location && this.toInput ? this.toInput(...p.location) : p.location;
    this.items.push({ ...p, ...(location ? { location } : {}) });
    if (this.items.length >= this.limit) throw new InputProblems(this, true);
  }

  /** An InputError caught from a check that stops at its first problem, kept as one problem. */
  addError(err: InputError, kind: ProblemKind = err.kind ?? 'file'): void {
    this.add({ kind, message: err.detail, ...(err.feature ? { feature: err.feature } : {}), ...(err.location ? { location: err.location } : {}) });
  }

  /** The end of a stage: stops the run when it found problems. */
  check(): void {
    if (this.items.length > 0) throw new InputProblems(this, false);
  }
}

/** The refusal of an input with all its problems: one line for one problem, grouped lines for more. */
export class InputProblems extends InputError {
  readonly problems: readonly Problem[];
  readonly crs: string | null;

  constructor(list: ProblemList, readonly stopped: boolean) {
    const first = list.items[0]!;
    const file = list.file ? { file: list.file } : {};
    super(first.message, { ...file, ...(first.feature ? { feature: first.feature } : {}), ...(first.location ? { location: first.location } : {}) });
    this.name = 'InputProblems';
    this.problems = [...list.items];
    this.crs = list.crs;
    if (this.problems.length > 1 || stopped) this.message = groupedMessage(list, stopped);
  }
}

function groupedMessage(list: ProblemList, stopped: boolean): string {
  const items = list.items;
  const lines = [`${list.file ? list.file + ': ' : ''}${stopped ? `the first ${items.length}` : items.length} problems; the input is refused${stopped ? ` (--max-problems raises the limit of ${list.limit})` : ''}:`];
  for (const kind of Object.keys(PROBLEM_KINDS) as ProblemKind[]) {
    const group = items.filter((p) => p.kind === kind);
    if (group.length === 0) continue;
    lines.push(`  ${PROBLEM_KINDS[kind]} (${group.length}):`);
    for (const p of group) {
      const where = [p.feature ? describeFeature(p.feature) : null, p.location ? formatLocation(p.location) : null].filter((s) => s !== null);
      lines.push(`    ${where.length ? where.join(', ') + ': ' : ''}${p.message}`);
    }
  }
  return lines.join('\n');
}
