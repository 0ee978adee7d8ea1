// An overlay layer's mesh on the GPU (uploaded once per setData): the polygon triangles and
// the three sets of quads (lines, polygon rings, points), each a vertex array with its own
// index buffer.
import { QUAD_FLOATS, QUAD_VERTICES, type OverlayMesh } from '../overlay/overlay-quads.js';

export interface DrawnPart {
  vao: WebGLVertexArrayObject;
  /** Indices to draw (gl.TRIANGLES, UNSIGNED_INT). */
  count: number;
}

export class GpuOverlayMesh {
  readonly fill: DrawnPart;
  readonly lines: DrawnPart;
  readonly rings: DrawnPart;
  readonly points: DrawnPart;
  private readonly buffers: WebGLBuffer[] = [];

  constructor(
    private readonly gl: WebGL2RenderingContext,
    mesh: OverlayMesh,
  ) {
    this.fill = this.part(mesh.fill.positions, mesh.fill.indices, (g) => {
      g.enableVertexAttribArray(0);
      g.vertexAttribPointer(0, 2, g.FLOAT, false, 8, 0);
    });
    this.lines = this.quads(mesh.lines);
    this.rings = this.quads(mesh.rings);
    this.points = this.quads(mesh.points);
  }

  delete(): void {
    for (const p of [this.fill, this.lines, this.rings, this.points]) this.gl.deleteVertexArray(p.vao);
    for (const b of this.buffers) this.gl.deleteBuffer(b);
  }

  /** Quads as overlay-quad.vert reads them: the segment (vec4) and the corner (vec3), two triangles each. */
  private quads(q: Float32Array): DrawnPart {
    const n = q.length / (QUAD_FLOATS * QUAD_VERTICES);
    const indices = new Uint32Array(6 * n);
    for (let i = 0; i < n; i++) indices.set([0, 1, 2, 2, 1, 3].map((k) => 4 * i + k), 6 * i);
    return this.part(q, indices, (g) => {
      g.enableVertexAttribArray(0);
      g.vertexAttribPointer(0, 4, g.FLOAT, false, 4 * QUAD_FLOATS, 0);
      g.enableVertexAttribArray(1);
      g.vertexAttribPointer(1, 3, g.FLOAT, false, 4 * QUAD_FLOATS, 16);
    });
  }

  private part(vertices: Float32Array, indices: Uint32Array, attributes: (gl: WebGL2RenderingContext) => void): DrawnPart {
    const gl = this.gl;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const vbo = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
    gl.bufferData(gl.ARRAY_BUFFER, vertices, gl.STATIC_DRAW);
    attributes(gl);
    const ibo = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ibo);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, indices, gl.STATIC_DRAW);
    gl.bindVertexArray(null);
    gl.bindBuffer(gl.ARRAY_BUFFER, null);
    this.buffers.push(vbo, ibo);
    return { vao, count: indices.length };
  }
}
