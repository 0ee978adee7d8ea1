// Which file on disk answers a request path: the file itself or a directory's index.html,
// as the first precompressed sibling the client accepts that exists, else as itself.
import { SIBLING_SUFFIX, type Coding, type Compressed } from './accept-encoding.js';
import type { LookupCache } from './lookup-cache.js';
import type { Resolved } from './resolve-file.js';

export type FileFound = Extract<Resolved, { kind: 'file' }>;

export type Choice =
  | {
      kind: 'file';
      file: FileFound; // what to send: the file or its sibling
      coding: Coding; // the Content-Encoding that file is in
      name: string; // the name asked for, which decides the type and the caching
      fileSegments: string[]; // the path of `file` below the root
    }
  | { kind: 'add-slash' } // a directory asked for without its trailing slash
  | { kind: 'missing' };

const ADD_SLASH: Choice = { kind: 'add-slash' };
const MISSING: Choice = { kind: 'missing' };

export async function chooseFile(lookups: LookupCache, segments: string[], trailingSlash: boolean, codings: readonly Compressed[]): Promise<Choice> {
  let fileSegments = segments;
  let found = await lookups.resolve(segments);
  if (found.kind === 'directory') {
    // The root itself has no slash to add.
    if (!trailingSlash && segments.length > 0) return ADD_SLASH;
    fileSegments = [...segments, 'index.html'];
    found = await lookups.resolve(fileSegments);
  } else if (trailingSlash) {
    return MISSING; // a file is not a directory
  }
  if (found.kind !== 'file') return MISSING;
  const name = fileSegments[fileSegments.length - 1]!;
  const dir = fileSegments.slice(0, -1);
  // One sibling at a time, in the client's order: a remembered lookup is a single stat, so
  // stopping at the first one found costs less than asking for all of them at once.
  for (const coding of codings) {
    const siblingSegments = [...dir, name + SIBLING_SUFFIX[coding]];
    const sibling = await lookups.resolve(siblingSegments);
    if (sibling.kind === 'file') return { kind: 'file', file: sibling, coding, name, fileSegments: siblingSegments };
  }
  return { kind: 'file', file: found, coding: 'identity', name, fileSegments };
}
