// parseTargetPath: the request target as plain file-name segments, or the reason to refuse it.
// Every traversal attempt the server tests send is refused here or becomes plain names (the
// symlinks among them are refused when the file is resolved, see resolve-file.ts).
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { parseTargetPath, pathForSegments, type TargetPath } from './url-path.js';
import { TRAVERSAL_TARGETS } from './test/traversal-attempts.js';

const ok = (segments: string[], trailingSlash = false, query = ''): TargetPath => ({ ok: true, segments, trailingSlash, query });
const refused = (status: 400 | 404): TargetPath => ({ ok: false, status });

test('paths become decoded segments, slashes and the query set apart', () => {
  const cases: [string, TargetPath][] = [
    ['/', ok([], true)],
    ['/index.json', ok(['index.json'])],
    ['/a%20file.json', ok(['a file.json'])],
    ['//sub//data.json', ok(['sub', 'data.json'])],
    ['/sub/', ok(['sub'], true)],
    ['/index.json?v=2', ok(['index.json'], false, '?v=2')],
    ['/index.json#top', ok(['index.json'])],
    ['/%25zz.json', ok(['%zz.json'])], // decoded once: %25 is a percent sign, nothing more
    ['http://127.0.0.1/index.json', ok(['index.json'])], // absolute-form
    ['HTTP://127.0.0.1', ok([], true)], // an empty path is the root
  ];
  for (const [target, expected] of cases) assert.deepEqual(parseTargetPath(target), expected, target);
});

test('what cannot be a path under the root is refused: 400, or 404 for a dotfile', () => {
  const cases: [string, TargetPath][] = [
    ['*', refused(400)],
    ['index.json', refused(400)],
    ['/%zz', refused(400)],
    ['/%ff%fe.json', refused(400)], // not UTF-8
    ['/sub%2fdata.json', refused(400)], // an encoded slash never separates
    ['/..', refused(400)],
    ['/./index.json', refused(400)],
    ['/a\\b', refused(400)],
    ['/a%00b', refused(400)],
    ['/a%0ab', refused(400)],
    ['/.git/config', refused(404)],
    ['/sub/.env', refused(404)],
  ];
  for (const [target, expected] of cases) assert.deepEqual(parseTargetPath(target), expected, target);
});

test('every traversal attempt is refused, or is made of plain names only', () => {
  for (const target of TRAVERSAL_TARGETS) {
    const parsed = parseTargetPath(target);
    if (!parsed.ok) continue;
    for (const segment of parsed.segments) {
      assert.ok(segment !== '..' && segment !== '.' && !/[/\\\0]/.test(segment) && !segment.startsWith('.'), `${target}: segment ${JSON.stringify(segment)}`);
    }
  }
});

test('segments become a path again, each percent-encoded, so it cannot leave this server', () => {
  assert.equal(pathForSegments(['a file', 'x?y'], true), '/a%20file/x%3Fy/');
  assert.equal(pathForSegments(['sub'], false), '/sub');
  assert.equal(pathForSegments([], true), '/');
});
