// axe-core, the standard accessibility checker, run in a test's page: its violations, one line
// each with the elements at fault.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import type { AxeResults } from 'axe-core';
import type { Page } from 'playwright-core';

interface AxeWindow {
  axe: { run(context: object, options: object): Promise<AxeResults> };
  document: object;
}

let source: string | null = null;

/** Every rule axe runs by default (WCAG A and AA, and its best practices) on the page as it is. */
export async function axeViolations(page: Page): Promise<string[]> {
  source ??= readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
  await page.addScriptTag({ content: source });
  const results = await page.evaluate(() => {
    const w = globalThis as unknown as AxeWindow;
    return w.axe.run(w.document, { resultTypes: ['violations'] });
  });
  // A run that checked nothing would pass vacuously: among the rules passed, the landmark ones.
  const passed = results.passes.map((r) => r.id);
  for (const id of ['region', 'landmark-one-main']) assert.ok(passed.includes(id), `axe checked ${id}: ${passed.join(' ')}`);
  return results.violations.map((v) => `${v.id} (${v.impact ?? '?'}): ${v.help}: ${v.nodes.map((n) => `${n.target.join(' ')}: ${n.failureSummary ?? ''}`).join(' | ')}`);
}
