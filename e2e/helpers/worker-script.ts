// The map's worker script in a test server's log: the map's head start on a first view is
// measured against it (what the map fetches for the worker while its script is still coming).
import assert from 'node:assert/strict';
import type { LoggedRequest } from './test-server.js';

/** The worker's script, as the test page's build names it. */
export const WORKER_SCRIPT = /^\/assets\/chunk-worker-[\w-]+\.js$/;

/**
 * Asserts that `asked`, the first request for `what`, went out while the worker's script (its
 * request in `log`, served) was still coming: at least 500 ms before it came.
 */
export function assertAskedBeforeScript(log: readonly LoggedRequest[], what: string, asked: LoggedRequest | undefined): void {
  const script = log.find((e) => WORKER_SCRIPT.test(e.path));
  assert.ok(script && script.outcome === 200, 'the worker\'s script was served');
  assert.ok(asked, `${what} asked for`);
  assert.ok(asked.start < script.end - 500, `${what} asked for ${asked.start - script.start} ms after the worker's script was, which came after ${script.end - script.start} ms`);
}
