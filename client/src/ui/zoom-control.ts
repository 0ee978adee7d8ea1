// Zoom in and out buttons: one zoom step about the centre, as the + and - keys.
import type { Control, VarioMap } from '../vario-map.js';
import { controlButton, controlGroup } from './control-dom.js';

export class ZoomControl implements Control {
  onAdd(map: VarioMap): HTMLElement {
    const group = controlGroup('vario-map-zoom');
    group.append(
      controlButton('vario-map-zoom-in', 'Zoom in', '+', () => void map.zoomIn()),
      controlButton('vario-map-zoom-out', 'Zoom out', '\u2212', () => void map.zoomOut()),
    );
    return group;
  }

  onRemove(): void {
    // Its buttons go with its element.
  }
}
