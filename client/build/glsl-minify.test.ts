// The minified shaders against the files: every token but comments and whitespace the same and
// in order (tokenized again), no comment left but the title (the first line comment, up to its
// colon: bench:passes names the programs by it), each # line a line of its own, #version still
// first; and a hand-made source, byte for byte.
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import tokenize from 'glsl-tokenizer/string';
import { minifyGlsl } from './glsl-minify.js';

const dir = path.join(path.dirname(fileURLToPath(import.meta.url)), '../shaders');
const code = (src: string): string[] => tokenize(src, { version: '300 es' }).filter((t) => !['whitespace', 'block-comment', 'line-comment', 'eof'].includes(t.type)).map((t) => t.data);

test("every shader keeps its code's tokens, in order, without its comments", () => {
  const files = readdirSync(dir).filter((f) => /\.(vert|frag|glsl)$/.test(f));
  assert.ok(files.length >= 10, `${files.length} shader files`);
  let before = 0, after = 0;
  for (const f of files) {
    const src = readFileSync(path.join(dir, f), 'utf8');
    const min = minifyGlsl(src);
    assert.deepEqual(code(min), code(src), f);
    const comments = tokenize(min, { version: '300 es' }).filter((t) => t.type.endsWith('comment')).map((t) => t.data);
    // A pass's shaders are titled "// <name> pass: ..."; the includes' first lines have no such title.
    const first = src.split('\n').find((l) => l.startsWith('//'))!;
    const title = /^\/\/ \w+ pass(?=:)/.exec(first)?.[0];
    assert.deepEqual(comments, title ? [title] : [], `${f}: its title alone is left`);
    if (/\.frag$/.test(f)) assert.ok(title, `${f}: a fragment shader names its pass`);
    for (const line of min.split('\n')) if (line.includes('#')) assert.match(line, /^#/, `${f}: a # line shares a line: ${line}`);
    if (src.startsWith('#version')) assert.match(min, /^#version 300 es\n/, f);
    before += src.length;
    after += min.length;
  }
  assert.ok(after < before / 2, `${after} of ${before} characters left`);
});

test('a hand-made shader comes out as expected', () => {
  const src = [
    '#version 300 es',
    '// Test pass: a comment line.',
    '// Another.',
    'precision highp float; /* a block',
    '   comment */',
    '#ifdef FLAT',
    '  float a = 1.0;   // trailing',
    '#endif',
    '',
    '',
    'void main() {',
    '    gl_FragColor = vec4(a,  a, a, 1.0);',
    '    uint u = 1u/**/<</**/2u;',
    '}',
  ].join('\n');
  assert.equal(minifyGlsl(src), '#version 300 es\n// Test pass\nprecision highp float;\n#ifdef FLAT\nfloat a = 1.0;\n#endif\nvoid main() {\ngl_FragColor = vec4(a, a, a, 1.0);\nuint u = 1u << 2u;\n}\n');
});
