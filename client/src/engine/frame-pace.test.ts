// The device's time per frame, from hand-made start times of the frames drawn.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { FramePace, PAUSE_MS } from './frame-pace.js';

const after = (times: number[]): number => {
  const p = new FramePace();
  for (const t of times) p.frameAt(t);
  return p.ms;
};

test('unknown until two frames came less than a pause apart', () => {
  assert.equal(after([]), 0);
  assert.equal(after([0]), 0);
  assert.equal(after([0, 5000, 10000]), 0, 'single frames seconds apart');
});

test('frames back to back give the device\'s pace; pauses between them do not lengthen it', () => {
  assert.equal(after([0, 16, 33, 50]), 16);
  assert.equal(after([0, 400, 800, 1200]), 400, 'a software GPU');
  assert.equal(after([0, 400, 800, 800 + PAUSE_MS / 2, 800 + PAUSE_MS / 2 + 400]), 400, 'a click half a second after a zoom');
});

test('the shortest of the last five gaps', () => {
  assert.equal(after([0, 400, 800, 816]), 16);
  assert.equal(after([0, 16, 32, 432, 832, 1232, 1632]), 16, 'a fast gap among the last five');
  assert.equal(after([0, 16, 416, 816, 1216, 1616, 2016]), 400, 'the fast gap has left them');
});
