// The easings: in and out at rest, and the one that continues a zoom at its pace.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { continuingEasing, easeInOut, easingSpeed } from './easing.js';

const close = (a: number, b: number, tol: number, what = ''): void => assert.ok(Math.abs(a - b) <= tol, `${what} ${a} vs ${b}`);

describe('easing', () => {
  test('ease-in-out starts and ends at rest', () => {
    assert.equal(easeInOut(0), 0);
    assert.equal(easeInOut(1), 1);
    assert.ok(easingSpeed(easeInOut, 0) < 0.1 && easingSpeed(easeInOut, 0.99) < 0.1 && easingSpeed(easeInOut, 0.5) > 1.4);
  });

  test('a continuing zoom starts at the pace it is given', () => {
    for (const speed of [0.5, 1, 2]) close(easingSpeed(continuingEasing(speed), 0), speed, 0.15 * speed, `slope ${speed}`);
    assert.equal(continuingEasing(0), easeInOut, 'from rest: ease in and out');
  });
});
