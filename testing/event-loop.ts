// Waiting for asynchronous code under test without timing it: by event-loop turns (setImmediate,
// which node:test's fake timers leave alone unless asked), never by a clock the test asserts on.

const turn = (): Promise<void> => new Promise((resolve) => setImmediate(resolve));

/**
 * A few event-loop turns: promise chains that wait on nothing outside the process have run.
 * Enough to say "nothing more happened" after a fake timer tick.
 */
export async function settle(turns = 5): Promise<void> {
  for (let i = 0; i < turns; i++) await turn();
}

/**
 * Turns until `cond` holds. Some work completes outside JavaScript (crypto.subtle's digest runs
 * on the thread pool), so this waits for it; the limit only stops a hang, it measures nothing.
 */
export async function eventually(cond: () => boolean, what: string): Promise<void> {
  // On the process's own clock: a test may fake performance.now (fake-clock.ts) and Date.
  const giveUp = process.hrtime.bigint() + 10_000_000_000n;
  while (!cond()) {
    if (process.hrtime.bigint() > giveUp) throw new Error(`never happened: ${what}`);
    await turn();
  }
}

/**
 * What `p` settles to, waited for by turns: a promise left pending (a retry waiting on a fake
 * timer nobody ticks) fails the test with `what`, instead of the runner cancelling the file.
 */
export async function settled<T>(p: Promise<T>, what: string): Promise<T> {
  let done = false;
  const watched = p.finally(() => {
    done = true;
  });
  watched.catch(() => undefined); // the rejection is the caller's, when it awaits below
  await eventually(() => done, what);
  return watched;
}
