// Where the colour pass compiles patterns in (pattern-range.ts): a hand-made cube whose scale doubles every
// 3 steps (a quarter of the faces), and patterns given by scale ranges.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import type { CubeStyle } from '../../../format/style.js';
import { patternsMeet, patternZRanges } from './pattern-range.js';

describe('pattern z ranges', () => {
  // 1:1,000 with 64 faces at z 0, 16 at z 3 (1:2,000), 4 at z 6 (1:4,000).
  const info = { baseScale: 1000, baseFaces: 64, scaleTable: [[0, 64], [3, 16], [6, 4]] as [number, number][], zMax: 6 };
  const style = {
    classes: [
      { key: 'water', color: '#0000ff', pattern: { kind: 'hatch', color: '#ffffff', maxScale: 2000 } },
      { key: 'field', color: '#00ff00' },
      { key: 'wood', color: '#008000', pattern: { kind: 'dots', color: '#004000', minScale: 4000 } },
    ],
  } as unknown as CubeStyle;

  test('each pattern shows over its scale range turned into z', () => {
    assert.deepEqual(patternZRanges(style, info), [[-1, 3], [6, 1e30]]);
  });

  test('patterns are drawn only when one meets the slice', () => {
    const ranges = patternZRanges(style, info);
    assert.equal(patternsMeet(ranges, 0, 0), true, '1:1,000: the water hatch');
    assert.equal(patternsMeet(ranges, 4, 5), false, 'between 1:2,000 and 1:4,000: none');
    assert.equal(patternsMeet(ranges, 4, 6), true, 'a surface reaching 1:4,000: the wood dots');
    assert.equal(patternsMeet([], 0, 6), false, 'a style without patterns');
  });
});
