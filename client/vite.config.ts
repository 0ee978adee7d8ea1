// Builds the browser client into dist/client: index.html (the engine's test page), demo.html
// (the full-page demo on the public API), their module worker and shaders.
// dist/client/src holds the Node build of the pure modules and tests (tsc), so the output
// directory is not emptied: only Vite's own assets/ folder is cleared before each build.
import { rmSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';
import { glslMinifyPlugin } from './build/glsl-minify.js';

const outDir = fileURLToPath(new URL('../dist/client', import.meta.url));

export default defineConfig({
  root: fileURLToPath(new URL('.', import.meta.url)),
  base: './',
  build: {
    outDir,
    emptyOutDir: false,
    target: 'es2022',
    sourcemap: true,
    rollupOptions: {
      input: {
        index: fileURLToPath(new URL('./index.html', import.meta.url)),
        demo: fileURLToPath(new URL('./demo.html', import.meta.url)),
      },
      // Lowercase hex hashes in the names, which servers recognise as immutable (server/cache-control.ts).
      output: { hashCharacters: 'hex' },
    },
  },
  worker: { format: 'es', rollupOptions: { output: { hashCharacters: 'hex' } } },
  plugins: [
    glslMinifyPlugin(),
    {
      name: 'clear-assets',
      apply: 'build',
      buildStart() {
        rmSync(`${outDir}/assets`, { recursive: true, force: true });
      },
    },
  ],
});
