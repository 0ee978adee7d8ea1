// The offscreen targets of a frame, sized to the canvas in device pixels:
// - ids: RG32UI upper/lower face + RG32UI classes/surface z, with a float depth buffer (MRT);
// - surface: R32F slicing surface z;
// - colour: the accumulated (supersampled) colour (a frame of weight 1 goes to the canvas only, renderer.ts);
// - lines().cover: RGBA8, the cube's lines' coverage (line-pass.ts), kept until the next frame
//   (the pass putting the map on the canvas paints them, and so does Renderer.present);
// - overlays().coverage: scratch RGBA8, each overlay layer's coverage (overlay-pass.ts);
// - overlays().overlays: every overlay layer painted (premultiplied), in the colour target's format.
// The line target is made when lines are first drawn, the overlay targets when an overlay is:
// a map without them (a cube without lines, a page that adds no layer) spends 32 bytes a pixel,
// not 48 (28, not 40, without float targets; on a phone's 1170x2532 device pixels, 47 MB less).
// Integer and float textures are sampled with texelFetch and NEAREST filtering (integer
// textures read as zero with any other filter).

export function texture2d(gl: WebGL2RenderingContext, internal: number, w: number, h: number): WebGLTexture {
  const t = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, t);
  gl.texStorage2D(gl.TEXTURE_2D, 1, internal, w, h);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
  gl.bindTexture(gl.TEXTURE_2D, null);
  return t;
}

function framebuffer(gl: WebGL2RenderingContext, colours: WebGLTexture[], depth: WebGLRenderbuffer | null, name: string): WebGLFramebuffer {
  const fb = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
  colours.forEach((t, i) => gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + i, gl.TEXTURE_2D, t, 0));
  if (depth) gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
  gl.drawBuffers(colours.map((_, i) => gl.COLOR_ATTACHMENT0 + i));
  const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  if (status !== gl.FRAMEBUFFER_COMPLETE && !gl.isContextLost()) throw new Error(`${name} framebuffer incomplete (0x${status.toString(16)})`);
  return fb;
}

export interface Caps {
  /** R32F and RGBA16F/32F can be rendered to. */
  floatTargets: boolean;
}

export class Targets {
  width = 0;
  height = 0;
  ids!: WebGLTexture;
  aux!: WebGLTexture;
  depth!: WebGLRenderbuffer;
  idFb!: WebGLFramebuffer;
  surface!: WebGLTexture;
  surfaceFb: WebGLFramebuffer | null = null;
  colour!: WebGLTexture;
  colourFb!: WebGLFramebuffer;
  /** The colour target's format (to read it back). */
  colourFloat = false;
  private lineTargets: LineTargets | null = null;
  private overlayTargets: OverlayTargets | null = null;
  private live = false;

  constructor(
    private readonly gl: WebGL2RenderingContext,
    private readonly caps: Caps,
  ) {}

  resize(width: number, height: number): void {
    if (this.live && width === this.width && height === this.height) return;
    this.delete();
    const gl = this.gl;
    this.width = width;
    this.height = height;
    this.ids = texture2d(gl, gl.RG32UI, width, height);
    this.aux = texture2d(gl, gl.RG32UI, width, height);
    this.depth = gl.createRenderbuffer();
    gl.bindRenderbuffer(gl.RENDERBUFFER, this.depth);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT32F, width, height);
    gl.bindRenderbuffer(gl.RENDERBUFFER, null);
    this.idFb = framebuffer(gl, [this.ids, this.aux], this.depth, 'id');
    this.surface = texture2d(gl, gl.R32F, width, height);
    // Without renderable float targets the surface is computed on the CPU and uploaded.
    this.surfaceFb = this.caps.floatTargets ? framebuffer(gl, [this.surface], null, 'surface') : null;
    this.colourFloat = this.caps.floatTargets;
    this.colour = texture2d(gl, this.colourFloat ? gl.RGBA16F : gl.RGBA8, width, height);
    this.colourFb = framebuffer(gl, [this.colour], null, 'colour');
    this.live = true;
  }

  /** The lines' coverage as the last line pass left it; null when none has drawn at this size. */
  get lineCover(): WebGLTexture | null {
    return this.lineTargets?.cover ?? null;
  }

  /** The cube's lines' coverage target, made the first time it is asked for at this size. */
  lines(): LineTargets {
    if (!this.lineTargets) {
      const cover = texture2d(this.gl, this.gl.RGBA8, this.width, this.height);
      this.lineTargets = { cover, fb: framebuffer(this.gl, [cover], null, 'line coverage') };
    }
    return this.lineTargets;
  }

  /** The overlays' targets, made the first time they are asked for at this size. */
  overlays(): OverlayTargets {
    if (!this.overlayTargets) {
      const gl = this.gl;
      const coverage = texture2d(gl, gl.RGBA8, this.width, this.height);
      const overlays = texture2d(gl, this.colourFloat ? gl.RGBA16F : gl.RGBA8, this.width, this.height);
      this.overlayTargets = { coverage, coverageFb: framebuffer(gl, [coverage], null, 'overlay coverage'), overlays, overlaysFb: framebuffer(gl, [overlays], null, 'overlays') };
    }
    return this.overlayTargets;
  }

  /** GPU memory the targets take, bytes. */
  get bytes(): number {
    if (!this.live) return 0;
    const colour = this.colourFloat ? 8 : 4;
    // ids and aux 8 each, depth 4, surface 4, colour; lines 4; coverage 4 and overlays as colour.
    const perPixel = 8 + 8 + 4 + 4 + colour + (this.lineTargets ? 4 : 0) + (this.overlayTargets ? 4 + colour : 0);
    return perPixel * this.width * this.height;
  }

  delete(): void {
    if (!this.live) return;
    const gl = this.gl;
    for (const t of [this.ids, this.aux, this.surface, this.colour, this.lineTargets?.cover, this.overlayTargets?.coverage, this.overlayTargets?.overlays]) if (t) gl.deleteTexture(t);
    gl.deleteRenderbuffer(this.depth);
    for (const f of [this.idFb, this.surfaceFb, this.colourFb, this.lineTargets?.fb, this.overlayTargets?.coverageFb, this.overlayTargets?.overlaysFb]) if (f) gl.deleteFramebuffer(f);
    this.lineTargets = null;
    this.overlayTargets = null;
    this.live = false;
  }
}

export interface LineTargets {
  cover: WebGLTexture;
  fb: WebGLFramebuffer;
}

export interface OverlayTargets {
  coverage: WebGLTexture;
  coverageFb: WebGLFramebuffer;
  overlays: WebGLTexture;
  overlaysFb: WebGLFramebuffer;
}
