// nginx with exactly the configuration in docs/deploy.md (server/nginx.conf.template, filled
// in) must follow the same serving rules as our server. Skipped only where nginx is missing.
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, describe, test } from 'node:test';
import { repoRoot } from '../../testing/paths.js';
import { contentTypeTable } from '../content-types.js';
import { NGINX_BIN, startNginx, TEMPLATE_PATH, type RunningNginx } from '../nginx-process.js';
import { makeFixture, type Fixture } from './fixture.js';
import { describeHeaderRules } from './header-rules.js';

const template = readFileSync(TEMPLATE_PATH, 'utf8');

test('docs/deploy.md shows the nginx config exactly as tested', () => {
  const doc = readFileSync(path.join(repoRoot, 'docs/deploy.md'), 'utf8');
  assert.ok(doc.includes('```nginx\n' + template + '```\n'), 'copy server/nginx.conf.template into docs/deploy.md unchanged');
});

test('the nginx types block gives every extension the type our server gives it', () => {
  const block = /\btypes \{\n([\s\S]*?)\n\s*\}/.exec(template)![1]!;
  const nginxTypes = new Map<string, string>();
  for (const line of block.split('\n')) {
    const [type, ...exts] = line.trim().replace(/;$/, '').split(/\s+/);
    for (const ext of exts) nginxTypes.set(ext, type!);
  }
  // Our text types carry their charset; nginx adds it through charset_types.
  const ours = new Map([...contentTypeTable()].map(([ext, type]) => [ext, type.replace('; charset=utf-8', '')]));
  assert.deepEqual(nginxTypes, ours);
});

if (!existsSync(NGINX_BIN)) {
  // Not skipped: `npm test` promises the documented config is tested (.ci/run installs nginx).
  test('nginx follows the serving rules', () => {
    assert.fail(`${NGINX_BIN} not found: install Debian's nginx package (apt-get install nginx) to test the documented config`);
  });
} else {
  describe('nginx with the documented config', () => {
    let fx: Fixture;
    let nginx: RunningNginx;
    before(async () => {
      fx = makeFixture();
      nginx = await startNginx(fx.root);
    });
    after(async () => {
      await nginx?.stop();
      fx?.remove();
    });
    describeHeaderRules(() => ({ base: nginx.url, port: nginx.port }), () => fx);
  });
}
