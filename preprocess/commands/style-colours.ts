// Class colours, by class index, from the style JSON stored in a tGAP or cube.
export function classColours(style: Record<string, unknown>): string[] {
  const classes = style.classes;
  if (!Array.isArray(classes)) return [];
  return classes.map((c) => (typeof c === 'object' && c !== null && typeof (c as { color?: unknown }).color === 'string' ? (c as { color: string }).color : '#ff00ff'));
}
