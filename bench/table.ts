// Printing a benchmark's results: a table with a header row, right-aligned columns.

export function printTable(rows: string[][]): void {
  const widths = rows[0]!.map((_, c) => Math.max(...rows.map((r) => r[c]!.length)));
  for (const r of rows) process.stdout.write(`${r.map((v, c) => v.padStart(widths[c]!)).join('  ')}\n`);
}
