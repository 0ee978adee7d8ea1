// What a GeoJSON layer makes of its projected data: the mesh the GPU draws and the index its
// pointer events search. Loaded with the first layer that needs it (geojson-layer.ts), so that a
// map without GeoJSON layers does not carry earcut, Flatbush and this code (8 kB gzip).
import type { Parts } from './geojson-read.js';
import { HitIndex } from './overlay-hit.js';
import { buildMesh } from './overlay-mesh.js';
import type { OverlayMesh } from './overlay-quads.js';

export interface LayerGeometry {
  mesh: OverlayMesh;
  hits: HitIndex;
}

export function layerGeometry(parts: readonly Parts[]): LayerGeometry {
  return { mesh: buildMesh(parts), hits: new HitIndex(parts) };
}
