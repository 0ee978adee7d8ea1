// The HTML code blocks of a Markdown text (```html fences), for tests of the docs' pages.

/** The contents of every ```html fenced block, in order. */
export function htmlCodeBlocks(markdown: string): string[] {
  return [...markdown.matchAll(/^```html[^\n]*\n([\s\S]*?)^```/gm)].map((m) => m[1] ?? '');
}
