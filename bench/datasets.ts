// The four datasets of ../shared/data and their styles, for the benchmarks.
import { existsSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

export interface Dataset {
  name: string;
  file: string;
  style: string;
}

export function datasets(filter?: string): Dataset[] {
  const dir = path.resolve(root, '../shared/data');
  const all: Dataset[] = [
    { name: 'bgt_otterlo_400m', file: 'bgt_otterlo_400m.geojson', style: 'bgt.json' },
    { name: 'bgt_otterlo_1800m', file: 'bgt_otterlo_1800m.geojson', style: 'bgt.json' },
    { name: 'nlcd_zion', file: 'nlcd_zion.geojson.gz', style: 'nlcd.json' },
    { name: 'as18_17', file: 'as18_17.geojson.gz', style: 'as18.json' },
  ];
  return all
    .map((d) => ({ ...d, file: path.join(dir, d.file), style: path.join(root, 'styles', d.style) }))
    .filter((d) => existsSync(d.file) && (!filter || d.name.includes(filter)));
}

export function median(xs: number[]): number {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m]! : (s[m - 1]! + s[m]!) / 2;
}
