#!/usr/bin/env node
// npm start (after npm run build): builds the bundled dataset's cube into chunks/ when it is
// missing or older than its inputs (the GeoJSON, the style, the compiled builder), then serves
// the full-page demo (dist/client/demo.html) and the cube (at /chunks/) from 127.0.0.1 with the
// project's static server until Ctrl-C. PORT picks the port (default 8080, else a free one).
import { spawnSync } from 'node:child_process';
import { existsSync, readdirSync, statSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const input = path.join(root, 'data/bgt_otterlo_1800m.geojson');
const style = path.join(root, 'styles/bgt.json');
const out = path.join(root, 'chunks');
const clientDir = path.join(root, 'dist/client');

/** Newest modification time of a file or of any file below a directory. */
function newest(p) {
  const st = statSync(p);
  if (!st.isDirectory()) return st.mtimeMs;
  let t = 0;
  for (const name of readdirSync(p)) t = Math.max(t, newest(path.join(p, name)));
  return t;
}

function cubeIsCurrent() {
  const index = path.join(out, 'index.json');
  if (!existsSync(index)) return false;
  const inputs = Math.max(newest(input), newest(style), newest(path.join(root, 'dist/preprocess')));
  return statSync(index).mtimeMs >= inputs;
}

if (cubeIsCurrent()) {
  console.log(`The cube in ${path.relative(process.cwd(), out) || '.'}/ is up to date.`);
} else {
  console.log(`Building the cube of ${path.relative(root, input)} into chunks/ ...`);
  // ssc build replaces the directory only once the new cube is complete.
  const r = spawnSync(process.execPath, [path.join(root, 'bin/ssc.js'), 'build', input, '--style', style, '--out', out], { stdio: 'inherit', cwd: root });
  if (r.status !== 0) process.exit(r.status ?? 1);
}

const { createSiteServer } = await import(path.join(root, 'dist/server/site-server.js'));
// One origin for both: /chunks/... is the cube, everything else the built client.
const site = createSiteServer({ clientDir, cubeDir: out });

let port;
try {
  port = await site.listen(Number(process.env.PORT ?? 8080), '127.0.0.1');
} catch (err) {
  if (err.code !== 'EADDRINUSE' || process.env.PORT) throw err;
  port = await site.listen(0, '127.0.0.1');
}
console.log(`\nThe vario-scale map of Otterlo: http://127.0.0.1:${port}/\n(Ctrl-C stops the server.)`);

const stop = () => {
  void site.close().then(() => process.exit(0));
};
process.on('SIGINT', stop);
process.on('SIGTERM', stop);
