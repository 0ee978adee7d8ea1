// The bodies the map fetches for the worker before the worker runs: the floor chunks its first
// view shows (ChunkSource's head start; on a slow network they come while the worker's script
// still loads). A request for one of them waits for that body instead of asking again.
export class HeadStart {
  /** By URL: the body to come, until a request takes it. */
  private readonly bodies = new Map<string, Promise<ArrayBuffer | null>>();
  /** By URL: how to hand the body over, until it comes (taken or not). */
  private readonly settles = new Map<string, (body: ArrayBuffer | null) => void>();

  /** The map is fetching these URLs. */
  expect(urls: readonly string[]): void {
    for (const url of urls) {
      if (this.bodies.has(url) || this.settles.has(url)) continue;
      this.bodies.set(url, new Promise<ArrayBuffer | null>((resolve) => this.settles.set(url, resolve)));
    }
  }

  /** The body of an expected URL came; null: the map's fetch failed, and the worker's own request (with its retries) takes over. */
  arrived(url: string, body: ArrayBuffer | null): void {
    this.settles.get(url)?.(body);
    this.settles.delete(url);
  }

  /** The body the map fetches for `url`, once (a second request asks the network); undefined when it fetches none. */
  take(url: string): Promise<ArrayBuffer | null> | undefined {
    const body = this.bodies.get(url);
    this.bodies.delete(url);
    return body;
  }
}
