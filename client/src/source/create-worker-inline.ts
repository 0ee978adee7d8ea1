// Starts the chunk worker from a copy inlined in the bundle (a blob URL): the script-tag build
// has no module URL to find a separate worker file by, and a page may load it from another
// origin, where a worker file could not be started at all.
import ChunkWorker from './chunk-worker.ts?worker&inline';

export function createChunkWorker(): Worker {
  return new ChunkWorker({ name: 'ssc-chunks' });
}
