/**
 * The worksheet page builds the LMS packages in the browser for its own choice of questions,
 * variants and seed: the Moodle bank holds those variants, and the SCORM zip carries the app's
 * static build with the launch page declaring the choice.
 */
import { XMLParser } from 'fast-xml-parser';
import { unzipSync } from 'fflate';
import type { Download } from '@playwright/test';
import { test, expect } from './fixtures';

async function read(d: Download): Promise<Buffer> {
  const chunks: Buffer[] = [];
  for await (const c of await d.createReadStream()) chunks.push(c as Buffer);
  return Buffer.concat(chunks);
}

test('the worksheet page builds the packages for its questions in the browser', async ({ page }) => {
  test.setTimeout(120_000);
  await page.goto('./#/practice/sheet?seed=21&q=1,3&count=2');
  await expect(page.getByTestId('lms-downloads')).toBeVisible();
  let download = page.waitForEvent('download', { timeout: 60_000 });
  await page.getByTestId('lms-build-questions-moodle.xml').click();
  const xml = (await read(await download)).toString('utf8');
  const doc = new XMLParser({ ignoreAttributes: false, attributeNamePrefix: '@' }).parse(xml);
  const ids = doc.quiz.question.filter((q: any) => q['@type'] === 'cloze').map((q: any) => q.idnumber);
  expect(ids).toEqual(['rml-q1-21', 'rml-q1-22', 'rml-q3-21', 'rml-q3-22']);

  download = page.waitForEvent('download', { timeout: 60_000 });
  await page.getByTestId('lms-build-practice-scorm12.zip').click();
  const zip = unzipSync(new Uint8Array(await read(await download)));
  const index = new TextDecoder().decode(zip['index.html']);
  expect(index).toContain(
    '<meta name="rml-lms" content="{&quot;kind&quot;:&quot;scorm12&quot;,&quot;questions&quot;:[&quot;q1&quot;,&quot;q3&quot;],&quot;seed&quot;:21,&quot;mastery&quot;:0.8',
  );
  expect(new TextDecoder().decode(zip['imsmanifest.xml'])).toContain('adlcp:scormtype="sco"');
  const scripts = [...index.matchAll(/src="\.\/(assets\/[^"]+\.js)"/g)].map((m) => m[1]);
  expect(scripts.length).toBeGreaterThan(0);
  for (const s of scripts) expect(zip[s], `${s} is in the package`).toBeTruthy();
  expect(Object.keys(zip).some((f) => f === 'sw.js')).toBe(false);
  await expect(page.getByTestId('lms-build-status')).toContainText('practice-scorm12.zip');
});
