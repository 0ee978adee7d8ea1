// The page templates embedders copy (the HTML pages in docs/*.md and the demo page) are fit for
// phones and screen readers: a viewport meta tag (else a phone lays out 980 px and the map's
// canvas is several times the screen) and the map inside a <main> landmark.
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, test } from 'node:test';
import { htmlCodeBlocks } from './html-code-blocks.js';
import { repoRoot } from './paths.js';

const VIEWPORT = '<meta name="viewport" content="width=device-width, initial-scale=1">';

/** Every whole page (a block with <html>) in docs/*.md and the demo page, by where it is. */
function templates(): [string, string][] {
  const docs = path.join(repoRoot, 'docs');
  const pages: [string, string][] = [];
  for (const name of readdirSync(docs).filter((n) => n.endsWith('.md')).sort()) {
    htmlCodeBlocks(readFileSync(path.join(docs, name), 'utf8')).forEach((block, i) => {
      if (/<html\b/i.test(block)) pages.push([`docs/${name}, HTML block ${i + 1}`, block]);
    });
  }
  pages.push(['client/demo.html', readFileSync(path.join(repoRoot, 'client/demo.html'), 'utf8')]);
  return pages;
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
