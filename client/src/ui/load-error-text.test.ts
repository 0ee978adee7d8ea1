import assert from 'node:assert/strict';
import { test } from 'node:test';
import { loadErrorText } from './load-error-text.js';

const url = 'https://example.org/cube/index.json';

test('each cause is named with the URL', () => {
  assert.equal(loadErrorText({ kind: 'http', status: 404, url, message: 'HTTP 404' }), `${url} was not found (HTTP 404).`);
  assert.equal(loadErrorText({ kind: 'http', status: 500, url, message: 'HTTP 500' }), `The server answered HTTP 500 for ${url}.`);
  assert.match(loadErrorText({ kind: 'network', url, message: 'Failed to fetch' }), /^https:\/\/example\.org\/cube\/index\.json could not be fetched: .*CORS/);
  assert.equal(loadErrorText({ kind: 'index', url, message: 'index.json: meta is missing' }), `${url} is not a cube (the index.json that ssc build writes): index.json: meta is missing`);
  assert.match(loadErrorText({ kind: 'worker', url, message: "the map's worker could not be started" }), /^The map's worker script could not be loaded, so https:\/\/example\.org\/cube\/index\.json cannot be shown: .*beside vario-map\.js.*worker-src/);
});
