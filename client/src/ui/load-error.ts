// What the container shows when the cube's index cannot be loaded: the map has nothing to draw,
// so the reader (and the page's author) learns why instead of seeing a blank map.
import type { SourceErrorInfo } from '../source/worker-protocol.js';
import { loadErrorText } from './load-error-text.js';
import { showMessageBox } from './message-box.js';

export function showLoadError(container: HTMLElement, e: SourceErrorInfo): HTMLElement {
  return showMessageBox(container, 'ssc-load-error', ['The map could not be loaded.', loadErrorText(e)]);
}
