// A real dataset generalized by the CLI from source into a folder of the caller's, and its tGAP
// read back: for tests of what the build makes of real data.
import path from 'node:path';
import { readTgap } from '../format/tgap.js';
import type { Tgap } from '../format/tgap-model.js';
import { dataset, styleFile } from './paths.js';
import { runSsc } from './run-ssc.js';

export async function generalizedDataset(dir: string, file: string, style: string): Promise<{ tgapFile: string; tgap: Tgap }> {
  const tgapFile = path.join(dir, `${path.basename(file).replace(/\..*$/, '')}.tgap`);
  const g = runSsc(['generalize', dataset(file), '--style', styleFile(style), '--out', tgapFile, '--quiet']);
  if (g.code !== 0) throw new Error(`ssc generalize ${file} failed (exit ${g.code}): ${g.stderr}`);
  return { tgapFile, tgap: await readTgap(tgapFile) };
}
