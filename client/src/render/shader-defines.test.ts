// Shader variants: the defines go after #version (which must stay the first line).
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { withDefines } from './shader-defines.js';

test('withDefines puts each define after the #version line and leaves the rest as it is', () => {
  const src = '#version 300 es\nprecision highp float;\nvoid main() {}\n';
  assert.equal(withDefines(src, []), src);
  assert.equal(withDefines(src, ['FLAT', 'STATES']), '#version 300 es\n#define FLAT\n#define STATES\nprecision highp float;\nvoid main() {}\n');
});
