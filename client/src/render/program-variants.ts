// One pair of shader sources compiled with some of their #ifdef features turned on (a few per
// pass: FLAT, LINES, BLENDING...), each variant linked when a frame first asks for it. A
// software GPU takes a while to compile, and most variants of a pass are never drawn in a
// session (a lens, supersampling), so they cost nothing at start-up.
import { Program } from './program.js';
import { withDefines } from './shader-defines.js';
import { withIncludes } from './shader-include.js';

export class ProgramVariants {
  private readonly programs = new Map<string, Program>();

  /** `includes`: the GLSL the sources #include, by name (shader-include.ts). */
  constructor(
    private readonly gl: WebGL2RenderingContext,
    private readonly vertexSource: string,
    private readonly fragmentSource: string,
    private readonly name: string,
    private readonly includes: Readonly<Record<string, string>> = {},
  ) {}

  /** The program with `features` defined in both shaders, linked on first use. */
  get(features: readonly string[] = []): Program {
    const key = features.join(' ');
    let p = this.programs.get(key);
    if (!p) {
      const source = (s: string): string => withIncludes(withDefines(s, features), this.includes);
      p = new Program(this.gl, source(this.vertexSource), source(this.fragmentSource), `${this.name}${key ? ` (${key})` : ''}`);
      this.programs.set(key, p);
    }
    return p;
  }

  delete(): void {
    for (const p of this.programs.values()) p.delete();
    this.programs.clear();
  }
}
