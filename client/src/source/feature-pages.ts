// What picking shows about a face: its face table record (class, feature, steps) and the input
// attributes of its feature, from pages fetched once each on first use. Runs in the worker.
import { decodeAttributePage, featureAttributes, type AttributePage } from '../../../format/attribute-page.js';
import type { PageList } from '../../../format/cube-index.js';
import { decodeFacePage, faceRecord, type FacePage } from '../../../format/face-page.js';
import { gunzipIfNeeded } from './gunzip.js';
import { fetchBytes, fetchJson, type RetryOptions } from './fetch-retry.js';
import type { FeatureInfo } from './worker-protocol.js';

/** The page holding item `i` (pages sorted by `first`), or undefined. */
function pageOf(list: PageList, i: number): { first: number; file: string } | undefined {
  let lo = 0, hi = list.pages.length - 1, found = -1;
  while (lo <= hi) {
    const mid = (lo + hi) >> 1;
    if (list.pages[mid]!.first <= i) {
      found = mid;
      lo = mid + 1;
    } else hi = mid - 1;
  }
  if (found < 0 || i >= list.count) return undefined;
  return list.pages[found];
}

export class FeaturePages {
  private readonly facePages = new Map<string, Promise<FacePage>>();
  private readonly attrPages = new Map<string, Promise<AttributePage>>();

  constructor(
    private readonly faces: PageList,
    private readonly attributes: PageList,
    private readonly url: (file: string) => string,
    private readonly retry: RetryOptions,
  ) {}

  async lookup(face: number): Promise<FeatureInfo | null> {
    const fp = pageOf(this.faces, face);
    if (!fp) return null;
    const rec = faceRecord(await this.facePage(fp.file), face);
    if (!rec) return null;
    return { ...rec, properties: await this.properties(rec.feature) };
  }

  /** An input feature's attributes (null: no feature, or none stored). */
  async properties(feature: number): Promise<Record<string, unknown> | null> {
    const ap = feature >= 0 ? pageOf(this.attributes, feature) : undefined;
    if (!ap) return null;
    return featureAttributes(await this.attrPage(ap.file), feature);
  }

  private facePage(file: string): Promise<FacePage> {
    let p = this.facePages.get(file);
    if (!p) {
      p = fetchBytes(this.url(file), this.retry).then(gunzipIfNeeded).then(decodeFacePage);
      p.catch(() => this.facePages.delete(file));
      this.facePages.set(file, p);
    }
    return p;
  }

  private attrPage(file: string): Promise<AttributePage> {
    let p = this.attrPages.get(file);
    if (!p) {
      p = fetchJson(this.url(file), this.retry).then((json) => decodeAttributePage(json, file));
      p.catch(() => this.attrPages.delete(file));
      this.attrPages.set(file, p);
    }
    return p;
  }
}
