// Shader variants: one source compiled with some of its #ifdef features turned on.

/** `source` with `#define NAME` for each name, after its `#version` line. */
export function withDefines(source: string, names: readonly string[]): string {
  if (names.length === 0) return source;
  const eol = source.indexOf('\n');
  return `${source.slice(0, eol + 1)}${names.map((n) => `#define ${n}\n`).join('')}${source.slice(eol + 1)}`;
}
