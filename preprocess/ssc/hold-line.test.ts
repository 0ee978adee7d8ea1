// Where a loser's area comes back to its class along the winner's line, on hand-made face lists.
import test from 'node:test';
import assert from 'node:assert/strict';
import { EventKind, phaseZ, REEMIT_PHASE, scaleInfoOf, type Tgap, type TgapEvent, type TgapFace } from '../../format/tgap-model.js';
import { reemitBefore, reemitsHeldAcross, returnOnLine } from './hold-line.js';

const STEPS = 20;
/** A face of class c alive from step lo to hi, then merged into `into` (-1: split or never; phase: its end phase). */
const face = (c: number, lo: number, hi: number, into = -1, phase = 0): TgapFace => ({ classIndex: c, feature: -1, stepLow: lo, stepHigh: hi, mergedInto: into, endPhase: phase, area2: 2 });

// Face 0 unused. X (1, class 0) merges into W (2, class 1) at step 3. W is re-emitted as R (3) at
// step 5, R merges into S (4, class 1) at step 8, S into T (5, class 0) at step 11. T lives on,
// re-emitted as U (6) at step 14.
const LINE: TgapFace[] = [
  face(0, 0, 0),
  face(0, 0, 3, 2),
  face(1, 0, 5, 3, REEMIT_PHASE),
  face(1, 5, 8, 4),
  face(1, 0, 11, 5),
  face(0, 0, 14, 6, REEMIT_PHASE),
  face(0, 14, STEPS + 1),
];

test('the line follows re-emits and merges into faces of its class to the merge that brings the area back', () => {
  assert.equal(returnOnLine(LINE, 2, 0, STEPS, Infinity), 4, 'S merges into T, of class 0');
  assert.equal(returnOnLine(LINE, 2, 0, STEPS, phaseZ(11, 0)), 4, 'just within the limit');
  assert.equal(returnOnLine(LINE, 2, 0, STEPS, phaseZ(11, 0) - 1e-9), -1, 'S ends past the limit');
  assert.equal(returnOnLine(LINE, 2, 2, STEPS, Infinity), -1, 'no face of class 2 on the line: it lives to the top');
});

test('a re-emit on the way to the face that brings the area back is seen; the returning face\'s own end is not on the way', () => {
  assert.equal(reemitBefore(LINE, 2, 4), true, 'W is re-emitted as R');
  assert.equal(reemitBefore(LINE, 3, 4), false, 'R merges into S');
  assert.equal(reemitBefore(LINE, 5, 5), false, 'T itself, re-emitted after');
});

test('the line crosses other classes, and a split ends it', () => {
  // W (class 1) merges into M (class 2) at 4, M is split at 9.
  const faces = [face(0, 0, 0), face(0, 0, 2, 2), face(1, 0, 4, 3), face(2, 0, 9)];
  assert.equal(returnOnLine(faces, 2, 0, STEPS, Infinity), 3, 'the split may give the area back');
  // M merges into N (class 0) instead.
  const back = [face(0, 0, 0), face(0, 0, 2, 2), face(1, 0, 4, 3), face(2, 0, 9, 4), face(0, 0, STEPS + 1)];
  assert.equal(returnOnLine(back, 2, 0, STEPS, Infinity), 3);
  assert.equal(returnOnLine(back, 2, 1, STEPS, Infinity), -1, 'nothing of class 1 after W');
});

test('the re-emits a hold may cross are those on the line before the area comes back, not after', () => {
  const events: TgapEvent[] = [
    { kind: EventKind.Merge, step: 3, loser: 1, into: 2 },
    { kind: EventKind.Reemit, step: 5, loser: 2, into: 3 },
    { kind: EventKind.Merge, step: 8, loser: 3, into: 4 },
    { kind: EventKind.Merge, step: 11, loser: 4, into: 5 },
    { kind: EventKind.Reemit, step: 14, loser: 5, into: 6 },
  ];
  const facesAlive = Array.from({ length: STEPS + 1 }, (_, s) => 100 - 2 * s);
  const t = { meta: { steps: STEPS, baseScale: 1000, baseFaces: 100, facesAlive }, faces: LINE, events } as unknown as Tgap;
  const info = scaleInfoOf(t);
  assert.deepEqual([...reemitsHeldAcross(t, info, 8)], [3], 'R, between W and S; not U, after the return');
  // Scale 1:1,000 x sqrt(100 / faces alive): about x1.1 from step 3 to step 11, past a limit of x1.05.
  assert.deepEqual([...reemitsHeldAcross(t, info, 1.05)], []);
});
