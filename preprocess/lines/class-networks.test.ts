import test from 'node:test';
import assert from 'node:assert/strict';
import { classNetworks } from './class-networks.js';

test('classes joined by network are one network, numbered by the first class, through chains either way', () => {
  const classes = [{ key: 'field' }, { key: 'bridge', network: 'road' }, { key: 'road' }, { key: 'ferry', network: 'bridge' }, { key: 'water' }];
  assert.deepEqual([...classNetworks(classes)], [0, 1, 1, 1, 4]);
  assert.deepEqual([...classNetworks([{ key: 'a', network: 'b' }, { key: 'b', network: 'a' }, { key: 'c' }])], [0, 0, 2]);
});
