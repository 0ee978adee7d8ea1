// Colours for the classes of data without a style (docs/STYLE.md, "How ssc style colours
// classes"): a known nomenclature's legend first, then a colour suggested by the class name
// (water blue, forest green, ...), then a fixed palette that holds no blue, so that a class
// nothing is known about never looks like water.
import { NOMENCLATURES, type KnownClass } from './nomenclatures.js';

export interface ChosenClass {
  key: string;
  label: string;
  color: string;
  weight: number;
  /** Where the colour came from: a nomenclature's name, "name: <theme>" or "palette". */
  source: string;
}

interface Theme {
  name: string;
  /** Matched against the lower-case class value; the first theme that matches wins. */
  words: RegExp;
  color: string;
  weight: number;
}

// Order matters: "wetland" before "water" and "wood", "onbegroeid" (bare) before "begroeid".
const THEMES: Theme[] = [
  { name: 'wetland', words: /wetland|marsh|bog|swamp|moeras|veen|sumpf|ried|marais/, color: '#a9cfc4', weight: 1.5 },
  { name: 'water', words: /water|river|lake|sea\b|ocean|stream|canal|pond|reservoir|sloot|gracht|meer|rivier|kanaal|vijver|gewässer|fluss|\bsee\b|\beau\b|\blac\b|rivière/, color: '#9ec9e8', weight: 2.5 },
  { name: 'snow and ice', words: /glacier|gletscher|snow|\bice\b|sneeuw|schnee|neige/, color: '#eef5fb', weight: 2 },
  { name: 'bare', words: /onbegroeid|bare|barren|sand|zand|rock|rots|fels|beach|dune|duin|gravel|kies|unpaved|onverhard/, color: '#e9dfc6', weight: 0.8 },
  { name: 'building', words: /build|pand|gebouw|gebäude|house|huis|urban|residential|industr|commerc|bebouw|developed|\bbâti/, color: '#c98f7e', weight: 3 },
  { name: 'transport', words: /road|\bweg|weg\b|wegdeel|street|straat|strasse|straße|rail|spoor|path|\bpad\b|parking|transport|verkeer|highway|route/, color: '#dcd8d0', weight: 1.5 },
  { name: 'forest', words: /forest|wood|\bbos|bos\b|wald|forêt|tree|bomen|loofbos|naaldbos/, color: '#68ab63', weight: 1.1 },
  { name: 'shrub and heath', words: /shrub|scrub|heath|heide|struik|brush|gebüsch|lande/, color: '#a9c27a', weight: 1 },
  { name: 'crops', words: /arable|crop|akker|acker|farm|agri|cultivat|orchard|vineyard|boomgaard|weinbau/, color: '#f2e27d', weight: 1 },
  { name: 'grass and vegetation', words: /grass|gras|meadow|pasture|weide|wiese|lawn|park|green|groen|begroeid|vegetat|herbaceous|prairie/, color: '#cde59a', weight: 1 },
  { name: 'paved', words: /paved|verhard|pavement|asphalt/, color: '#d6d2cb', weight: 1 },
];

/** Distinct colours for classes nothing is known about: no blue (water) among them. */
export const PALETTE = ['#fdb462', '#cdb5d6', '#b3de69', '#fccde5', '#ffed6f', '#d9d9d9', '#fb8072', '#bc80bd', '#ccebc5', '#e5c494', '#c7a76c', '#f1b6da'];

/** The colour of the single class when the data has no class property. */
export const ONE_CLASS_COLOR = '#e0dccf';

/** The n-th variant of a colour: the colour, then alternately darker and lighter in growing steps. */
export function shade(hex: string, n: number): string {
  if (n === 0) return hex.toLowerCase();
  const f = (n % 2 === 1 ? -1 : 1) * 0.12 * Math.ceil(n / 2);
  const channel = (i: number): string => {
    const c = parseInt(hex.slice(1 + 2 * i, 3 + 2 * i), 16);
    const v = f < 0 ? c * (1 + f) : c + (255 - c) * f;
    return Math.round(Math.min(255, Math.max(0, v))).toString(16).padStart(2, '0');
  };
  return `#${channel(0)}${channel(1)}${channel(2)}`;
}

/** The nomenclature whose legend applies to these class values, if any. */
function numericNomenclatureOf(keys: string[]): (typeof NOMENCLATURES)[number] | undefined {
  return NOMENCLATURES.find((n) => n.numeric && keys.length > 0 && keys.every((k) => Object.hasOwn(n.classes, k)));
}

/** Colour, label and weight of every class value, in the order given. Deterministic. */
export function chooseClassColours(keys: string[]): ChosenClass[] {
  const numeric = numericNomenclatureOf(keys);
  const named = NOMENCLATURES.filter((n) => !n.numeric);
  // How often each colour was handed out, so that classes of one theme stay apart.
  const uses = new Map<string, number>();
  const take = (base: string): string => {
    const n = uses.get(base) ?? 0;
    uses.set(base, n + 1);
    return shade(base, n);
  };
  let paletteIndex = 0;
  return keys.map((key) => {
    const lower = key.toLowerCase();
    const known: [KnownClass, string] | undefined = numeric
      ? [numeric.classes[key]!, numeric.name]
      : named.flatMap((n): [KnownClass, string][] => (Object.hasOwn(n.classes, lower) ? [[n.classes[lower]!, n.name]] : []))[0];
    if (known) return { key, label: known[0].label, color: take(known[0].color), weight: known[0].weight ?? 1, source: known[1] };
    const theme = THEMES.find((t) => t.words.test(lower));
    if (theme) return { key, label: key, color: take(theme.color), weight: theme.weight, source: `name: ${theme.name}` };
    const i = paletteIndex++;
    return { key, label: key, color: shade(PALETTE[i % PALETTE.length]!, Math.floor(i / PALETTE.length)), weight: 1, source: 'palette' };
  });
}

/** Where the colours of these classes come from, e.g. "NLCD (8)" or "their names (3), a fixed palette (2)". */
export function describeColourSources(keys: string[]): string {
  const counts = new Map<string, number>();
  for (const c of chooseClassColours(keys)) {
    const what = c.source === 'palette' ? 'a fixed palette' : c.source.startsWith('name: ') ? 'their names' : `the ${c.source} legend`;
    counts.set(what, (counts.get(what) ?? 0) + 1);
  }
  return [...counts].map(([what, n]) => `${what} (${n})`).join(', ');
}
