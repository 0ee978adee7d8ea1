// Per face, which of its feature states are drawn (a bit each, colour-options.ts DRAWN_STATES):
// one R8UI texel per face id (row-major, a fixed width), which the colour pass looks the
// pixel's face up in. A face's texel is rewritten alone
// when its state changes, so a hover costs one tiny upload whatever the cube's size.
import { texture2d } from './targets.js';

/** Texels per row, 2^11: 2048 is the least MAX_TEXTURE_SIZE WebGL2 allows (colour.frag shifts by it, not divides). */
export const FACE_STATE_SHIFT = 11;
export const FACE_STATE_WIDTH = 1 << FACE_STATE_SHIFT;

export class FaceStateTexture {
  readonly texture: WebGLTexture;
  private readonly height: number;

  constructor(
    private readonly gl: WebGL2RenderingContext,
    readonly faceCount: number,
    states: Iterable<[number, number]>,
  ) {
    this.height = Math.max(1, Math.ceil(faceCount / FACE_STATE_WIDTH));
    const max = gl.getParameter(gl.MAX_TEXTURE_SIZE) as number;
    if (this.height > max) throw new Error(`feature state: ${faceCount} faces need a texture ${this.height} rows high; this GPU allows ${max}`);
    // WebGL fills new storage with zeros: no state is drawn.
    this.texture = texture2d(gl, gl.R8UI, FACE_STATE_WIDTH, this.height);
    for (const [face, bits] of states) this.set(face, bits);
  }

  /** The face's drawn states, bit i for DRAWN_STATES[i]. */
  set(face: number, bits: number): void {
    if (face < 0 || face >= this.faceCount) return;
    const gl = this.gl;
    gl.bindTexture(gl.TEXTURE_2D, this.texture);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.texSubImage2D(gl.TEXTURE_2D, 0, face % FACE_STATE_WIDTH, Math.floor(face / FACE_STATE_WIDTH), 1, 1, gl.RED_INTEGER, gl.UNSIGNED_BYTE, new Uint8Array([bits]));
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 4);
    gl.bindTexture(gl.TEXTURE_2D, null);
  }

  delete(): void {
    this.gl.deleteTexture(this.texture);
  }
}
