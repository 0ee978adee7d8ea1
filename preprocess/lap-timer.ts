// Wall time of the named stages of a run, for the reports that `ssc` and the benchmarks print.

/** `lap(name)` records the milliseconds since the previous lap (or the start) under `name`. */
export function lapTimer(): { timings: Record<string, number>; lap: (name: string) => void } {
  const timings: Record<string, number> = {};
  let t0 = performance.now();
  const lap = (name: string): void => {
    const now = performance.now();
    timings[name] = Math.round(now - t0);
    t0 = now;
  };
  return { timings, lap };
}
