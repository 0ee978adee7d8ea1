// What every browser test file sets up: a real cube of bgt_otterlo_400m built for the file, a
// server for the client and the cube, and Chromium; and after each test, the check that the
// page logged no console error or uncaught exception.
import assert from 'node:assert/strict';
import { after, afterEach, before } from 'node:test';
import type { Browser } from 'playwright-core';
import { launchChromium, type MapPage } from './browser.js';
import { buildCube, clientDir, otterlo400, readCube, type BuiltCube, type CubeContents } from './cube.js';
import { startTestServer, type TestServer } from './test-server.js';

export interface TestBed {
  cube: BuiltCube;
  contents: CubeContents;
  server: TestServer;
  browser: Browser;
}

export async function setUpTestBed(buildArgs: string[] = []): Promise<TestBed> {
  const cube = await buildCube(otterlo400, buildArgs);
  const contents = await readCube(cube.dir);
  const server = await startTestServer({ clientDir, cubeDir: cube.dir });
  const browser = await launchChromium();
  return { cube, contents, server, browser };
}

export async function tearDownTestBed(bed: Partial<TestBed> | undefined): Promise<void> {
  await bed?.browser?.close();
  await bed?.server?.close();
  await bed?.cube?.remove();
}

/** After a test: no console errors or uncaught exceptions on its page, which is then closed. */
export async function checkAndClose(mp: MapPage | null): Promise<void> {
  if (mp) assert.deepEqual(mp.problems, [], 'no console errors or uncaught exceptions');
  await mp?.close();
}

export interface SuiteBed extends TestBed {
  /** The running test's page: checked for console errors and closed after the test. */
  page: MapPage | null;
}

/**
 * In a describe(): sets the test bed up before its tests and down after them, and checks and
 * closes each test's page (bed.page). The fields are there from the first test on.
 */
export function useTestBed(buildArgs: string[] = []): SuiteBed {
  const bed = { page: null } as SuiteBed;
  before(async () => {
    Object.assign(bed, await setUpTestBed(buildArgs));
  });
  afterEach(async () => {
    await checkAndClose(bed.page);
    bed.page = null;
  });
  after(async () => {
    await tearDownTestBed(bed);
  });
  return bed;
}
