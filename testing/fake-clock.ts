// A fake clock for code that reads performance.now() and waits on setTimeout: both mocked and
// moved together by advance(), so that a test of a wait looks just before its end and at it,
// instead of sleeping and hoping a busy machine fires the timer on time. Restored with the test.
import type { TestContext } from 'node:test';

export interface FakeClock {
  /** Moves performance.now() on by `ms`, then runs the timers due by then (they read the new time, as with node's fake Date). */
  advance(ms: number): void;
}

export function fakeClock(t: TestContext): FakeClock {
  // A whole millisecond, not before the real clock: from a fraction, a wait of 1050 ms worked out
  // as start + 1050 - (start + 1049 + 1) could come to 2e-13 ms, left for a tick nobody gives.
  let now = Math.ceil(performance.now());
  t.mock.timers.enable({ apis: ['setTimeout'] });
  t.mock.method(performance, 'now', () => now);
  return {
    advance(ms) {
      now += ms;
      t.mock.timers.tick(ms);
    },
  };
}
