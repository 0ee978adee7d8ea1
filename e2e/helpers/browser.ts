// Chromium for the browser tests (playwright-core driving the system's binary), and a page
// with the demo map that records every console error and uncaught exception.
import { chromium, type Browser, type BrowserContext, type Page } from 'playwright-core';

export const CHROMIUM_ARGS = [
  '--no-sandbox',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--enable-unsafe-swiftshader',
  '--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1 , EXCLUDE localhost',
];

export function launchChromium(): Promise<Browser> {
  return chromium.launch({ executablePath: process.env.CHROMIUM_PATH ?? '/usr/lib/chromium/chromium', args: CHROMIUM_ARGS });
}

export interface MapPage {
  page: Page;
  context: BrowserContext;
  /** Console errors and uncaught exceptions so far. */
  problems: string[];
  /** Console errors matching these are expected (e.g. the failures a test injects). */
  expect(pattern: RegExp): void;
  close(): Promise<void>;
}

export interface OpenOptions {
  width?: number;
  height?: number;
  deviceScaleFactor?: number;
  /** Runs in the page before its scripts (e.g. to take WebGL2 away). */
  initScript?: string;
  /** The page under the base URL (default index.html, the engine's test page). */
  page?: string;
  /** A touch screen (touch events and taps). */
  hasTouch?: boolean;
  /** A phone: the meta viewport is honoured (with hasTouch, a coarse pointer). */
  isMobile?: boolean;
  reducedMotion?: 'reduce' | 'no-preference';
  /** The URL's fragment, with its #. */
  hash?: string;
  /** Called with the new page before it loads, e.g. to watch every response from the first. */
  onPage?: (page: Page) => void;
  /** Console errors the page is expected to log from its first moment (as MapPage.expect). */
  expect?: RegExp[];
}

/** Opens the engine's test page (or opts.page) with the given query parameters (source etc.). */
export async function openMap(browser: Browser, baseUrl: string, params: Record<string, string | number>, opts: OpenOptions = {}): Promise<MapPage> {
  const context = await browser.newContext({
    viewport: { width: opts.width ?? 640, height: opts.height ?? 480 },
    deviceScaleFactor: opts.deviceScaleFactor ?? 1,
    hasTouch: opts.hasTouch ?? false,
    isMobile: opts.isMobile ?? false,
    reducedMotion: opts.reducedMotion ?? 'no-preference',
  });
  const page = await context.newPage();
  if (opts.initScript) await page.addInitScript(opts.initScript);
  opts.onPage?.(page);
  const problems: string[] = [];
  const expected: RegExp[] = [...(opts.expect ?? [])];
  page.on('console', (m) => {
    if (m.type() !== 'error') return;
    const where = m.location().url;
    const text = `${m.text()} ${where}`;
    if (!expected.some((re) => re.test(text))) problems.push(`console error: ${text}`);
  });
  page.on('pageerror', (err) => problems.push(`uncaught: ${err.message}`));
  page.on('worker', (w) => {
    w.on('console', (m) => {
      if (m.type() === 'error' && !expected.some((re) => re.test(m.text()))) problems.push(`worker console error: ${m.text()}`);
    });
  });
  const q = new URLSearchParams(Object.entries(params).map(([k, v]): [string, string] => [k, String(v)]));
  await page.goto(`${baseUrl}${opts.page ?? 'index.html'}?${q}${opts.hash ?? ''}`);
  return {
    page,
    context,
    problems,
    expect: (re) => expected.push(re),
    close: () => context.close(),
  };
}
