/**
 * The LMS packages' manifests, read from the packages as built (src/lms/packages.ts): SCORM 1.2
 * and 2004 each declare one SCO launching index.html with the mastery score, and cmi5.xml one AU
 * per question of the package. (The packages running in an LMS are the browser tests', in
 * tests/e2e/lms-*.spec.ts.)
 */
import { describe, expect, it } from 'vitest';
import { unzipSync } from 'fflate';
import { auId, buildPackages } from '../../src/lms/packages';

const SEED = 11;
const app = {
  'index.html': new TextEncoder().encode('<!doctype html><html><head></head><body></body></html>'),
};
const text = (bytes: Uint8Array | undefined) => new TextDecoder().decode(bytes);

describe('package manifests', () => {
  it('SCORM 1.2 and 2004: one SCO launching index.html, with the mastery score', () => {
    const out = buildPackages(
      { questions: ['q5'], variants: 1, seed: SEED, mastery: 0.8, version: 'test' },
      app,
    );
    const m12 = text(unzipSync(out['practice-scorm12.zip'])['imsmanifest.xml']);
    expect(m12).toContain('<schemaversion>1.2</schemaversion>');
    expect(m12.match(/adlcp:scormtype="sco"/g)).toHaveLength(1);
    expect(m12).toContain('href="index.html"');
    expect(m12).toContain('<adlcp:masteryscore>80</adlcp:masteryscore>');
    const m04 = text(unzipSync(out['practice-scorm2004.zip'])['imsmanifest.xml']);
    expect(m04).toContain('<schemaversion>2004 4th Edition</schemaversion>');
    expect(m04.match(/adlcp:scormType="sco"/g)).toHaveLength(1);
    expect(m04).toContain('href="index.html"');
    expect(m04).toContain('<imsss:minNormalizedMeasure>0.8</imsss:minNormalizedMeasure>');
  });

  it('cmi5.xml: one AU per question of the package, with its mastery score', () => {
    const out = buildPackages(
      { questions: ['q3', 'q5'], variants: 1, seed: SEED, mastery: 0.8, version: 'test' },
      app,
    );
    const xml = text(unzipSync(out['practice-cmi5.zip'])['cmi5.xml']);
    const aus = [...xml.matchAll(/<au id="([^"]+)"[^>]*masteryScore="0.8"/g)].map((m) => m[1]);
    expect(aus).toEqual([auId({ seed: SEED }, 'q3'), auId({ seed: SEED }, 'q5')]);
    expect(xml).toContain('<url>index.html?rml-au=q5</url>');
    expect(xml).toContain('courseStructure');
  });
});
