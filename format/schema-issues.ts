// Valibot's issues as sentences that say where in the file each problem is: every problem
// of a file at once, not one per run.
import * as v from 'valibot';

/** "classes.road.color: must be \"#rrggbb\"" for each issue, in the order found. */
export function describeIssues(issues: readonly v.BaseIssue<unknown>[]): string[] {
  return issues.map((issue) => {
    const path = v.getDotPath(issue);
    return path ? `${path}: ${issue.message}` : issue.message;
  });
}
