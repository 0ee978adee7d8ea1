// The embeddable library (Vite library mode) into dist/lib: `--mode es` builds the ES module
// (vario-map.js; its worker, and proj4, which it imports after a cube's index has arrived, are
// files in assets/) and the stylesheet; `--mode umd` the script-tag build (vario-map.umd.js,
// global `vario`, proj4 inside) with the worker inlined, by swapping
// create-worker.ts for create-worker-inline.ts. The type declarations come from
// tsconfig.lib.json, and an empty one for the stylesheet (package.json's exports), so that
// `import 'vario-scale-map/vario-map.css'` type-checks without a bundler's client types.
import { rmSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';
import { glslMinifyPlugin } from './build/glsl-minify.js';

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
      // proj4, imported after a cube's index has arrived (geo/crs-transform.ts), is a file of its
      // own beside the worker, named for what it is.
      // Lowercase hex hashes in the names, as the app's, which servers recognise as immutable
      // (server/cache-control.ts): a page loaded again takes the worker and proj4 from its cache
      // without asking.
      rolldownOptions: {
        // The lazily loaded modules (proj4, a GeoJSON layer's geometry) share a few small ones
        // with the rest: those stay in vario-map.js, which then exports them to those files under
        // short internal names beside its public ones, instead of going into a file of their own
        // that vario-map.js would wait for.
        preserveEntrySignatures: 'allow-extension',
        output: {
          hashCharacters: 'hex',
          chunkFileNames: (c: { moduleIds: string[] }) => (c.moduleIds.some((id) => id.includes('/node_modules/proj4/')) ? 'assets/proj4-[hash].js' : 'assets/[name]-[hash].js'),
        },
      },
      lib: {
        entry,
        name: 'vario',
        formats: [umd ? 'umd' : 'es'],
        fileName: () => (umd ? 'vario-map.umd.js' : 'vario-map.js'),
        cssFileName: 'vario-map',
      },
    },
    // The worker is one file, any lazy import inlined: a page's bundler takes the prebuilt
    // worker over as a single asset and does not follow such an import, which would fail.
    worker: { format: umd ? 'iife' : 'es', rolldownOptions: { output: { codeSplitting: false, hashCharacters: 'hex' } } },
    plugins: [
      glslMinifyPlugin(),
      {
        name: 'clear-lib',
        apply: 'build',
        buildStart() {
          // The ES build runs first and starts from an empty folder (the types are written after).
          if (!umd) rmSync(outDir, { recursive: true, force: true });
        },
        generateBundle(_options, bundle) {
          if (!umd) this.emitFile({ type: 'asset', fileName: 'vario-map.css.d.ts', source: '// The stylesheet: imported for its effect only.\nexport {};\n' });
          // The inlined worker's source map has no file to belong to (and would be shipped).
          else for (const name of Object.keys(bundle)) if (/^assets\/chunk-worker-[\w-]+\.js\.map$/.test(name)) delete bundle[name];
        },
      },
    ],
  };
});
