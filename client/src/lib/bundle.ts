// What the library builds bundle (client/vite.lib.config.ts): the public surface and its
// stylesheet, which Vite writes out as dist/lib/vario-map.css.
import '../ui/vario-map.css';

export * from './index.js';
