// The pointers down on the map (mouse buttons, fingers, pens) and where they are, so that a
// one-finger pan hands over to a two-finger pinch and back.

export interface TrackedPointer {
  x: number;
  y: number;
  type: string;
}

export class Pointers {
  readonly down = new Map<number, TrackedPointer>();

  update(id: number, x: number, y: number, type: string): void {
    this.down.set(id, { x, y, type });
  }

  release(id: number): void {
    this.down.delete(id);
  }

  /** Touches down now, in the order they went down. */
  touches(): TrackedPointer[] {
    return [...this.down.values()].filter((p) => p.type === 'touch');
  }

  clear(): void {
    this.down.clear();
  }
}
