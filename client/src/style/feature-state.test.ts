// Feature state: merged per face, removed by key or whole, and only `true` draws a state;
// face ids outside the cube are refused with the range named.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { FeatureStates } from './feature-state.js';

describe('feature state', () => {
  test('states merge, and are removed by key or whole', () => {
    const s = new FeatureStates();
    s.set({ face: 5 }, { highlight: true });
    s.set({ face: 5 }, { note: 'picked' });
    assert.deepEqual(s.get({ face: 5 }), { highlight: true, note: 'picked' });
    assert.deepEqual(s.get({ face: 6 }), {});
    s.set({ face: 9 }, { highlight: 'yes', hover: true });
    const drawn = ['hover', 'highlight'];
    assert.equal(s.bits(5, drawn), 2, 'highlight: bit 1');
    assert.equal(s.bits(9, drawn), 1, 'only true draws: hover alone');
    s.set({ face: 9 }, { highlight: true });
    assert.equal(s.bits(9, drawn), 3);
    s.remove({ face: 5 }, 'highlight');
    assert.deepEqual(s.get({ face: 5 }), { note: 'picked' });
    assert.equal(s.bits(5, drawn), 0);
    s.remove({ face: 5 });
    assert.deepEqual(s.get({ face: 5 }), {});
  });

  test('a copy is returned: changing it changes nothing', () => {
    const s = new FeatureStates();
    s.set({ face: 2 }, { highlight: true });
    const got = s.get({ face: 2 });
    got.highlight = false;
    assert.equal(s.bits(2, ['highlight']), 1);
  });

  test('bad faces and states are named', () => {
    const s = new FeatureStates();
    s.faceCount = 100;
    assert.throws(() => s.set({ face: 100 }, { highlight: true }), /setFeatureState: \{ face \} must be a face id \(an integer from 1 to 99\), not 100/);
    assert.throws(() => s.set({ face: 0 }, { highlight: true }), /not 0/);
    assert.throws(() => s.get({ face: 1.5 }), /getFeatureState: .*not 1\.5/);
    assert.throws(() => s.remove({} as { face: number }), /removeFeatureState: .*not undefined/);
    assert.throws(() => s.set({ face: 3 }, null as unknown as Record<string, unknown>), /the state must be an object/);
  });
});
