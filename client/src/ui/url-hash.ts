// The view in the URL's hash as MapLibre GL JS's `hash` option writes it, #zoom/lat/lng: a link
// shows the same place and scale here and in MapLibre, and back/forward or an edited hash move
// the map there.
import { formatHash, parseHash } from './hash-text.js';
import type { VarioMap } from '../vario-map.js';

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
    const hash = formatHash(this.map.getZoom(), this.map.getCenter().toArray());
    if (hash !== location.hash) history.replaceState(history.state, '', hash);
  };

  private readonly onHashChange = (): void => {
    const v = parseHash(location.hash);
    // The map's own hash (written on moveend) is where it already is.
    if (!v || formatHash(v.zoom, v.center) === formatHash(this.map.getZoom(), this.map.getCenter().toArray())) return;
    this.map.jumpTo(v);
  };
}
