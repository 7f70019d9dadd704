/**
 * What a reader does with a plot, checked once on one plot (every plot is the same component,
 * src/ui/Plot.tsx; its layout and marks are unit-tested in tests/ui/chart.test.ts and
 * tests/render/chart.test.tsx): the pointer reads the nearest point out, a mouse drag zooms to a
 * box and a double click goes back, the tool buttons work from the keyboard, and Save gives a PNG.
 */
import { test, expect, openScene } from './fixtures';

test('a plot: the pointer’s readout, drag to zoom and back, the tool buttons by keyboard, Save as PNG', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await openScene(page, '#/monte-carlo?open=convergence');
  const plot = page.getByTestId('convergence-error-plot');
  await plot.scrollIntoViewIfNeeded();
  const svg = plot.locator('svg.chart');
  const firstLine = svg.locator('path.chart-line').first();
  await expect(firstLine).toBeAttached({ timeout: 60_000 });
  const box = (await svg.boundingBox())!;
  const xTicks = () => svg.locator('.chart-xticks text').allTextContents();
  const opened = await xTicks();

  await test.step('the readout names the nearest point’s line and its values', async () => {
    const d = (await firstLine.getAttribute('d'))!;
    const points = [...d.matchAll(/[ML](-?[\d.]+) (-?[\d.]+)/g)].map((m) => [Number(m[1]), Number(m[2])]);
    const [x, y] = points[Math.floor(points.length / 2)];
    await page.mouse.move(box.x + x + 2, box.y + y - 2);
    const lines = svg.locator('.chart-readout text');
    await expect(lines.first()).toHaveText((await svg.locator('.chart-legend text').first().textContent())!);
    await expect(lines.nth(1)).toHaveText(/^N \d+, \|estimate − exact\| \S+$/);
    // Escape dismisses it where the pointer is; moving off the plot's area ends it too
    await page.keyboard.press('Escape');
    await expect(lines).toHaveCount(0);
    await page.mouse.move(box.x + x + 3, box.y + y - 2);
    await expect(lines.first()).toBeVisible();
    await page.mouse.move(box.x + 2, box.y + box.height - 2);
    await expect(lines).toHaveCount(0);
  });

  await test.step('a drag zooms to its box; a double click goes back', async () => {
    await page.mouse.move(box.x + box.width * 0.45, box.y + box.height * 0.4);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width * 0.6, box.y + box.height * 0.7, { steps: 4 });
    await expect(svg.locator('.chart-zoombox')).toHaveCount(1);
    await page.mouse.up();
    await expect.poll(xTicks).not.toEqual(opened);
    await page.mouse.dblclick(box.x + box.width * 0.5, box.y + box.height * 0.5);
    await expect.poll(xTicks).toEqual(opened);
  });

  await test.step('the tool buttons show on focus and work by keyboard', async () => {
    const zoomIn = plot.getByRole('button', { name: 'Zoom in' });
    await zoomIn.focus();
    await expect(plot.locator('.plot-tools')).toHaveCSS('opacity', '1');
    await page.keyboard.press('Enter');
    await expect.poll(xTicks).not.toEqual(opened);
    await plot.getByRole('button', { name: 'Reset the axes' }).press('Enter');
    await expect.poll(xTicks).toEqual(opened);
  });

  await test.step('Save gives a PNG of the plot', async () => {
    const [download] = await Promise.all([
      page.waitForEvent('download'),
      plot.getByRole('button', { name: 'Save the plot as a PNG image' }).click(),
    ]);
    expect(download.suggestedFilename()).toMatch(/\.png$/);
    const bytes = await (await download.createReadStream()).toArray();
    const head = Buffer.concat(bytes).subarray(0, 8);
    expect([...head]).toEqual([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  });
});
