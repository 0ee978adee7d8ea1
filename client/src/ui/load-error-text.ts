// The words for a cube whose index could not be loaded: the URL and the cause a page's author
// can act on (a wrong path, a server without CORS, a file that is not a cube, a worker script
// that cannot be loaded).
import type { SourceErrorInfo } from '../source/worker-protocol.js';

export function loadErrorText(e: SourceErrorInfo): string {
  switch (e.kind) {
    case 'http':
      return e.status === 404 || e.status === 410 ? `${e.url} was not found (HTTP ${e.status}).` : `The server answered HTTP ${e.status ?? '?'} for ${e.url}.`;
    case 'network':
      // Browsers tell a refused cross-origin read and an unreachable server apart to no script.
      return `${e.url} could not be fetched: the server did not answer, or it does not allow this page's origin to read it (CORS: it must send Access-Control-Allow-Origin).`;
    case 'index':
    case 'corrupt':
      return `${e.url} is not a cube (the index.json that ssc build writes): ${e.message}`;
    case 'style':
      return e.message;
    case 'worker':
      return `The map's worker script could not be loaded, so ${e.url} cannot be shown: the script must be served beside vario-map.js, and a Content-Security-Policy must allow it (worker-src).`;
  }
}
