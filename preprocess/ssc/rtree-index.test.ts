// The chunk index's R-tree on hand-made leaves: leaf i is the unit box at (i, 2i), z from i to
// i + 1, so every node's box can be worked out from the leaves it holds.
import test from 'node:test';
import assert from 'node:assert/strict';
import { isExternal, isLeaf, parseSubIndex, type ChunkLeaf, type IndexNode, type InnerNode } from '../../format/cube-index.js';
import { FANOUT, packTree, rootOutOfLine, splitTree } from './rtree-index.js';

function leaves(n: number): ChunkLeaf[] {
  return Array.from({ length: n }, (_, i) => ({
    bbox: [i, 2 * i, i, i + 1, 2 * i + 1, i + 1],
    file: `c-${String(i).padStart(3, '0')}.bin`,
    bytes: 100,
    triangles: 10,
    sha256: '0'.repeat(64),
  }));
}

/** The leaves under a node, in order, following sub-index files through `files`. */
function leavesUnder(n: IndexNode, files: Map<string, InnerNode> = new Map()): ChunkLeaf[] {
  if (isLeaf(n)) return [n];
  if (isExternal(n)) {
    const sub = files.get(n.ref);
    assert.ok(sub, `sub-index ${n.ref} was written`);
    return leavesUnder(sub, files);
  }
  return n.children.flatMap((c) => leavesUnder(c, files));
}

/** Checks every inner node: 1 to FANOUT children and the box exactly around theirs. */
function checkNodes(n: IndexNode): void {
  if (!('children' in n)) return;
  assert.ok(n.children.length >= 1 && n.children.length <= FANOUT, `${n.children.length} children`);
  const lo = [0, 1, 2].map((i) => Math.min(...n.children.map((c) => c.bbox[i]!)));
  const hi = [3, 4, 5].map((i) => Math.max(...n.children.map((c) => c.bbox[i]!)));
  assert.deepEqual(n.bbox, [...lo, ...hi]);
  n.children.forEach(checkNodes);
}

test('a tree of 40 leaves: 16, 16 and 8 under three nodes under the root, boxes around their children', () => {
  const ls = leaves(40);
  const root = packTree(ls);
  assert.deepEqual(root.children.map((c) => ('children' in c ? c.children.length : -1)), [16, 16, 8]);
  checkNodes(root);
  // Leaves 0..39: x 0..40, y 0..79, z 0..40.
  assert.deepEqual(root.bbox, [0, 0, 0, 40, 79, 40]);
  assert.deepEqual(leavesUnder(root), ls, 'every leaf once, in the order given');
});

test('the root is an inner node however few leaves there are', () => {
  assert.deepEqual(packTree(leaves(1)).children.length, 1);
  const sixteen = packTree(leaves(16));
  assert.ok(sixteen.children.every(isLeaf), '16 leaves fit under the root');
  const seventeen = packTree(leaves(17));
  assert.deepEqual(seventeen.children.map((c) => ('children' in c ? c.children.length : -1)), [16, 1]);
});

test('subtrees too large for the index move to sub-index files, and every leaf is still reached once', () => {
  const ls = leaves(300);
  const root = packTree(ls);
  const names: string[] = [];
  const maxBytes = 4000;
  const { root: top, files } = splitTree(root, maxBytes, () => {
    names.push(`s-${names.length}.json`);
    return names[names.length - 1]!;
  });
  assert.ok(files.length > 0);
  assert.deepEqual(files.map((f) => f.name), names);
  assert.ok(JSON.stringify(top).length <= maxBytes, 'the index fits');
  const byName = new Map(files.map((f) => [f.name, parseSubIndex(JSON.parse(f.json), f.name)]));
  assert.deepEqual(leavesUnder(top, byName), ls);
  // A reference counts the chunks behind it and keeps the subtree's box.
  const check = (n: IndexNode): void => {
    if (isExternal(n)) {
      const sub = byName.get(n.ref)!;
      assert.equal(n.chunks, leavesUnder(sub, byName).length);
      assert.deepEqual(n.bbox, sub.bbox);
    } else if ('children' in n) n.children.forEach(check);
  };
  check(top);
  for (const sub of byName.values()) checkNodes(sub);
});

test('a tree that fits stays whole', () => {
  const root = packTree(leaves(40));
  const { root: top, files } = splitTree(root, 1 << 20, () => assert.fail('no file expected'));
  assert.equal(files.length, 0);
  assert.deepEqual(top, root);
});

test('out of line, every inner child of the root is a sub-index file of its own; files already split off stay, and every leaf is reached once', () => {
  const ls = leaves(300);
  let n = 0;
  const name = (): string => `s-${n++}.json`;
  // 300 leaves: 19 nodes of up to 16 under 2 under the root; the split moves some of them out,
  // and the root keeps an inner child.
  const split = splitTree(packTree(ls), 6000, name);
  const inline = split.root.children.filter((c) => 'children' in c).length;
  assert.ok(split.files.length > 0 && inline >= 1, `${split.files.length} files, ${inline} inner children under the root`);
  const { root, files } = rootOutOfLine(split, name);
  assert.deepEqual(files.slice(0, split.files.length), split.files);
  assert.equal(files.length, split.files.length + inline);
  assert.ok(root.children.every(isExternal), 'only references under the root');
  assert.deepEqual(root.bbox, split.root.bbox);
  const byName = new Map(files.map((f) => [f.name, parseSubIndex(JSON.parse(f.json), f.name)]));
  assert.deepEqual(leavesUnder(root, byName), ls);
  for (const c of root.children) if (isExternal(c)) assert.equal(c.chunks, leavesUnder(byName.get(c.ref)!, byName).length);
  // A root whose children are leaves (16 chunks or fewer) has nothing to move.
  const small = splitTree(packTree(leaves(10)), 1 << 20, name);
  assert.deepEqual(rootOutOfLine(small, () => assert.fail('no file expected')), small);
});
