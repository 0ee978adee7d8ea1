// index.json read and checked on the map's main thread, while the worker's script still loads:
// the map takes the cube's metadata and starts its first view's chunks without waiting for the
// worker (ChunkSource), and the worker gets the checked index.
import { parseIndex, type CubeIndex } from '../../../format/cube-index.js';
import { fetchJson, type RetryOptions } from './fetch-retry.js';

/** index.json fetched and checked: throws FetchFailure, or an Error naming what is not an index. */
export async function readIndex(indexUrl: string, retry: RetryOptions): Promise<CubeIndex> {
  return parseIndex(await fetchJson(indexUrl, retry));
}
