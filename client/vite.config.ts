// Builds the browser client (client/index.html, its module worker and shaders) into dist/client.
// dist/client/src/shared holds the Node build of the shared modules (tsc), so the output
// directory is not emptied: only Vite's own assets/ folder is cleared before each build.
import { rmSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

const outDir = fileURLToPath(new URL('../dist/client', import.meta.url));

export default defineConfig({
  root: fileURLToPath(new URL('.', import.meta.url)),
  base: './',
  build: {
    outDir,
    emptyOutDir: false,
    target: 'es2022',
    sourcemap: true,
  },
  worker: { format: 'es' },
  plugins: [
    {
      name: 'clear-assets',
      apply: 'build',
      buildStart() {
        rmSync(`${outDir}/assets`, { recursive: true, force: true });
      },
    },
  ],
});
