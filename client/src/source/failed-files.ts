// The files whose last fetch failed, and whether the cause may pass (mayPass: a network failure,
// or a 5xx, 408 or 429 after the retries): the scheduler's chunks and the index tree's sub-index
// files. When the page is back online, the passing ones are forgotten, to be asked for again.
import { mayPass } from './fetch-retry.js';

export class FailedFiles {
  private readonly failed = new Map<string, boolean>();
  /** When the page was last back online (performance.now()). */
  private onlineAt = -Infinity;

  /**
   * Records that the fetch of `file`, begun at `startedAt` (performance.now()), failed with
   * `err`. False when it is not recorded: a passing failure of a fetch begun before the page
   * was last back online may be the outage's, so the caller asks for the file again (once: that
   * fetch begins after).
   */
  fail(file: string, err: unknown, startedAt: number): boolean {
    const passing = mayPass(err);
    if (passing && startedAt < this.onlineAt) return false;
    this.failed.set(file, passing);
    return true;
  }

  has(file: string): boolean {
    return this.failed.has(file);
  }

  /** The file came after all. */
  delete(file: string): void {
    this.failed.delete(file);
  }

  /** The page is back online: forgets the failures that may pass, and returns their files. */
  backOnline(): string[] {
    this.onlineAt = performance.now();
    const forgotten: string[] = [];
    for (const [file, passing] of this.failed) {
      if (!passing) continue;
      this.failed.delete(file);
      forgotten.push(file);
    }
    return forgotten;
  }
}
