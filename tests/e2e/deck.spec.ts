/**
 * The lecture deck (#/deck): what only a browser shows. A deck built from scene links (two added
 * from the scenes' share bars, one pasted) plays forward and back by keys, reveals on `v`, blacks
 * out on `b`, survives a reload on its slide, and its link reopens it; in classroom mode the copied
 * links keep present=1 and ask=1. The editor's file round trip, refusal and keyboard reordering.
 * The model itself (checks, codes, edits) is unit-tested in tests/deck/.
 */
import { test, expect } from './fixtures';
import type { Page } from '@playwright/test';

const count = (page: Page) => page.getByTestId('deck-slide-number');
const blur = (page: Page) => page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());

test('a deck built from links plays by keys, reveals on v, blacks out on b, survives a reload and its link reopens it; the editor downloads, refuses, reorders', async ({
  page,
  context,
}) => {
  test.setTimeout(180_000);
  await test.step('a deck built from links plays by keys, reveals on v, blacks out on b, survives a reload and its link reopens it', async () => {
    // two views added from their scenes' share bars (one asks first), one link pasted in the editor
    await page.goto('./#/texture?u=0.7&v=0.3&ask=1');
    await page.getByTestId('add-to-deck').click();
    await expect(page.getByTestId('add-to-deck-status')).toHaveText('Added: slide 1 — open the deck');
    await page.goto('./#/monte-carlo');
    await page.getByTestId('add-to-deck').click();
    await expect(page.getByTestId('add-to-deck-status')).toHaveText('Added: slide 2 — open the deck');
    await page.getByRole('link', { name: 'open the deck' }).click();
    await expect(page.getByTestId('deck-slide-edit')).toHaveCount(2);
    await page.getByTestId('deck-add-link').fill('https://example.org/#/texture?u=0.2&v=0.9&present=1');
    await page.getByTestId('deck-add').click();
    await expect(page.getByTestId('deck-said')).toHaveText('Added: slide 3.');
    await page.getByLabel('Caption').first().fill('Bilinear weights, by hand first.');

    // present: slide 1 asks its question until v
    await page.getByTestId('deck-present-link').click();
    await expect(page).toHaveURL(/present=1/);
    // (on the slide just added; the presenting page, not the editing one it replaces, has its scene up)
    await expect(page.getByTestId('deck-edit-link')).toBeVisible();
    await expect(page.getByTestId('scene-stage')).toBeVisible();
    await expect(count(page)).toHaveText('Slide 3 of 3');
    await page.keyboard.press('Home');
    await expect(count(page)).toHaveText('Slide 1 of 3');
    await expect(page.getByTestId('deck-caption')).toHaveText('Bilinear weights, by hand first.');
    await expect(page.getByTestId('ask-prompt-text')).toContainText('nearest');
    await expect(page.getByTestId('deck-question')).toHaveCount(0);
    // the slide's copied link and QR code keep classroom mode and the held-back results
    await page.getByTestId('copy-link').click();
    const slideLink = await page.getByTestId('share-text').inputValue();
    expect(slideLink).toMatch(/#\/texture\?.*u=0\.7.*present=1.*ask=1|#\/texture\?.*ask=1.*present=1/);
    await page.getByTestId('show-qr').click();
    await expect(page.getByTestId('qr-code')).toHaveAttribute('data-text', slideLink);
    await page.keyboard.press('Escape');
    await blur(page);
    await page.keyboard.press('v');
    await expect(page.getByTestId('ask-prompt')).toHaveCount(0);
    await expect(page.getByTestId('deck-question')).toContainText('nearest');

    // forward and back by keys; the slide is in the address
    await page.keyboard.press('ArrowRight');
    await expect(count(page)).toHaveText('Slide 2 of 3');
    await expect(page.getByTestId('deck-stage').locator('.scene-monte-carlo')).toHaveCount(1);
    await page.keyboard.press(' ');
    await expect(count(page)).toHaveText('Slide 3 of 3');
    await expect(page).toHaveURL(/slide=3/);
    await page.keyboard.press('PageUp');
    await expect(count(page)).toHaveText('Slide 2 of 3');
    await page.keyboard.press('Home');
    await expect(count(page)).toHaveText('Slide 1 of 3');
    await page.keyboard.press('End');
    await expect(count(page)).toHaveText('Slide 3 of 3');
    await page.keyboard.press('ArrowLeft');
    await page.keyboard.press('PageDown');
    await page.keyboard.press('ArrowLeft');
    await expect(count(page)).toHaveText('Slide 2 of 3');

    // b blacks the screen out; any key brings the same slide back
    await page.keyboard.press('b');
    await expect(page.getByTestId('deck-blackout')).toBeVisible();
    await page.keyboard.press('x');
    await expect(page.getByTestId('deck-blackout')).toHaveCount(0);
    await expect(count(page)).toHaveText('Slide 2 of 3');

    // a reload stays on the slide; the deck's link (in classroom mode) reopens it elsewhere
    await page.reload();
    await expect(count(page)).toHaveText('Slide 2 of 3');
    await page.getByTestId('deck-copy-link').click();
    const deckLink = await page.getByTestId('deck-link-text').inputValue();
    expect(deckLink).toMatch(/#\/deck\?d=[\w-]+&slide=2&present=1$/);
    const other = await context.newPage();
    await other.goto(deckLink);
    await expect(other.getByTestId('deck-slide-number')).toHaveText('Slide 2 of 3');
    await expect(other.getByTestId('scene-stage')).toBeVisible();
    await other.keyboard.press('ArrowLeft');
    await expect(other.getByTestId('ask-prompt-text')).toContainText('nearest');
    await expect(other.getByTestId('deck-caption')).toHaveText('Bilinear weights, by hand first.');
    await other.close();
  });

  await test.step('the editor: a ready deck downloads, a bad file is refused, slides reorder by keyboard', async () => {
    await page.goto('./#/deck?q=3');
    await expect(page.getByTestId('deck-slide-edit')).toHaveCount(5);
    const titles = () => page.getByTestId('deck-slide-edit').locator('input[id$="-title"]');
    const first = await titles().nth(0).inputValue();
    const second = await titles().nth(1).inputValue();

    // keyboard reordering: the moved slide keeps focus on its button
    await page.getByRole('button', { name: 'Move slide 2 up' }).focus();
    await page.keyboard.press('Enter');
    await expect(titles().nth(0)).toHaveValue(second);
    await expect(titles().nth(1)).toHaveValue(first);
    // (first now, it cannot go up: focus is on its other move button)
    await expect(page.getByRole('button', { name: 'Move slide 1 down' })).toBeFocused();
    // an edited ready deck goes into the link
    await expect(page).toHaveURL(/#\/deck\?d=/);

    const download = page.waitForEvent('download');
    await page.getByTestId('deck-download').click();
    const file = await (await download).path();
    expect((await download).suggestedFilename()).toBe('q3-texture-lookup.deck.json');

    await page.getByRole('button', { name: 'Remove slide 1' }).click();
    await expect(page.getByTestId('deck-slide-edit')).toHaveCount(4);

    // a file that is not a deck: a message naming why, the deck unchanged
    await page.getByTestId('deck-open-file').setInputFiles({
      name: 'notes.json',
      mimeType: 'application/json',
      buffer: Buffer.from('{"slides": []}'),
    });
    await expect(page.getByTestId('deck-said')).toContainText('notes.json was not opened');
    await expect(page.getByTestId('deck-said')).toContainText('no "format": "render-math-lab-deck"');
    await expect(page.getByTestId('deck-slide-edit')).toHaveCount(4);

    // the downloaded file opens again, as it was
    await page.getByTestId('deck-open-file').setInputFiles(file);
    await expect(page.getByTestId('deck-said')).toContainText('5 slides');
    await expect(titles().nth(0)).toHaveValue(second);

    // embedded: the deck plays, without its editor
    await page.goto('./#/deck?q=3&embed=1');
    await expect(count(page)).toHaveText('Slide 1 of 5');
    await expect(page.getByTestId('deck-editor')).toHaveCount(0);
  });
});
