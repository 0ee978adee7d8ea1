// The tGAP file: magic, version, metadata JSON, then vertices, faces, edges and events as
// columns of little-endian numbers, then a SHA-256 of all of it (docs/FORMAT.md, "tGAP file").
// Node only (node:crypto, node:fs): the map never reads a tGAP.
import { promises as fs } from 'node:fs';
import { BinaryReader, BinaryWriter } from './binary-sections.js';
import { FormatError } from './format-error.js';
import type { EventKind, Tgap, TgapEdge, TgapEvent, TgapFace, TgapMeta } from './tgap-model.js';

export const TGAP_MAGIC = 0x50414754; // "TGAP" read as a little-endian u32
export const TGAP_VERSION = 1;

/** Offsets of variable-length lists: element i is items[off[i] .. off[i + 1]). */
function offsets<T>(items: T[], len: (t: T) => number): Uint32Array {
  const off = new Uint32Array(items.length + 1);
  for (let i = 0; i < items.length; i++) off[i + 1] = off[i]! + len(items[i]!);
  return off;
}

function concatI32<T>(items: T[], get: (t: T) => ArrayLike<number> | undefined, total: number): Int32Array {
  const out = new Int32Array(total);
  let o = 0;
  for (const it of items) {
    const a = get(it);
    if (!a) continue;
    out.set(a, o);
    o += a.length;
  }
  return out;
}

export function encodeTgap(t: Tgap): Uint8Array {
  const w = new BinaryWriter();
  w.u32(TGAP_MAGIC);
  w.u32(TGAP_VERSION);
  w.json(t.meta);
  const xy = new Float64Array(t.xs.length * 2);
  for (let i = 0; i < t.xs.length; i++) {
    xy[2 * i] = t.xs[i]!;
    xy[2 * i + 1] = t.ys[i]!;
  }
  w.array(xy);
  const F = t.faces;
  w.array(Uint16Array.from(F, (f) => f.classIndex));
  w.array(Int32Array.from(F, (f) => f.feature));
  w.array(Uint32Array.from(F, (f) => f.stepLow));
  w.array(Uint32Array.from(F, (f) => f.stepHigh));
  w.array(Int32Array.from(F, (f) => f.mergedInto));
  w.array(Uint8Array.from(F, (f) => f.endPhase));
  w.array(Float64Array.from(F, (f) => f.area2));
  const E = t.edges;
  w.array(Int32Array.from(E, (e) => e.start));
  w.array(Int32Array.from(E, (e) => e.end));
  w.array(Int32Array.from(E, (e) => e.left));
  w.array(Int32Array.from(E, (e) => e.right));
  w.array(Uint32Array.from(E, (e) => e.stepLow));
  w.array(Uint32Array.from(E, (e) => e.stepHigh));
  const vOff = offsets(E, (e) => e.verts.length);
  w.array(vOff);
  w.array(concatI32(E, (e) => e.verts, vOff[E.length]!));
  const pOff = offsets(E, (e) => e.parents.length);
  w.array(pOff);
  w.array(concatI32(E, (e) => e.parents, pOff[E.length]!));
  const rOff = offsets(E, (e) => e.removed.length);
  w.array(rOff);
  w.array(concatI32(E, (e) => e.removed, rOff[E.length]!));
  const phases = new Uint8Array(rOff[E.length]!);
  E.forEach((e, i) => phases.set(e.removedPhase, rOff[i]));
  w.array(phases);
  const V = t.events;
  w.array(Uint8Array.from(V, (e) => e.kind));
  w.array(Uint32Array.from(V, (e) => e.step));
  w.array(Int32Array.from(V, (e) => e.loser));
  w.array(Int32Array.from(V, (e) => e.into));
  const tOff = offsets(V, (e) => (e.triFaces ? e.triFaces.length : 0));
  w.array(tOff);
  w.array(concatI32(V, (e) => e.tris, tOff[V.length]! * 3));
  w.array(concatI32(V, (e) => e.triFaces, tOff[V.length]!));
  return w.finish();
}

