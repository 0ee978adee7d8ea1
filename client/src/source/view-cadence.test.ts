// The rest a view needs before its margin is fetched, from hand-made arrival times of views.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { PACE_FACTOR, PAUSE_MS, ViewCadence } from './view-cadence.js';

const after = (times: number[]): ViewCadence => {
  const c = new ViewCadence();
  for (const t of times) c.viewAt(t);
  return c;
};

test('a first view, or views as fast as frames on a phone, rest the minimum', () => {
  assert.equal(new ViewCadence().restMs(300), 300);
  assert.equal(after([0]).restMs(300), 300);
  assert.equal(after([0, 16, 33, 50, 66]).restMs(300), 300);
});

test('views coming slower than the minimum (400 ms frames) rest one and a half times their pace', () => {
  assert.equal(after([0, 400, 800, 1200]).restMs(300), PACE_FACTOR * 400);
  // Two views a frame (a pinch): the slowest of the last gaps sets the pace.
  assert.equal(after([0, 5, 400, 405, 800]).restMs(300), PACE_FACTOR * 395);
});

test('a pause between views is not a pace; only the last three gaps count', () => {
  assert.equal(after([0, 5000, 10000]).restMs(300), 300, 'single jumps seconds apart');
  assert.equal(after([0, 500, 500 + PAUSE_MS + 1]).restMs(300), PACE_FACTOR * 500, 'a zoom, a pause, a jump: the zoom still counts');
  assert.equal(after([0, 600, 700, 800, 900]).restMs(300), 300, 'the slow gap has left the last three');
});
