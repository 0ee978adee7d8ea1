// The view in the URL's hash, #x/y/scale (ground coordinates to about a pixel, the scale
// denominator rounded): a link shows the same place, and back/forward or an edited hash move
// the map there.
import { formatHash, parseHash } from './hash-text.js';
import type { VarioMap } from '../vario-map.js';
import { PIXEL_SIZE_MM } from '../../../format/pixel-size.js';

export class UrlHash {
  constructor(private readonly map: VarioMap) {
    map.on('moveend', this.write);
    window.addEventListener('hashchange', this.onHashChange);
  }

  /** Moves the map to the hash's view, if the hash holds one; else writes the view there. */
  apply(): void {
    const v = parseHash(location.hash);
    if (v) this.map.jumpTo(v);
    else this.write();
  }

  remove(): void {
    this.map.off('moveend', this.write);
    window.removeEventListener('hashchange', this.onHashChange);
  }

  private readonly write = (): void => {
    const meta = this.map.getMetadata();
    const hash = formatHash(this.map.getCenter(), this.map.getScaleDenominator(), meta?.pixelSizeMm ?? PIXEL_SIZE_MM);
    if (hash !== location.hash) history.replaceState(history.state, '', hash);
  };

  private readonly onHashChange = (): void => {
    const v = parseHash(location.hash);
    if (!v) return;
    const c = this.map.getCenter();
    if (v.center[0] === c[0] && v.center[1] === c[1] && v.scaleDenominator === Math.round(this.map.getScaleDenominator())) return;
    this.map.jumpTo(v);
  };
}
