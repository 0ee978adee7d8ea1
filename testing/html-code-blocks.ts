// The HTML code blocks of a Markdown text (```html fences), and the whole pages among them in
// docs/*.md with the demo page: the templates embedders copy, for the tests of the docs' pages.
import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { repoRoot } from './paths.js';

/** The contents of every ```html fenced block, in order. */
export function htmlCodeBlocks(markdown: string): string[] {
  return [...markdown.matchAll(/^```html[^\n]*\n([\s\S]*?)^```/gm)].map((m) => m[1] ?? '');
}

/** Every whole page (a block with <html>) in docs/*.md, as [where, html]. */
export function docsPageTemplates(): [string, string][] {
  const docs = path.join(repoRoot, 'docs');
  const pages: [string, string][] = [];
  for (const name of readdirSync(docs).filter((n) => n.endsWith('.md')).sort()) {
    htmlCodeBlocks(readFileSync(path.join(docs, name), 'utf8')).forEach((block, i) => {
      if (/<html\b/i.test(block)) pages.push([`docs/${name}, HTML block ${i + 1}`, block]);
    });
  }
  return pages;
}
