// The embeddable library (Vite library mode) into dist/lib: `--mode es` builds the ES module
// (vario-map.js, its worker a file beside it) and the stylesheet; `--mode umd` the script-tag
// build (vario-map.umd.js, global `vario`) with the worker inlined, by swapping
// create-worker.ts for create-worker-inline.ts. The type declarations come from
// tsconfig.lib.json.
import { rmSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

const outDir = fileURLToPath(new URL('../dist/lib', import.meta.url));
const entry = fileURLToPath(new URL('./src/lib/bundle.ts', import.meta.url));
const inlineWorker = fileURLToPath(new URL('./src/source/create-worker-inline.ts', import.meta.url));

export default defineConfig(({ mode }) => {
  const umd = mode === 'umd';
  return {
    root: fileURLToPath(new URL('.', import.meta.url)),
    base: './',
    publicDir: false,
    resolve: umd ? { alias: [{ find: /^\.\/create-worker\.js$/, replacement: inlineWorker }] } : {},
    build: {
      outDir,
      emptyOutDir: false,
      target: 'es2022',
      sourcemap: true,
      copyPublicDir: false,
      lib: {
        entry,
        name: 'vario',
        formats: [umd ? 'umd' : 'es'],
        fileName: () => (umd ? 'vario-map.umd.js' : 'vario-map.js'),
        cssFileName: 'vario-map',
      },
    },
    worker: { format: umd ? 'iife' : 'es' },
    plugins: [
      {
        name: 'clear-lib',
        apply: 'build',
        buildStart() {
          // The ES build runs first and starts from an empty folder (the types are written after).
          if (!umd) rmSync(outDir, { recursive: true, force: true });
        },
      },
    ],
  };
});
