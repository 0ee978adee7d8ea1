// What the map is told when the index or a sub-index file cannot be had: the request that
// failed (status, or a network error), or a file that is not a cube's index.
import { FetchFailure } from './fetch-retry.js';
import type { SourceErrorInfo } from './worker-protocol.js';

export function indexError(err: unknown, url = ''): SourceErrorInfo {
  if (err instanceof FetchFailure) {
    const info: SourceErrorInfo = { kind: err.kind === 'http' ? 'http' : 'network', message: err.message, url: err.url };
    if (err.status !== undefined) info.status = err.status;
    return info;
  }
  // Not JSON, or JSON that is not an index: the file is not a cube's.
  return { kind: 'index', message: err instanceof Error ? err.message : String(err), url };
}
