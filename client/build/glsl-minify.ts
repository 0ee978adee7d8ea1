// The shaders as the built map carries them: without their comments and indentation. Their
// comments say why the code is as it is, at length: the library's ES build went from 77.9 to
// 71.9 kB gzip without them (the UMD build from 146.5 to 141.1), some 30 ms of a first map at
// Slow 4G's 1.6 Mbit/s (worked out, not measured). Tokenized with glsl-tokenizer, so that
// nothing but a comment or whitespace is touched; every # line stays a line of its own. A first
// line comment that starts with a title and a colon keeps its title ("// ID pass"):
// bench:passes tells the programs apart by it, and so does a person reading a shader in the
// browser's tools. Used by the Vite builds (glslMinifyPlugin), not by the map itself.
// glsl-tokenizer's types: glsl-tokenizer.d.ts.
import { readFile } from 'node:fs/promises';
import tokenize from 'glsl-tokenizer/string';
import type { Plugin } from 'vite';

/**
 * `source` without comments (but the first line comment's title, if it has one), blank lines
 * and indentation; a run of whitespace becomes a newline if it held one, else a space.
 */
export function minifyGlsl(source: string): string {
  let out = '';
  let titled = false;
  for (const t of tokenize(source, { version: '300 es' })) {
    if (t.type === 'line-comment' && !titled) {
      titled = true;
      const title = /^\/\/ [\w ]{1,40}(?=:)/.exec(t.data);
      if (title) out += `${title[0]}\n`;
      continue;
    }
    if (t.type === 'line-comment' || t.type === 'eof') continue;
    // A block comment parts the tokens either side of it as a space does.
    if (t.type === 'block-comment' || t.type === 'whitespace') out += t.data.includes('\n') ? '\n' : ' ';
    else out += t.data;
  }
  return `${out.replace(/ *\n[\n ]*/g, '\n').replace(/ {2,}/g, ' ').trim()}\n`;
}

/** A shader file imported with `?raw` (client/shaders/) is given to the bundle minified. */
export function glslMinifyPlugin(): Plugin {
  return {
    name: 'minify-glsl',
    // The dev server serves the files as they are: a shader error's line is the file's.
    apply: 'build',
    enforce: 'pre',
    async load(id) {
      const m = /^(.*[\\/]client[\\/]shaders[\\/][^\\/?]+\.(?:vert|frag|glsl))\?raw$/.exec(id);
      if (!m) return null;
      this.addWatchFile(m[1]!);
      return `export default ${JSON.stringify(minifyGlsl(await readFile(m[1]!, 'utf8')))};`;
    },
  };
}
