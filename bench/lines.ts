// npm run bench:lines [-- <dataset filter>]: the collapse of linear faces to lines (issue 12,
// item 1) on the two Otterlo cuts. Per linear class: faces that end in a split, line objects
// and their length, and the connected pieces the lines form when each is taken at its start
// (the face's geometry at its split), beside the pieces the class's areas form at the base
// scale (faces sharing an edge). Faces of a linear class with one neighbour are merged whole,
// not split, and leave no line: counted beside. Then pruning over scale (item 2): the lines
// left at the base scale, 1:5k, 1:10k and 1:25k (as ssc build makes them: the lines the style
// draws, weighed by their rules and strokes) with their vertices in full and simplified
// (bench/line-scales.ts), and whether each class's main network stays one piece at every
// state it is shown.
import { EventKind, resolveFace, type Tgap } from '../format/tgap-model.js';
import { collapseLines } from '../preprocess/lines/collapse-lines.js';
import { lineComponents } from '../preprocess/lines/line-components.js';
import { generalizeFile } from '../preprocess/pipeline.js';
import { generalizedLines } from '../preprocess/ssc/cube-lines.js';
import { loadStyle } from '../preprocess/style.js';
import { datasets } from './datasets.js';
import { LINE_SCALE_HEADER, lineScaleRows, mainNetworkSplits } from './line-scales.js';
import { printTable } from './table.js';

/** Pieces the faces of class c form at state 0, faces joined across their shared edges. */
function areaComponents(tgap: Tgap, c: number): number {
  const parent = new Map<number, number>();
  const find = (f: number): number => {
    let r = f;
    while (parent.get(r) !== r) r = parent.get(r)!;
    parent.set(f, r);
    return r;
  };
  tgap.faces.forEach((f, i) => {
    if (i > 0 && f.stepLow === 0 && f.classIndex === c) parent.set(i, i);
  });
  for (const e of tgap.edges) {
    if (e.stepLow > 0) continue;
    const l = resolveFace(tgap.faces, e.left, 0), r = resolveFace(tgap.faces, e.right, 0);
    if (parent.has(l) && parent.has(r)) parent.set(find(l), find(r));
  }
  let n = 0;
  for (const f of parent.keys()) if (find(f) === f) n++;
  return n;
}

const rows: string[][] = [['dataset', 'class', 'linear splits', 'merged whole', 'lines', 'length km', 'line pieces', 'area pieces at base']];
const notes: string[] = [];
const scaleRows: string[][] = [LINE_SCALE_HEADER];
const pruneNotes: string[] = [];
for (const d of datasets(process.argv[2], ['bgt_otterlo_400m', 'bgt_otterlo_1800m'])) {
  process.stderr.write(`${d.name}... `);
  const { tgap } = await generalizeFile(d.file, { style: d.style });
  const style = await loadStyle(d.style);
  const t0 = performance.now();
  const { lines, stats } = collapseLines(tgap, style);
  const ms = performance.now() - t0;
  style.classes.forEach((c, ci) => {
    if (!c.linear) return;
    const mine = lines.filter((l) => l.classIndex === ci);
    const ended = (kind: EventKind): number => tgap.events.filter((e) => e.kind === kind && tgap.faces[e.loser]!.classIndex === ci).length;
    const splits = ended(EventKind.Split);
    const km = mine.reduce((s, l) => s + l.length, 0) / 1000;
    rows.push([d.name, c.key, String(splits), String(ended(EventKind.Merge)), String(mine.length), km.toFixed(2), String(lineComponents(mine.flatMap((l) => l.paths))), String(areaComponents(tgap, ci))]);
  });
  rows.push([d.name, 'all', String(stats.linearSplits), `${stats.linearMerges} into others`, String(stats.lines), (stats.length / 1000).toFixed(2), String(lineComponents(lines.flatMap((l) => l.paths))), '']);
  // As ssc build makes them: the lines the style draws, by their rules' weights and strokes.
  const t1 = performance.now();
  const { pruned, simplified } = generalizedLines(tgap, style);
  const pruneMs = performance.now() - t1;
  scaleRows.push(...lineScaleRows(d.name, tgap, style, simplified.lines, [5000, 10000, 25000]));
  const st = pruned.stats, ss = simplified.stats;
  pruneNotes.push(`${d.name}: collapse again, prune and simplify ${(pruneMs / 1000).toFixed(2)} s; density held ${pruned.density.toFixed(4)} mm/mm²; pruned ${st.pruned} (at birth ${st.prunedAtBirth}), to the top ${st.toTop}, states over budget ${st.statesOverBudget}; simplify: vertices removed ${ss.removed}, put off by a vertex in the triangle ${ss.blocked}, of those kept for good ${ss.given}`);
  for (const m of mainNetworkSplits(tgap, style, pruned.lines)) pruneNotes.push(`  ${m.cls}: main network shown at ${m.shownStates} states; checked where a line of it goes: ${m.checked}, in pieces (with areas) at ${m.split}`);
  notes.push(`${d.name}: collapse ${(ms / 1000).toFixed(2)} s; ports ${stats.ports}, taken up by later lines ${stats.anchorsReached} (by a bridge ${stats.anchorsBridged}), outside their face by then ${stats.anchorsOutside}, never taken up ${stats.anchorsLeft}; empty centrelines ${stats.empty}`);
  process.stderr.write('done\n');
}
console.log(`bench:lines, collapseLines on the tGAP of ssc generalize, node ${process.version}`);
console.log('line pieces: connected pieces of the class\'s lines, each at its start, joined where they share a point exactly');
printTable(rows);
console.log(notes.join('\n'));
console.log('\npruneLines: lines shown at state floor(z) of each scale; pieces joined where lines share a point; "with areas": lines not yet born stand in for their areas');
printTable(scaleRows);
console.log(pruneNotes.join('\n'));
