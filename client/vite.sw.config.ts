// Builds the service worker (src/offline/service-worker.ts, with workbox bundled in) as one
// classic script, dist/client/sw.src.js; scripts/precache-manifest.js then injects the app
// shell's file list into it and writes dist/client/sw.js.
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

export default defineConfig({
  root: fileURLToPath(new URL('.', import.meta.url)),
  publicDir: false,
  // workbox logs in development builds only; this is the switch it reads.
  define: { 'process.env.NODE_ENV': JSON.stringify('production') },
  build: {
    outDir: fileURLToPath(new URL('../dist/client', import.meta.url)),
    emptyOutDir: false,
    target: 'es2022',
    copyPublicDir: false,
    lib: {
      entry: fileURLToPath(new URL('./src/offline/service-worker.ts', import.meta.url)),
      name: 'varioServiceWorker',
      formats: ['iife'],
      fileName: () => 'sw.src.js',
    },
  },
});
