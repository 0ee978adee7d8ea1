// A centreline while it is being made: points joined by straight pieces (an undirected graph).
// Ports are the points where the line must end or pass (never pruned); every other point is a
// midpoint of a triangle's inner edge, a junction triangle's centre or a port's foot on the axis.

export class AxisGraph {
  readonly xs: number[] = [];
  readonly ys: number[] = [];
  readonly adj: number[][] = [];
  readonly port: boolean[] = [];

  add(x: number, y: number, port = false): number {
    this.xs.push(x);
    this.ys.push(y);
    this.adj.push([]);
    this.port.push(port);
    return this.xs.length - 1;
  }

  link(a: number, b: number): void {
    if (a === b || this.adj[a]!.includes(b)) return;
    this.adj[a]!.push(b);
    this.adj[b]!.push(a);
  }

  unlink(a: number, b: number): void {
    const la = this.adj[a]!, lb = this.adj[b]!;
    la.splice(la.indexOf(b), 1);
    lb.splice(lb.indexOf(a), 1);
  }

  degree(n: number): number {
    return this.adj[n]!.length;
  }

  dist(a: number, b: number): number {
    return Math.hypot(this.xs[a]! - this.xs[b]!, this.ys[a]! - this.ys[b]!);
  }

  get size(): number {
    return this.xs.length;
  }
}
