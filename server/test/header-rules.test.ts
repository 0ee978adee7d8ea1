// The shared serving rules (header-rules.ts) against our server: once serving small files
// from memory (the default) and once streaming every file from disk.
import assert from 'node:assert/strict';
import { after, before, describe, it } from 'node:test';
import { CORS_ORIGIN, makeFixture, type Fixture } from './fixture.js';
import { describeHeaderRules } from './header-rules.js';
import { startOurs, type Started } from './start-server.js';

const configurations = [
  { name: 'files from memory', options: {} },
  { name: 'files streamed from disk', options: { maxCachedFileBytes: 0, cacheBytes: 0 } },
];

for (const { name, options } of configurations) {
  describe(`our server, ${name}`, () => {
    let fx: Fixture;
    let ours: Started;
    before(async () => {
      fx = makeFixture();
      ours = await startOurs({ root: fx.root, cors: [CORS_ORIGIN], ...options });
    });
    after(async () => {
      await ours.server.close();
      fx.remove();
    });

    describeHeaderRules(() => ours, () => fx);

    it('reported no internal errors', () => {
      assert.deepEqual(ours.errors, []);
    });
  });
}
