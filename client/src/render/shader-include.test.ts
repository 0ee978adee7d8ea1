// Shader includes: the line is replaced by the chunk, nothing else changes.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { withIncludes } from './shader-include.js';

test('withIncludes puts each chunk in place of its #include line and leaves the rest as it is', () => {
  const src = '#version 300 es\nprecision highp float;\n#include "a.glsl"\nvoid main() {}\n#include "a.glsl"\n';
  assert.equal(withIncludes(src, { 'a.glsl': 'float a() { return 1.0; }\n' }), '#version 300 es\nprecision highp float;\nfloat a() { return 1.0; }\nvoid main() {}\nfloat a() { return 1.0; }\n');
  assert.equal(withIncludes('void main() {}\n', {}), 'void main() {}\n');
});

test('an include that is not given is an error naming it', () => {
  assert.throws(() => withIncludes('#include "b.glsl"\n', { 'a.glsl': '' }), /includes "b.glsl", which is not given \(given: a.glsl\)/);
});
