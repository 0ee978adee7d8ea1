// An independent rasterization of GeoJSON polygons for the tests: even-odd point-in-polygon at
// every pixel centre, straight from the input coordinates (no topology, no tGAP).

export interface RefView {
  width: number;
  height: number;
  bbox: [number, number, number, number];
}

/** Feature index + 1 per pixel (0 = none); rings as GeoJSON coordinate arrays. */
export function rasterizeFeatures(polygonsByFeature: number[][][][][], view: RefView): Uint32Array {
  const { width: W, height: H, bbox } = view;
  const [x0, , x1, y1] = bbox;
  const px = (x1 - x0) / W, py = (bbox[3] - bbox[1]) / H;
  const ids = new Uint32Array(W * H);
  polygonsByFeature.forEach((polys, fi) => {
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
    const rings: number[][][] = [];
    for (const p of polys) {
      for (const r of p) {
        rings.push(r);
        for (const [x, y] of r as unknown as [number, number][]) {
          minX = Math.min(minX, x); maxX = Math.max(maxX, x);
          minY = Math.min(minY, y); maxY = Math.max(maxY, y);
        }
      }
    }
    const i0 = Math.max(0, Math.floor((minX - x0) / px - 0.5)), i1 = Math.min(W - 1, Math.ceil((maxX - x0) / px));
    const j0 = Math.max(0, Math.floor((y1 - maxY) / py - 0.5)), j1 = Math.min(H - 1, Math.ceil((y1 - minY) / py));
    for (let j = j0; j <= j1; j++) {
      const y = y1 - (j + 0.5) * py;
      for (let i = i0; i <= i1; i++) {
        const x = x0 + (i + 0.5) * px;
        let inside = false;
        for (const r of rings) {
          for (let k = 0, m = r.length - 1; k < r.length; m = k++) {
            const a = r[k]!, b = r[m]!;
            if (a[1]! > y !== b[1]! > y && x < ((b[0]! - a[0]!) * (y - a[1]!)) / (b[1]! - a[1]!) + a[0]!) inside = !inside;
          }
        }
        if (inside) ids[j * W + i] = fi + 1;
      }
    }
  });
  return ids;
}

/** Pixels that differ, and of those the ones not next to a change of id in `ref` (not on a boundary). */
export function compareIds(got: Uint32Array, ref: Uint32Array, W: number, H: number): { equal: number; differ: number; offBoundary: number } {
  let equal = 0, differ = 0, offBoundary = 0;
  for (let j = 0; j < H; j++) {
    for (let i = 0; i < W; i++) {
      const p = j * W + i;
      if (got[p] === ref[p]) {
        equal++;
        continue;
      }
      differ++;
      let boundary = false;
      for (let dj = -1; dj <= 1 && !boundary; dj++) {
        for (let di = -1; di <= 1; di++) {
          const ii = i + di, jj = j + dj;
          if (ii < 0 || jj < 0 || ii >= W || jj >= H) continue;
          if (ref[jj * W + ii] !== ref[p]) {
            boundary = true;
            break;
          }
        }
      }
      if (!boundary) offBoundary++;
    }
  }
  return { equal, differ, offBoundary };
}