export function decodeTgap(buf: Uint8Array, file: string): Tgap {
  const r = new BinaryReader(buf, file);
  if (r.u32() !== TGAP_MAGIC) throw new FormatError('is not a tGAP file (bad magic)', file);
  const version = r.u32();
  if (version !== TGAP_VERSION) throw new FormatError(`has tGAP version ${version}; this program reads version ${TGAP_VERSION}`, file);
  const meta = r.json<TgapMeta>();
  const xy = r.f64();
  const nv = xy.length / 2;
  const xs = new Float64Array(nv), ys = new Float64Array(nv);
  for (let i = 0; i < nv; i++) {
    xs[i] = xy[2 * i]!;
    ys[i] = xy[2 * i + 1]!;
  }
  const fClass = r.u16(), fFeature = r.i32(), fLow = r.u32a(), fHigh = r.u32a(), fInto = r.i32(), fPhase = r.u8(), fArea = r.f64();
  const faces: TgapFace[] = [];
  for (let i = 0; i < fClass.length; i++) {
    faces.push({ classIndex: fClass[i]!, feature: fFeature[i]!, stepLow: fLow[i]!, stepHigh: fHigh[i]!, mergedInto: fInto[i]!, endPhase: fPhase[i]!, area2: fArea[i]! });
  }
  const eStart = r.i32(), eEnd = r.i32(), eLeft = r.i32(), eRight = r.i32(), eLow = r.u32a(), eHigh = r.u32a();
  const vOff = r.u32a(), verts = r.i32();
  const pOff = r.u32a(), parents = r.i32();
  const rOff = r.u32a(), removed = r.i32(), phases = r.u8();
  const ne = eStart.length;
  const check = (ok: boolean, what: string): void => {
    if (!ok) throw new FormatError(`is inconsistent: ${what}`, file);
  };
  check(vOff.length === ne + 1 && pOff.length === ne + 1 && rOff.length === ne + 1, 'edge offset tables');
  check(vOff[ne] === verts.length && pOff[ne] === parents.length && rOff[ne] === removed.length && phases.length === removed.length, 'edge lists');
  const edges: TgapEdge[] = [];
  for (let i = 0; i < ne; i++) {
    edges.push({
      start: eStart[i]!, end: eEnd[i]!, left: eLeft[i]!, right: eRight[i]!, stepLow: eLow[i]!, stepHigh: eHigh[i]!,
      verts: verts.subarray(vOff[i], vOff[i + 1]),
      parents: parents.subarray(pOff[i], pOff[i + 1]),
      removed: removed.subarray(rOff[i], rOff[i + 1]),
      removedPhase: phases.subarray(rOff[i], rOff[i + 1]),
    });
  }
  const vKind = r.u8(), vStep = r.u32a(), vLoser = r.i32(), vInto = r.i32();
  const tOff = r.u32a(), tris = r.i32(), triFaces = r.i32();
  r.done();
  const nev = vKind.length;
  check(tOff.length === nev + 1 && tOff[nev] === triFaces.length && tris.length === triFaces.length * 3, 'event triangles');
  const events: TgapEvent[] = [];
  for (let i = 0; i < nev; i++) {
    const ev: TgapEvent = { kind: vKind[i] as EventKind, step: vStep[i]!, loser: vLoser[i]!, into: vInto[i]! };
    if (tOff[i + 1]! > tOff[i]!) {
      ev.tris = tris.subarray(tOff[i]! * 3, tOff[i + 1]! * 3);
      ev.triFaces = triFaces.subarray(tOff[i], tOff[i + 1]);
    }
    events.push(ev);
  }
  // Every reference must point inside its table: a bad file fails here, not halfway through a map.
  const nf = faces.length;
  for (const e of edges) {
    check(e.left >= 0 && e.left < nf && e.right >= 0 && e.right < nf, 'an edge names a face that does not exist');
    check(e.start >= 0 && e.start < nv && e.end >= 0 && e.end < nv, 'an edge names a vertex that does not exist');
  }
  for (let i = 0; i < verts.length; i++) check(verts[i]! >= 0 && verts[i]! < nv, 'an edge names a vertex that does not exist');
  for (const f of faces) check(f.mergedInto < nf && f.classIndex < Math.max(1, (meta.style as { classes?: object }).classes ? Object.keys((meta.style as { classes: object }).classes).length : 65536), 'a face names a face or class that does not exist');
  return { meta, xs, ys, faces, edges, events };
}

export async function readTgap(file: string): Promise<Tgap> {
  let buf: Buffer;
  try {
    buf = await fs.readFile(file);
  } catch (err) {
    throw new FormatError(`cannot read tGAP: ${(err as Error).message}`, file);
  }
  return decodeTgap(buf, file);
}
