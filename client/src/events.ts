// A small typed event emitter (on, once, off, fire), like MapLibre's Evented.

export class Evented<Events extends object> {
  private readonly listeners = new Map<keyof Events, Set<(ev: never) => void>>();

  on<K extends keyof Events>(type: K, fn: (ev: Events[K]) => void): this {
    let set = this.listeners.get(type);
    if (!set) this.listeners.set(type, (set = new Set()));
    set.add(fn);
    return this;
  }

  off<K extends keyof Events>(type: K, fn: (ev: Events[K]) => void): this {
    this.listeners.get(type)?.delete(fn);
    return this;
  }

  once<K extends keyof Events>(type: K): Promise<Events[K]> {
    return new Promise((resolve) => {
      const fn = (ev: Events[K]): void => {
        this.off(type, fn);
        resolve(ev);
      };
      this.on(type, fn);
    });
  }

  /** Forgets every listener (the object is being removed). */
  protected removeAllListeners(): void {
    this.listeners.clear();
  }

  protected listens(type: keyof Events): boolean {
    return (this.listeners.get(type)?.size ?? 0) > 0;
  }

  protected fire<K extends keyof Events>(type: K, ev: Events[K]): void {
    for (const fn of [...(this.listeners.get(type) ?? [])]) (fn as (e: Events[K]) => void)(ev);
  }
}
