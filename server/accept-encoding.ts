// Which content codings to try for a response, from the request's Accept-Encoding
// (RFC 9110 §12.5.3): the client's q-values decide, brotli wins ties over gzip, and identity
// is always the last resort because every file has it.

export type Coding = 'br' | 'gzip' | 'identity';
export type Compressed = Exclude<Coding, 'identity'>;

/** The precompressed sibling of `name` for a coding is `name + suffix`. */
export const SIBLING_SUFFIX: Readonly<Record<Compressed, string>> = { br: '.br', gzip: '.gz' };

// Our preference among equally weighted codings: the smallest first.
const PREFERENCE: readonly Coding[] = ['br', 'gzip', 'identity'];
const QVALUE = /^(?:0(?:\.\d{0,3})?|1(?:\.0{0,3})?)$/;
// Below any q a client can write (0.001), so an unlisted identity loses to any listed coding.
const IMPLICIT_IDENTITY_Q = 0.0001;

/**
 * Codings to try in order. A missing or empty header means identity only: a client that says
 * nothing (curl, wget) could not decode anything else.
 */
export function codingsToTry(header: string | undefined): Coding[] {
  if (header === undefined || header.trim() === '') return ['identity'];
  const listed = new Map<string, number>();
  for (const element of header.split(',')) {
    const [rawName, ...params] = element.split(';');
    const name = rawName!.trim().toLowerCase();
    if (name === '') continue;
    let q = 1;
    let valid = true;
    for (const param of params) {
      const eq = param.indexOf('=');
      if (eq < 0 || param.slice(0, eq).trim().toLowerCase() !== 'q') continue;
      const value = param.slice(eq + 1).trim();
      if (QVALUE.test(value)) q = Number(value);
      else valid = false;
    }
    // A malformed weight says nothing we can trust about that coding: skip it.
    if (!valid) continue;
    const key = name === 'x-gzip' ? 'gzip' : name;
    if (!listed.has(key)) listed.set(key, q);
  }
  const star = listed.get('*');
  const weight = (c: Coding): number => {
    const explicit = listed.get(c);
    if (explicit !== undefined) return explicit;
    if (c === 'identity') return star === 0 ? 0 : IMPLICIT_IDENTITY_Q;
    return star ?? 0;
  };
  const order = PREFERENCE.filter((c) => weight(c) > 0).sort((a, b) => weight(b) - weight(a) || PREFERENCE.indexOf(a) - PREFERENCE.indexOf(b));
  if (!order.includes('identity')) order.push('identity');
  return order;
}

// Clients send one of a handful of Accept-Encoding values, so each answer is remembered by the
// header's exact text. The bound keeps a client that sends endless variations from growing it.
const REMEMBERED_HEADERS = 64;
const remembered = new Map<string, readonly Compressed[]>();
const NONE: readonly Compressed[] = Object.freeze([]);

/**
 * The precompressed copies worth looking for, best first: only codings the client prefers to
 * identity, since identity (the file itself) is always there.
 */
export function siblingCodings(header: string | undefined): readonly Compressed[] {
  if (header === undefined) return NONE;
  let codings = remembered.get(header);
  if (codings === undefined) {
    const order = codingsToTry(header);
    codings = Object.freeze(order.slice(0, order.indexOf('identity')).filter((c): c is Compressed => c !== 'identity'));
    if (remembered.size >= REMEMBERED_HEADERS) remembered.clear();
    remembered.set(header, codings);
  }
  return codings;
}
