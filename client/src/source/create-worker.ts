// Starts the chunk worker from its own file, next to the bundle (the app and the ES module
// build). The script-tag build swaps this module for create-worker-inline.ts (vite.lib.config.ts).
export function createChunkWorker(): Worker {
  return new Worker(new URL('./chunk-worker.ts', import.meta.url), { type: 'module', name: 'ssc-chunks' });
}
