// The line of the report that lists the repairs made to the input (ssc generalize, ssc build).

/** `repairs: tJunctions 4, slivers 2` (the non-zero counts, in their order), or `repairs: none`. */
export function repairsLine(repairs: Record<string, number>): string {
  return `repairs: ${Object.entries(repairs).filter(([, n]) => n > 0).map(([k, n]) => `${k} ${n}`).join(', ') || 'none'}`;
}
