// What the container shows where the browser has no WebGL2.
import { showMessageBox } from './message-box.js';

export function showWebGl2Missing(container: HTMLElement): HTMLElement {
  return showMessageBox(container, 'ssc-no-webgl2', [
    'This map needs WebGL2, which this browser does not offer (or has turned off). Try a current version of Firefox, Chrome, Edge or Safari, or turn hardware acceleration on.',
  ]);
}
