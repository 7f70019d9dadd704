/**
 * #/area-light's "Convergence" and "Run time against error" panels (folds under Explore further)
 * are filled by worker runs that start when each panel, once its fold is open, comes near the
 * screen. The panels mount after the scene (only when their folds open), so this checks that
 * opening them and scrolling to them does start the runs: the tables behind the plots fill with
 * one row per checkpoint and per (strategy, N).
 */
import { test, expect, openScene } from './fixtures';
import { TIMING_COUNTS } from '../../src/scenes/area-light/model';
import { STRATEGIES } from '../../src/scenes/area-light/strategies';

test('opened and scrolled into view, the convergence and timing panels get their data', async ({ page }) => {
  test.setTimeout(180_000);
  await openScene(page, '#/area-light?open=convergence,timing');
  const convergence = page.getByTestId('al-convergence-table');
  await convergence.scrollIntoViewIfNeeded();
  await convergence.locator('summary').click();
  // checkpoints N = 2 … 32768: one row each, with |error| and σ for the three strategies
  const convRows = convergence.locator('tbody tr');
  await expect(convRows.first()).toBeVisible({ timeout: 45_000 });
  await expect(convRows.first().locator('td')).toHaveCount(1 + 2 * STRATEGIES.length);

  const timing = page.getByTestId('al-timing-table');
  await timing.scrollIntoViewIfNeeded();
  await timing.locator('summary').click();
  await expect(timing.locator('tbody tr')).toHaveCount(STRATEGIES.length * TIMING_COUNTS.length, {
    timeout: 90_000,
  });
});
