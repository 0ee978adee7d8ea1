import assert from 'node:assert/strict';
import { test } from 'node:test';
import { changeShare, classChange } from './class-change.js';

test('classChange counts class changes among the pixels with a face in both frames', () => {
  // 8 pixels. 0 and 1: no face in one frame (outside the domain, although the class differs).
  // 2: same face, same class. 3: another face of the same class (a merge within a class: no
  // change seen). 4 and 5: another class. 6: same face id, class changed (a re-coloured face
  // counts: the class is what is seen). 7: no face in either.
  const before = { ids: new Uint32Array([0, 5, 1, 2, 3, 3, 4, 0]), classes: new Uint16Array([0, 2, 1, 1, 1, 1, 2, 0]) };
  const after = { ids: new Uint32Array([6, 0, 1, 7, 8, 9, 4, 0]), classes: new Uint16Array([3, 0, 1, 1, 2, 0, 1, 0]) };
  const c = classChange(before, after);
  assert.deepEqual(c, { domain: 5, changed: 3 });
  assert.equal(changeShare(c), 3 / 5);
});

test('classChange is symmetric and zero for identical frames', () => {
  const a = { ids: new Uint32Array([1, 2, 0]), classes: new Uint16Array([0, 1, 0]) };
  const b = { ids: new Uint32Array([1, 3, 4]), classes: new Uint16Array([0, 0, 1]) };
  assert.deepEqual(classChange(a, b), classChange(b, a));
  assert.deepEqual(classChange(a, a), { domain: 2, changed: 0 });
});

test('an empty domain is a share of 0; frames of different sizes are refused', () => {
  const none = { ids: new Uint32Array(2), classes: new Uint16Array(2) };
  assert.equal(changeShare(classChange(none, none)), 0);
  assert.throws(() => classChange(none, { ids: new Uint32Array(3), classes: new Uint16Array(3) }), /different sizes/);
});
