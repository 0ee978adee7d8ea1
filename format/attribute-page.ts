// An attribute page (docs/FORMAT.md, "Attribute page a-<hash>.json"): the input properties of
// a run of features, for picking. Encoder and decoder. Pure.
import * as v from 'valibot';
import { FormatError } from './format-error.js';
import { describeIssues } from './schema-issues.js';

/** Features per page (the build's choice; a reader takes `first` from the page). */
export const ATTRIBUTE_PAGE_SIZE = 4096;

const AttributePageSchema = v.object({
  first: v.pipe(v.number('must be a number'), v.integer('must be an integer'), v.minValue(0, 'must be >= 0')),
  attributes: v.array(v.nullable(v.record(v.string(), v.unknown(), 'must be an object or null')), 'must be an array'),
});

export type AttributePage = v.InferOutput<typeof AttributePageSchema>;

/** The page of attributes[first .. first + ATTRIBUTE_PAGE_SIZE) as UTF-8 JSON. */
export function encodeAttributePage(attributes: readonly (Record<string, unknown> | null)[], first: number): Uint8Array {
  return new TextEncoder().encode(JSON.stringify({ first, attributes: attributes.slice(first, first + ATTRIBUTE_PAGE_SIZE) }));
}

export function decodeAttributePage(json: unknown, file: string): AttributePage {
  const r = v.safeParse(AttributePageSchema, json);
  if (!r.success) throw new FormatError(`not an attribute page: ${describeIssues(r.issues).join('; ')}`, file);
  return r.output;
}

/** The properties of feature `feature` from a page that holds it (null: none recorded). */
export function featureAttributes(page: AttributePage, feature: number): Record<string, unknown> | null {
  return page.attributes[feature - page.first] ?? null;
}
