// What the data says about its classes, for a scaffolded style: which property holds the class
// (and which identifies a feature), and per class the face count, the area and the shape of
// its faces (how wide and how elongated), from which linear classes are suggested.
import type { InputFeature } from '../io/read-input.js';
import { ringArea2Flat, ringPerimeterFlat } from '../geom/ring.js';

export interface ClassStats {
  key: string;
  faces: number;
  /** Total area in CRS units squared. */
  area: number;
  /**
   * Area-weighted median over the faces of 2 area / perimeter (the width of a long strip, half
   * the side of a square): the width of the faces that hold most of the class's area.
   */
  width: number;
  /**
   * Median over the faces of perimeter^2 / (16 area) (1 for a square, about length / (4 width)
   * for a strip), by count or by area, whichever is higher: a class of many short road pieces
   * and a class of a few long ditches beside wide ponds both count as elongated.
   */
  elongation: number;
}

/** Property names that usually hold a class; such a property is preferred when guessing. */
const CLASS_NAME = /class|klasse|code|type|layer|landuse|land_use|cover|categor|kind|theme|typ/i;
/** The most distinct values a class property may have. */
export const MAX_GUESSED_CLASSES = 256;

/** A class or id value: a string or a whole number (a measure such as an area is neither). */
function classLike(v: unknown): v is string | number {
  return typeof v === 'string' || (typeof v === 'number' && Number.isInteger(v));
}

interface PropertySummary {
  name: string;
  /** Features whose value is a string or a whole number. */
  present: number;
  distinct: number;
}

function summarise(features: InputFeature[]): PropertySummary[] {
  const values = new Map<string, Set<string>>();
  const present = new Map<string, number>();
  for (const f of features) {
    for (const [k, v] of Object.entries(f.properties)) {
      if (!classLike(v)) continue;
      let s = values.get(k);
      if (!s) values.set(k, (s = new Set()));
      s.add(String(v));
      present.set(k, (present.get(k) ?? 0) + 1);
    }
  }
  return [...values].map(([name, s]) => ({ name, present: present.get(name)!, distinct: s.size })).sort((a, b) => (a.name < b.name ? -1 : a.name > b.name ? 1 : 0));
}

export interface ClassPropertyGuess {
  property: string | null;
  /** The candidates considered, best first, with their distinct value counts. */
  candidates: { name: string; distinct: number }[];
}

/**
 * The property that looks most like a class: set on every feature, 2 to MAX_GUESSED_CLASSES
 * distinct values (and fewer than the features, unless there are very few), preferring a
 * class-like name, then the fewest values.
 */
export function guessClassProperty(features: InputFeature[]): ClassPropertyGuess {
  const n = features.length;
  const candidates = summarise(features)
    .filter((p) => p.present === n && p.distinct >= 2 && p.distinct <= MAX_GUESSED_CLASSES && (p.distinct < n || n <= 4))
    .sort((a, b) => Number(CLASS_NAME.test(b.name)) - Number(CLASS_NAME.test(a.name)) || a.distinct - b.distinct)
    .map((p) => ({ name: p.name, distinct: p.distinct }));
  return { property: candidates[0]?.name ?? null, candidates };
}

/** A property named like an identifier whose values are set and unique on every feature, or null. */
export function guessIdProperty(features: InputFeature[]): string | null {
  const n = features.length;
  return summarise(features).find((p) => /id/i.test(p.name) && p.present === n && p.distinct === n && n > 1)?.name ?? null;
}

/** Area and perimeter of a feature (all its polygons; holes subtract area and add boundary). */
export function featureShape(f: InputFeature): { area: number; perimeter: number } {
  let area = 0, perimeter = 0;
  for (const rings of f.polygons) {
    rings.forEach((ring, i) => {
      const a = Math.abs(ringArea2Flat(ring)) / 2;
      area += i === 0 ? a : -a;
      perimeter += ringPerimeterFlat(ring);
    });
  }
  return { area, perimeter };
}

/** The value below which half the total weight lies (the lower one on a tie). */
function weightedMedian(values: number[], weights: number[]): number {
  const order = values.map((_, i) => i).sort((a, b) => values[a]! - values[b]! || a - b);
  const total = weights.reduce((s, w) => s + w, 0);
  let acc = 0;
  for (const i of order) {
    acc += weights[i]!;
    if (acc >= total / 2) return values[i]!;
  }
  return 0;
}

/** Class values in a stable order: numerically when every value is a number, else by code unit. */
export function sortClassKeys(keys: Iterable<string>): string[] {
  const all = [...keys];
  const numeric = all.every((k) => k.trim() !== '' && Number.isFinite(Number(k)));
  return numeric ? all.sort((a, b) => Number(a) - Number(b) || (a < b ? -1 : a > b ? 1 : 0)) : all.sort((a, b) => (a < b ? -1 : a > b ? 1 : 0));
}

/** Per class value (from `classOf`), the faces' count, area and shape, in sortClassKeys order. */
export function classStats(features: InputFeature[], classOf: (f: InputFeature, i: number) => string): ClassStats[] {
  const by = new Map<string, { faces: number; area: number; areas: number[]; widths: number[]; elongations: number[] }>();
  for (const [i, f] of features.entries()) {
    const key = classOf(f, i);
    let c = by.get(key);
    if (!c) by.set(key, (c = { faces: 0, area: 0, areas: [], widths: [], elongations: [] }));
    const { area, perimeter } = featureShape(f);
    c.faces++;
    c.area += area;
    if (area > 0 && perimeter > 0) {
      c.areas.push(area);
      c.widths.push((2 * area) / perimeter);
      c.elongations.push((perimeter * perimeter) / (16 * area));
    }
  }
  return sortClassKeys(by.keys()).map((key) => {
    const c = by.get(key)!;
    const ones = c.areas.map(() => 1);
    return {
      key, faces: c.faces, area: c.area,
      width: weightedMedian(c.widths, c.areas),
      elongation: Math.max(weightedMedian(c.elongations, ones), weightedMedian(c.elongations, c.areas)),
    };
  });
}
