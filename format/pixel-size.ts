// The standard screen pixel (OGC WMS 1.3 / WMTS): a scale denominator and a ground size per
// pixel are the same thing through it. Written into index.json as meta.pixelSizeMm.
export const PIXEL_SIZE_MM = 0.28;

/** Ground width and height (metres) a `width` x `height` px view covers per unit of scale denominator. */
export const groundPerScale = (width: number, height: number, pixelSizeMm = PIXEL_SIZE_MM): [number, number] => [(width * pixelSizeMm) / 1000, (height * pixelSizeMm) / 1000];

/**
 * A phone held upright, in CSS px. The map opens showing the whole extent, which on a phone lies
 * at a coarser scale than on the 1280 x 720 px view of the chunking's model; the chunks keep the
 * triangles covered above either apart (planChunks). bgt_otterlo_1800m's phone view queried
 * 147 kB (gzip) of surface chunks with the one cut and 102 kB with both, nlcd_zion's 1,740 and
 * 1,073 kB (docs/FORMAT.md, "index.json"). bench:session opens a page this size.
 */
export const PHONE_VIEW_PX: readonly [number, number] = [390, 844];
