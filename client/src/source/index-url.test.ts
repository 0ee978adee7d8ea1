import assert from 'node:assert/strict';
import { test } from 'node:test';
import { indexUrl } from './index-url.js';

const page = 'https://example.org/maps/page.html?x=1';

test('a cube directory, with or without its slash, means its index.json', () => {
  assert.equal(indexUrl('cube', page), 'https://example.org/maps/cube/index.json');
  assert.equal(indexUrl('cube/', page), 'https://example.org/maps/cube/index.json');
  assert.equal(indexUrl('/data/cube', page), 'https://example.org/data/cube/index.json');
  assert.equal(indexUrl('https://cdn.example.net/cube?v=2', page), 'https://cdn.example.net/cube/index.json?v=2');
  assert.equal(indexUrl('https://cdn.example.net/', page), 'https://cdn.example.net/index.json');
});

test('a .json file is the index itself, whatever its name', () => {
  assert.equal(indexUrl('cube/index.json', page), 'https://example.org/maps/cube/index.json');
  assert.equal(indexUrl('cube/otterlo.JSON', page), 'https://example.org/maps/cube/otterlo.JSON');
});
