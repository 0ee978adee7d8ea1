// The ID buffer read back from the GPU, as the renderer returns it and the tests read it.
export interface IdBuffer {
  width: number;
  height: number;
  /** Per pixel, rows from the top: upper face (0: none), lower face, classes (upper | lower << 16), surface z. */
  upper: Uint32Array;
  lower: Uint32Array;
  classes: Uint32Array;
  z: Float32Array;
  /** z of the slicing surface per pixel. */
  slice: Float32Array;
}
