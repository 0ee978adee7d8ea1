// The page templates embedders copy (the HTML pages in docs/*.md and the demo page) are fit for
// phones and screen readers: a viewport meta tag (else a phone lays out 980 px and the map's
// canvas is several times the screen) and the map inside a <main> landmark.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, test } from 'node:test';
import { docsPageTemplates, htmlCodeBlocks } from './html-code-blocks.js';
import { repoRoot } from './paths.js';

const VIEWPORT = '<meta name="viewport" content="width=device-width, initial-scale=1">';

/** The docs' pages and the demo page, by where they are. */
function templates(): [string, string][] {
  return [...docsPageTemplates(), ['client/demo.html', readFileSync(path.join(repoRoot, 'client/demo.html'), 'utf8')]];
}

describe('docs page templates', () => {
  test('the HTML blocks of Markdown are found', () => {
    assert.deepEqual(htmlCodeBlocks('a\n```html\n<p>1</p>\n```\n```ts\nx\n```\n```html\n<p>2</p>\n```\n'), ['<p>1</p>\n', '<p>2</p>\n']);
  });

  test('every page template has a viewport meta tag and the map inside <main>', () => {
    const pages = templates();
    assert.ok(pages.length >= 3, `the two pages of docs/embedding.md and the demo: ${pages.map(([w]) => w)}`);
    for (const [where, html] of pages) {
      assert.ok(html.includes(VIEWPORT), `${where}: ${VIEWPORT}`);
      const main = /<main\b[^>]*>([\s\S]*?)<\/main>/.exec(html);
      assert.ok(main?.[1]?.includes('id="map"'), `${where}: the map container inside <main>`);
    }
  });
});
