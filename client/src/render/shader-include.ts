// Shader sources that share a piece of GLSL: the line `#include "name"` replaced by it (GLSL ES
// has no include of its own).

/** `source` with each `#include "name"` line replaced by `chunks[name]`; an include not given is an error. */
export function withIncludes(source: string, chunks: Readonly<Record<string, string>>): string {
  return source.replace(/^#include "([^"]+)"[^\n]*$/gm, (_, name: string) => {
    const chunk = chunks[name];
    if (chunk === undefined) throw new Error(`shader includes "${name}", which is not given (given: ${Object.keys(chunks).join(', ') || 'none'})`);
    return chunk.trimEnd();
  });
}
